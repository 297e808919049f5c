#pragma once
/// The one interface behind which every way of running a system lives, with or without a
/// container: the UI, the CLI and the benchmarks only talk to an Engine.

#include <memory>
#include <optional>

#include "swarm/collision_mode.h"
#include "swarm/method.h"
#include "swarm/system.h"
#include "swarm/wall.h"

namespace swarm {

/// How many threads an engine uses by default: 2 where the platform has threads and at
/// least two cores, 1 in the browser.
int default_threads();

struct EngineConfig {
  Method method = Method::analytic;
  CollisionMode collisions = CollisionMode::paper;
  std::optional<double> container_radius;  ///< none: an isolated system
  /// Threads for the engine's work, 1 or 2 (more count as 2; the browser always uses 1).
  /// Results do not depend on it: sums are combined in a fixed order.
  int threads = default_threads();
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
  /// work is done on the system.
  virtual void set_container_radius(std::optional<double> R) = 0;
  virtual std::optional<double> container_radius() const = 0;
  virtual const EngineConfig& config() const = 0;
  /// An independent copy that steps on exactly as this engine would, to the last bit: the
  /// timeline's snapshots (swarm/timeline.h) are clones.
  virtual std::unique_ptr<Engine> clone() const = 0;
};

/// The straightforward engine: Appendix A with the chosen method as the trajectory map.
std::unique_ptr<Engine> make_reference_engine(System initial, const EngineConfig& config);

/// The best engine for the configuration: the fast engine (swarm/fast_engine.h) where it
/// applies (the analytic method with paper collisions, with or without a container), else the
/// reference engine.
std::unique_ptr<Engine> make_engine(System initial, const EngineConfig& config);

}  // namespace swarm
