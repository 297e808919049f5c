#pragma once
/// The one interface behind which every way of running a system lives, with or without a
/// container: the UI, the CLI and the benchmarks only talk to an Engine.

#include <cstdint>
#include <memory>
#include <optional>

#include "swarm/methods/external_forces.h"
#include "swarm/methods/method.h"
#include "swarm/physics/collision_mode.h"
#include "swarm/physics/floor.h"
#include "swarm/physics/system.h"
#include "swarm/physics/wall.h"
#include "swarm/physics/wall_motion.h"

namespace swarm {

/// The most threads an engine takes: each is a thread it starts and keeps, so a count typed by
/// mistake (--threads 65535) is refused rather than starting thousands.
inline constexpr int kMaxThreads = 256;

/// How many threads an engine uses by default: the machine's hardware threads
/// (std::thread::hardware_concurrency, at most kMaxThreads), 1 in the browser. The WebAssembly build has no threads:
/// they would need SharedArrayBuffer, which needs the COOP/COEP headers that static hosting
/// cannot send.
int default_threads();

struct EngineConfig {
  Method method = Method::analytic;
  CollisionMode collisions = CollisionMode::paper;
  std::optional<double> container_radius;  ///< none: an isolated system
  /// Threads for the engine's work: 1 to kMaxThreads (more than the machine has works, at a
  /// cost; the browser always uses 1). Results do not depend on it, bit for bit: the work is
  /// split and its sums combined in ways that do not depend on the count.
  int threads = default_threads();
  /// Gravity and drag (Appendix B), and a floor beside the container: the fast engine runs
  /// gravity, mass-proportional drag and an elastic floor; drag b on chosen particles and an
  /// inelastic floor run on the reference engine (fast_engine_applies).
  ExternalForces forces;
  std::optional<Floor> floor;

  // Walls that move or are hot, and particles that are hard spheres (Appendix B; paper
  // collisions only): swarm/physics/wall_motion.h, swarm/physics/thermal_wall.h,
  // swarm/physics/hard_spheres.h. Moving and hot walls run on the fast engine too (with the
  // analytic method); hard spheres only on the reference engine (fast_engine_applies).
  std::vector<WallMove> wall_moves;        ///< the wall's path from container_radius at t = 0
  std::optional<double> wall_temperature;  ///< a thermal wall at this T (energy units, k_B = 1)
  std::uint64_t wall_stream = 0;  ///< the thermal wall's draws are keyed on it (ThermalDraw)
  std::optional<double> sphere_radius;     ///< hard spheres of this radius (length)

  /// Whether energy comes or goes other than between the particles and their springs: a
  /// field, drag, a floor, a moving or a hot wall. Its runs keep energy books (EnergyBooks)
  /// worth showing.
  bool exchanges_energy() const {
    return forces.any() || floor || !wall_moves.empty() || wall_temperature;
  }
};

class Engine {
 public:
  virtual ~Engine() = default;
  /// Advances by dt and reports what the wall received in that step.
  virtual WallTally step(double dt) = 0;
  /// The current state, materialised if the engine keeps it in another form.
  virtual const System& system() = 0;
  virtual double time() const = 0;
  /// Moves the wall discontinuously (the expansion protocol). No particle is touched, so no
  /// work is done on the system. A wall that was moving (EngineConfig::wall_moves) stops.
  virtual void set_container_radius(std::optional<double> R) = 0;
  virtual std::optional<double> container_radius() const = 0;
  virtual const EngineConfig& config() const = 0;
  /// An independent copy that steps on exactly as this engine would, to the last bit: the
  /// timeline's snapshots (swarm/run/timeline.h) are clones.
  virtual std::unique_ptr<Engine> clone() const = 0;
};

/// The straightforward engine: Appendix A with the chosen method as the trajectory map.
std::unique_ptr<Engine> make_reference_engine(System initial, const EngineConfig& config);

/// The best engine for the configuration: the fast engine (swarm/engine/fast_engine.h) where it
/// applies (the analytic method with paper collisions, with or without a container, the wall
/// fixed, moving or hot, under gravity, mass-proportional drag and an elastic floor; not drag
/// b on chosen particles, an inelastic floor or hard spheres), else the reference engine.
std::unique_ptr<Engine> make_engine(System initial, const EngineConfig& config);

}  // namespace swarm
