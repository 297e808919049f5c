#include "swarm/run/run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

#include "run/advance_to_end.h"
#include "swarm/measure/speed_distribution.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/physics/gravity.h"

namespace swarm {
namespace {

/// (2/3) KE / N from a sample's CM-frame kinetic energy (SwarmReading::kinetic_cm), which
/// the sample's one pass over the particles already has; elsewhere measure's
/// kinetic_temperature.
double kinetic_temperature_of(double kinetic_cm, const System& s) {
  return s.particles.empty() ? 0.0 : 2 * kinetic_cm / (3 * double(s.particles.size()));
}

/// Steps between the kinetic T's readings in a stage's window. A reading materialises the
/// fast engine's state, which costs several of its steps: one every step made an expansion
/// 4x slower. A swarm's KE breathes at 2 omega (period pi / omega), so eight readings a period
/// average it as every step would; at J = 0, where only the CM's share of KE moves, 64 over
/// the window.
long kinetic_stride(double omega, double dt, long window_steps) {
  const double per_reading = omega > 0 ? M_PI / omega / 8 / dt : double(window_steps) / 64;
  return std::max(1L, long(std::floor(per_reading)));
}

}  // namespace

double relative_energy_change(double E0, double E_end, double energy_scale) {
  const double scale = E0 != 0 ? std::abs(E0) : energy_scale;
  return scale > 0 ? (E_end - E0) / scale : 0.0;
}

double relative_energy_change(const Sample& start, double E) {
  return relative_energy_change(start.E, E, start.KE + std::abs(start.PE));
}

std::vector<WallInterval> wall_intervals(const std::vector<Sample>& samples) {
  std::vector<WallInterval> out;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const Sample& s = samples[i];
    out.push_back({s.t, s.t - samples[i - 1].t, {s.P, s.T, s.hits}, s.R});
  }
  return out;
}

bool virial_balance_applies(const EngineConfig& config) {
  return config.container_radius && !config.exchanges_energy() && !config.sphere_radius;
}

std::vector<VirialInterval> virial_intervals(const std::vector<Sample>& samples,
                                             std::size_t first) {
  std::vector<VirialInterval> out;
  for (std::size_t i = first + 1; i < samples.size(); ++i) {
    const Sample& a = samples[i - 1];
    const Sample& b = samples[i];
    const double kinetic = (2 * a.KE - 2 * a.PE + 2 * b.KE - 2 * b.PE) / 2;
    out.push_back({b.t, b.t - a.t, 3 * b.P * sphere_volume(b.R), kinetic, a.G, b.G});
  }
  return out;
}

Run::Run(System initial, const RunPlan& plan)
    : Run(make_engine(std::move(initial), plan.engine), plan) {}

Run::Run(std::unique_ptr<Engine> engine, const RunPlan& plan)
    : engine_(std::move(engine)), plan_(plan) {
  const EnergyParts energy = energy_now();
  E0_ = energy.kinetic + energy.potential;
  energy_scale_ = energy.kinetic + std::abs(energy.potential);
  samples_.push_back(sample_now());
  if (plan_.expansion) {
    const ExpansionProtocol& e = *plan_.expansion;
    const long per_stage = steps_per_stage(e, plan_.dt);
    protocol_steps_ = e.stages * per_stage;
    const System& s = engine_->system();
    kinetic_stride_ =
        kinetic_stride(std::sqrt(std::abs(s.J) * total_mass(s)), plan_.dt,
                       per_stage - std::lround(e.thermalize_fraction * double(per_stage)));
  } else
    open_stage_by_hand();
}

EnergyParts Run::energy_now() {
  const System& s = engine_->system();
  return with_gravity(energy_parts(s), s);
}

EnergyParts Run::with_gravity(EnergyParts e, const System& s) const {
  const Vec3& g = plan_.engine.forces.gravity;
  if (g != Vec3::Zero()) e.potential += gravity_potential_energy(s, g);
  return e;
}

Run::Run(const Run& other)
    : engine_(other.engine_->clone()),
      plan_(other.plan_),
      steps_done_(other.steps_done_),
      wall_hits_(other.wall_hits_),
      floor_hits_(other.floor_hits_),
      books_(other.books_),
      E0_(other.E0_),
      energy_scale_(other.energy_scale_),
      sample_meter_(other.sample_meter_),
      stage_meter_(other.stage_meter_),
      stage_kinetic_sum_(other.stage_kinetic_sum_),
      stage_kinetic_steps_(other.stage_kinetic_steps_),
      kinetic_stride_(other.kinetic_stride_),
      samples_(other.samples_),
      stages_(other.stages_),
      failure_(other.failure_),
      protocol_steps_(other.protocol_steps_),
      hand_stage_start_(other.hand_stage_start_),
      hand_tallies_(other.hand_tallies_) {}

void Run::open_stage_by_hand() {
  if (!plan_.stages_by_hand || !engine_->container_radius()) return;
  hand_stage_start_ = steps_done_;
  hand_tallies_.clear();
}

void Run::expand_now(double factor) {
  const std::optional<double> R = engine_->container_radius();
  if (!R) return;
  if (stage_by_hand_open() && steps_done_ > hand_stage_start_) {
    // The protocol's window: the steps of the stage from index lround(f * length) on.
    const double f = plan_.expansion ? plan_.expansion->thermalize_fraction
                                     : ExpansionProtocol{}.thermalize_fraction;
    const long length = steps_done_ - hand_stage_start_;
    const WallReading w =
        hand_tallies_.reading(std::lround(f * double(length)), plan_.dt, wall_area(*R, *R));
    const System& s = engine_->system();
    stages_.push_back(
        {*R, wall_volume(*R), w.P, w.T, total_energy(s), w.hits, true, kinetic_temperature(s)});
  }
  engine_->set_container_radius(*R * factor);
  if (stage_by_hand_open()) open_stage_by_hand();
}

double Run::wall_area(double R_before, double R_after) const {
  const double a = plan_.engine.sphere_radius.value_or(0.0);
  return swept_area(R_before - a, R_after - a);
}

double Run::wall_volume(double R) const {
  return sphere_volume(R - plan_.engine.sphere_radius.value_or(0.0));
}

void Run::extend(long steps) { plan_.steps += std::max(0L, steps); }

Sample Run::sample_now() {
  const System& s = engine_->system();
  Sample out;
  out.t = s.t;
  const WallReading w = sample_meter_.reading();
  out.P = w.P;
  out.T = w.T;
  out.hits = w.hits;
  // One reading for the energies, the CM and the size, in two passes over the particles
  // where the three apart take eight: a sample is serial work between the engine's steps,
  // which on a large swarm and several threads weighs.
  const SwarmReading reading = swarm_reading(s);
  const EnergyParts energy = with_gravity(reading.energy, s);
  out.KE = energy.kinetic;
  out.PE = energy.potential;
  out.E = out.KE + out.PE;
  out.T_kinetic = kinetic_temperature_of(reading.kinetic_cm, s);
  out.R = engine_->container_radius().value_or(0.0);
  out.books = books_;
  out.cm_height = reading.cm.z();
  out.size = reading.size;
  out.G = reading.G;
  sample_meter_.reset();
  return out;
}

void Run::step_once() {
  const double R_before = engine_->container_radius().value_or(0.0);
  const WallTally tally = engine_->step(plan_.dt);
  const double R = engine_->container_radius().value_or(0.0);
  const double area = wall_area(R_before, R);
  ++steps_done_;
  wall_hits_ += tally.hits;
  floor_hits_ += tally.floor_hits;
  books_.add(tally.books);
  sample_meter_.add(tally, plan_.dt, area);

  if (stage_by_hand_open()) hand_tallies_.push(tally);
  if (plan_.expansion && steps_done_ <= protocol_steps_) {
    const ExpansionProtocol& e = *plan_.expansion;
    const long per_stage = steps_per_stage(e, plan_.dt);
    const long in_stage = (steps_done_ - 1) % per_stage;  // index of the step just taken
    const long window_start = std::lround(e.thermalize_fraction * double(per_stage));
    if (in_stage >= window_start) {
      stage_meter_.add(tally, plan_.dt, area);
      if ((in_stage - window_start) % kinetic_stride_ == 0) {
        stage_kinetic_sum_ += kinetic_temperature(engine_->system());
        ++stage_kinetic_steps_;
      }
    }
    if (in_stage == per_stage - 1) {
      const WallReading w = stage_meter_.reading();
      const EnergyParts energy = energy_now();
      Stage stage{R, wall_volume(R), w.P, w.T, energy.kinetic + energy.potential, w.hits};
      // An empty window (thermalize 1) reads no T kinetic, as it reads no wall T.
      stage.T_kinetic = stage_kinetic_steps_ > 0 ? stage_kinetic_sum_ / double(stage_kinetic_steps_)
                                                 : std::numeric_limits<double>::quiet_NaN();
      stages_.push_back(stage);
      stage_meter_.reset();
      stage_kinetic_sum_ = 0;
      stage_kinetic_steps_ = 0;
      if (long(stages_.size()) < e.stages) engine_->set_container_radius(R * e.factor);
    }
    if (steps_done_ == protocol_steps_) open_stage_by_hand();
  }
  if (steps_done_ % plan_.sample_every == 0 || steps_done_ == plan_.steps) {
    samples_.push_back(sample_now());
    check_finite(samples_.back());
  }
}

void Run::check_finite(const Sample& s) {
  const std::pair<const char*, double> quantities[] = {
      {"t", s.t}, {"P", s.P}, {"T", s.T}, {"KE", s.KE}, {"PE", s.PE}, {"E", s.E}, {"R", s.R}};
  for (const auto& [name, value] : quantities)
    if (!std::isfinite(value)) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "step %ld (t = %.6g): %s is not finite (%g)", steps_done_, s.t,
                    name, value);
      failure_ = buf;
      return;
    }
}

long Run::advance(long n) {
  long taken = 0;
  while (taken < n && !finished()) {
    step_once();
    ++taken;
  }
  return taken;
}

void Run::finish(const std::function<void(double)>& progress) {
  advance_to_end([this](long n) { advance(n); }, [this] { return finished(); },
                 [this] { return double(steps_done_) / double(plan_.steps); }, progress);
}

StageFits Run::fits() const {
  std::vector<double> V, P, T;
  for (const Stage& s : stages_) {
    V.push_back(s.V);
    P.push_back(s.P);
    T.push_back(s.T);
  }
  return {fit_power_law(V, P), fit_power_law(V, T), fit_power_law(T, P)};
}

RunSummary Run::summary() {
  const EnergyParts energy = energy_now();
  const System& s = engine_->system();
  RunSummary out;
  out.M = total_mass(s);
  out.omega = std::sqrt(std::abs(s.J) * out.M);
  out.E0 = E0_;
  out.E_end = energy.kinetic + energy.potential;
  out.energy_drift = relative_energy_change(E0_, out.E_end, energy_scale_);
  out.wall_hits = wall_hits_;
  out.steps = steps_done_;
  out.t_end = s.t;
  out.books = books_;
  out.floor_hits = floor_hits_;
  return out;
}

}  // namespace swarm
