#pragma once
/// The ways Swarm Lab can move a system forward in time.

#include <optional>
#include <string_view>

namespace swarm {

/// analytic: the exact closed-form map of the paper. The others integrate the pairwise
/// force law (eq. 1) numerically, summing over every pair.
enum class Method { analytic, euler, euler_cromer, verlet, rk4 };

/// How a wall collision inside a step is placed in time.
/// paper: Appendix A as written: reflect at the start of the step (first-order error).
/// exact: reflect at the instant the particle reaches the wall (exact up to rounding).
enum class CollisionMode { paper, exact };

std::string_view name_of(Method m);
std::string_view name_of(CollisionMode c);
std::optional<Method> method_named(std::string_view name);
std::optional<CollisionMode> collision_mode_named(std::string_view name);

/// The numerical methods cost O(N^2) per step; the analytic map costs O(N).
bool is_pairwise(Method m);

/// Global order of accuracy in dt (analytic: exact, reported as 0).
int order_of(Method m);

}  // namespace swarm
