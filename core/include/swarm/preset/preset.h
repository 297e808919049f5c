#pragma once
/// The shared preset format (JSON, version 1): one file runs the same in the CLI, the desktop
/// app and the browser. docs/presets.md, "Preset reference", documents every key.
// Implemented in core/src/preset/preset_{read,rules,write,derived}.cpp, one idea each.

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "swarm/preset/initial_conditions.h"
#include "swarm/preset/resource_budget.h"
#include "swarm/run/run.h"

namespace swarm {

inline constexpr int kPresetVersion = 1;

struct Preset {
  std::string name;
  std::string description;
  double J = 1.0;
  std::variant<std::vector<Particle>, SwarmSpec> particles = SwarmSpec{};
  std::optional<double> container_radius;
  Method method = Method::analytic;
  CollisionMode collisions = CollisionMode::paper;
  double dt = 1e-3;
  double duration = 1.0;  ///< with an expansion: stages * tau, derived
  std::optional<ExpansionProtocol> expansion;
  std::optional<long> sample_every;  ///< none: about 2000 samples over the run
  std::vector<Method> compare;       ///< methods run side by side from the same start
  // Appendix B: gravity, a floor and drag (swarm/physics/gravity.h, floor.h, drag.h).
  std::optional<Vec3> gravity;  ///< "gravity": [gx, gy, gz]
  std::optional<Floor> floor;   ///< "floor": {"z": h, "restitution": e}
  std::optional<Drag> drag;     ///< "drag": {"gamma": g} or {"b": b, "particles": [i, ...]}

  // Appendix B walls and contacts: "container": {"moves": [...]} or {"wall_temperature": Tw},
  // and "hard_spheres": {"radius": a} (swarm/physics/wall_motion.h, thermal_wall.h,
  // hard_spheres.h).
  std::vector<WallMove> wall_moves;
  std::optional<double> wall_temperature;
  std::optional<double> sphere_radius;
};

/// Either a valid preset or one message naming the field and the rule it breaks,
/// e.g. "particles[3].m: must be > 0".
struct PresetParse {
  std::optional<Preset> preset;
  std::string error;
};

/// Refuses text that is not exactly one JSON object (a NUL byte, anything after it, a key given
/// twice), a preset whose derived numbers would leave the range of a double, and one that
/// needs more than `limits` (the CLI's by default).
PresetParse parse_preset(std::string_view json_text, const ResourceLimits& limits = {});
/// Checks a preset built in code (the UI) against the same rules as parse_preset.
std::string preset_error(const Preset& p, const ResourceLimits& limits = {});
std::string preset_to_json(const Preset& p, int indent = 2);

/// The initial system: the explicit particles, or the generated swarm, at t = 0 with J set.
System initial_system(const Preset& p);
RunPlan run_plan(const Preset& p);
long step_count(const Preset& p);

}  // namespace swarm
