#pragma once
/// How a wall collision inside a step is placed in time.

#include <optional>
#include <string_view>

namespace swarm {

/// paper: Appendix A as written: reflect at the start of the step (first-order error).
/// exact: reflect at the instant the particle reaches the wall (exact up to rounding).
enum class CollisionMode { paper, exact };

std::string_view name_of(CollisionMode c);
std::optional<CollisionMode> collision_mode_named(std::string_view name);

}  // namespace swarm
