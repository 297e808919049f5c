#pragma once
/// A run of a preset: the engine stepped under its RunPlan the way the paper does (a fixed
/// container sampled at every interval, or the stepwise adiabatic expansion with
/// thermalisation and averaging windows), recording samples, stages and fits. The CLI, the UI
/// and the benchmarks all drive their systems through a Run.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "swarm/engine/engine.h"
#include "swarm/measure/fit.h"
#include "swarm/measure/thermometry.h"
#include "swarm/measure/virial_balance.h"
#include "swarm/measure/wall_tally_log.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/run/run_plan.h"

namespace swarm {

struct Sample {
  double t = 0;
  double P = 0, T = 0;  ///< over the steps since the previous sample; 0 without a container
  double KE = 0, PE = 0, E = 0;
  std::int64_t hits = 0;
  double R = 0;  ///< container radius, 0 when isolated
  /// Energy from outside since t = 0 (walls, floor, drag): E - E0 = books.net() when the
  /// books balance. PE and E include gravity's potential when there is gravity.
  EnergyBooks books;
  double cm_height = 0;  ///< z of the centre of mass (length)
  double size = 0;       ///< rms distance from the CM, sqrt(sum m |r - R_cm|^2 / M) (length)
  /// sum m r.v about the lab origin, the container's centre: the virial balance's G
  /// (swarm/measure/virial_balance.h; energy units)
  double G = 0;
  /// (2/3) KE / N in the CM frame, now: the gas's temperature whatever its speeds, where the
  /// wall's T (from the hitters' kinetic energy) is that only for a Maxwellian gas
  double T_kinetic = 0;
};

struct Stage {
  double R = 0;  ///< the container's radius
  double V = 0;  ///< the volume the centres reach: 4/3 pi (R - a)^3 with hard spheres of radius a
  double P = 0, T = 0;    ///< averaged over the last (1 - thermalize_fraction) of the stage
  double E = 0;           ///< total energy at the end of the stage
  std::int64_t hits = 0;  ///< wall hits in the averaging window
  bool by_hand = false;   ///< ended by "Expand now" rather than by the protocol
  /// (2/3) KE / N in the CM frame, averaged over the window P and T are (read at evenly
  /// spaced steps of it: kinetic_stride in run.cpp); a stage by hand's is the value at its end
  /// (its steps are not kept); NaN for an empty window (thermalize 1), like its T
  double T_kinetic = 0;
};

struct StageFits {
  PowerLawFit P_V, T_V, P_T;
};

struct RunSummary {
  double M = 0, omega = 0;  ///< omega = sqrt(|J| M)
  double E0 = 0, E_end = 0, energy_drift = 0;
  std::int64_t wall_hits = 0;
  long steps = 0;
  double t_end = 0;
  EnergyBooks books;             ///< energy from outside over the run: E_end - E0 = books.net()
  std::int64_t floor_hits = 0;  ///< bounces on the floor
};

/// A run that can be advanced piecewise (the UI) or to the end (the CLI).
class Run {
 public:
  Run(System initial, const RunPlan& plan);
  Run(std::unique_ptr<Engine> engine, const RunPlan& plan);
  /// An independent copy (its engine cloned) that carries on exactly as this run would.
  Run(const Run& other);
  Run& operator=(const Run&) = delete;

  /// Advances up to n steps; returns how many were taken.
  long advance(long n);
  /// Runs to the end, calling progress(fraction done) at least about once a second.
  void finish(const std::function<void(double)>& progress = {});
  /// At the end, or stopped because a number left the range of a double (see failure()).
  bool finished() const { return steps_done_ >= plan_.steps || !failure_.empty(); }
  /// "" while every sample is finite, else which quantity stopped the run and at which step,
  /// e.g. "step 412 (t = 0.412): E is not finite (nan)".
  const std::string& failure() const { return failure_; }
  long steps_done() const { return steps_done_; }

  /// Grows the container by `factor` now ("Expand now"); no particle is touched, so no work
  /// is done. Within a protocol's stages that is all. Outside them, with
  /// plan().stages_by_hand, it also ends the stage by hand that began at the last expansion
  /// (or at the start, or at the protocol's end) and begins the next: the stage is averaged
  /// like a protocol's, over its last (1 - thermalize_fraction) (the protocol's fraction, or
  /// ExpansionProtocol's default), and appended to stages() with by_hand set.
  void expand_now(double factor);
  /// Lengthens the run by `steps` (a finished run that continues). The protocol's stages
  /// stay as they were; the time after them is a stage by hand.
  void extend(long steps);
  /// Whether a stage by hand is under way (see expand_now), and the step it began at.
  bool stage_by_hand_open() const { return hand_stage_start_ >= 0; }
  long stage_by_hand_start() const { return hand_stage_start_; }

  Engine& engine() { return *engine_; }
  const RunPlan& plan() const { return plan_; }
  const std::vector<Sample>& samples() const { return samples_; }
  const std::vector<Stage>& stages() const { return stages_; }
  StageFits fits() const;
  RunSummary summary();
  /// The kinetic and potential energy of the current state; the potential counts the springs
  /// and, under gravity, -sum m g.r.
  EnergyParts energy_now();

 private:
  void step_once();
  Sample sample_now();
  /// e with gravity's potential energy added under gravity.
  EnergyParts with_gravity(EnergyParts e, const System& s) const;
  void check_finite(const Sample& s);
  void open_stage_by_hand();
  /// The area a step's wall pressure divides by: the sphere the particles' centres reach
  /// (radius R - a for hard spheres of radius a, where they give the wall their impulse),
  /// over the range a moving wall swept in the step (swept_area: P dV is then the wall's
  /// work exactly).
  double wall_area(double R_before, double R_after) const;
  /// The volume a stage's P goes with: the ball the centres reach, 4/3 pi (R - a)^3, the same
  /// sphere as wall_area's (an ideal-gas or Carnahan-Starling P V takes the volume the
  /// centres move in; the container's own 4/3 pi R^3 overstated it by 13 % for a = 0.04 R).
  double wall_volume(double R) const;

  std::unique_ptr<Engine> engine_;
  RunPlan plan_;
  long steps_done_ = 0;
  std::int64_t wall_hits_ = 0;
  std::int64_t floor_hits_ = 0;
  EnergyBooks books_;  // accumulated since t = 0
  double E0_ = 0, energy_scale_ = 1;
  WallMeter sample_meter_, stage_meter_;
  double stage_kinetic_sum_ = 0;  // of (2/3) KE / N in the CM frame over the stage's window
  long stage_kinetic_steps_ = 0;
  long kinetic_stride_ = 1;  // steps between those readings (kinetic_stride in run.cpp)
  std::vector<Sample> samples_;
  std::vector<Stage> stages_;
  std::string failure_;
  long protocol_steps_ = 0;      // the steps of the protocol's stages (0 without one)
  long hand_stage_start_ = -1;   // where the open stage by hand began; -1: none open
  WallTallyLog hand_tallies_;    // the steps of the open stage by hand
};

/// Relative change (E_end - E0) / |E0|, or over KE0 + |PE0| when E0 is zero.
double relative_energy_change(double E0, double E_end, double energy_scale);
/// The same from a run's first sample: (E - E0) / |E0|, or over KE0 + |PE0| when E0 is zero.
double relative_energy_change(const Sample& start, double E);

/// The wall interval behind every sample but the first (which covers no step), for
/// wall_average and windowed_wall_averages.
std::vector<WallInterval> wall_intervals(const std::vector<Sample>& samples);

/// Whether the virial balance (swarm/measure/virial_balance.h) holds for runs of this engine:
/// a container whose wall stays still and reflects elastically, and the springs as the only
/// force. Gravity, drag and a floor add the virial of outside forces, a moving wall its
/// motion's, a hot wall re-emits at random, and hard spheres' contacts add their own virial
/// (what makes their Z exceed 1): for those the balance is not applicable.
bool virial_balance_applies(const EngineConfig& config);
/// The virial terms behind every sample but the first, as wall_intervals' (the same
/// intervals): 3 P V with V = 4/3 pi R^3 of the interval's closing sample, 2 KE - 2 U by the
/// trapezoid rule, G at the ends. From samples[first] on (a trailing window's), or all.
std::vector<VirialInterval> virial_intervals(const std::vector<Sample>& samples,
                                             std::size_t first = 0);

}  // namespace swarm
