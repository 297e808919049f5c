#include "swarm/physics/collision_mode.h"

namespace swarm {

std::string_view name_of(CollisionMode c) { return c == CollisionMode::paper ? "paper" : "exact"; }

std::optional<CollisionMode> collision_mode_named(std::string_view name) {
  if (name == "paper") return CollisionMode::paper;
  if (name == "exact") return CollisionMode::exact;
  return std::nullopt;
}

}  // namespace swarm
