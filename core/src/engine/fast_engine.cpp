// The fast engine: Appendix A with the analytic method at a cost that grows with the number
// of wall hits rather than with N times the number of steps (see swarm/engine/fast_engine.h).
//
// Index
// [SECTION] Tuning
// [SECTION] State: a lane of the schedule (a particle: fast_engine_body.h)
// [SECTION] Engine: construction, step, system()
// [SECTION] Checks: Appendix A for the particles due in a step
// [SECTION] Shared motion: the CM, Y and the step's end
// [SECTION] The wall: where it is, for the hits and for the schedules
// [SECTION] Epochs and anchors: re-bases, new anchors, expiry
// [SECTION] Scheduling: windows, the lookahead, the timing wheel
// [SECTION] Factory

#include "swarm/engine/fast_engine.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "engine/fast_engine_anchor.h"
#include "engine/fast_engine_body.h"
#include "engine/fast_engine_lookahead.h"
#include "engine/fast_engine_wall.h"
#include "engine/fast_engine_window.h"
#include "engine/fast_engine_window_batch.h"
#include "engine/id_sort.h"
#include "engine/lane_pool.h"
#include "engine/timing_wheel.h"
#include "math/portable_math.h"
#include "swarm/methods/external_forces.h"
#include "swarm/physics/regime.h"

namespace swarm {
namespace {

using fast::Anchor;
using fast::Body;
using fast::kParked;
using fast::kUnknown;
using fast::StepIndex;
using fast::TimingWheel;

// [SECTION] Tuning

constexpr int kLookahead = fast::Lookahead::kSteps;
// For J < 0 the runaway amplifies the kicks like exp(Omega tau), so an anchor's offset soon
// outgrows any margin. A particle relies on the anchor it was last scheduled in, so a new
// anchor starts at least every kRepulsiveAnchorSteps steps (in O(1): it records Y's path from
// then on) and a schedule relies only on the kicks of the next couple of hundred steps.
constexpr StepIndex kRepulsiveAnchorSteps = 16;
// Re-base before exp(Omega tau) eats more than a few bits of the y_i (J < 0), and before the
// phase omega tau or the drift b tau gets large enough to cost digits (J >= 0).
constexpr double kMaxRepulsivePhase = 2.5;
constexpr double kMaxRepulsiveY = 0.005;  // times the wall radius
constexpr double kMaxAttractivePhase = 512;
constexpr double kMaxFreeSteps = 1024;
// Under drag the flow's determinant is exp(-gamma tau) and the coefficients a, b grow like
// exp(gamma tau / 2) against it: re-base before gamma tau passes this.
constexpr double kMaxDragDecay = 1;
// How many ids ahead of the one being checked the particle data is fetched.
constexpr std::size_t kPrefetch = 8;
// How many of a step's ids are checked, then given windows, then scheduled at a time: enough
// for the batched windows, few enough that their particles (80 bytes each) are still in the
// first-level cache when they are scheduled.
constexpr std::size_t kCheckChunk = 64;
// The particles are split by index into one lane per thread, each with its own buckets, so
// that a step's checks run on all the threads. No number depends on that split: a step's hits
// are combined in particle-id order (the reference engine's order), and the epoch's sums over
// all particles in blocks of kSumBlock particles, in block order.
constexpr std::size_t kSumBlock = 4096;
// Steps with fewer checks than this run on one thread. The pool's busy-polling hand-over is
// cheap enough that a step of a few dozen checks (the headline: about 40) loses nothing on two
// threads; it no longer gains either (2.48 s on one thread, 2.54 s on two, 2026-11-27).
constexpr std::size_t kParallelChecks = 1;
// An off-centre anchor (under gravity) follows the CM's parabola for this many times 1 /
// omega (J > 0), or steps (J = 0), and then gives way to a new one (OffsetFit): a longer horizon
// needs a wider margin, a shorter one expires more anchors. Measured on the gravity benchmark
// against 1 and 2 (bench/RESULTS.md).
constexpr double kFitTimes = 1.5;
constexpr double kFitSteps = 128;

// [SECTION] State

/// A hit of one step, kept apart until the step's hits are combined in particle-id order.
struct Hit {
  std::uint32_t id;
  Vec3 kick;  // m dv / M: its share of the change of V_cm
  WallTally tally;
  fast::CoefficientSums sums_change{};  // under drag: what it changed in the energy sums
};

/// What hits add up to, in particle-id order: their tally, the kick (the change of V_cm) and,
/// under drag, the energy sums with their changes.
struct HitSums {
  WallTally tally;
  Vec3 kick = Vec3::Zero();
  fast::CoefficientSums sums;
};

/// The step a lane's HitSums are of, published to the next lane's thread. It copies as its
/// value (clone() copies the engine).
struct SummedStep {
  std::atomic<std::uint64_t> step{~std::uint64_t(0)};
  SummedStep() = default;
  SummedStep(const SummedStep& other) : step(other.step.load()) {}
  SummedStep& operator=(const SummedStep& other) {
    step.store(other.step.load());
    return *this;
  }
};

/// One lane of the schedule: its timing wheel and the hits of one step. Each lane's thread
/// writes its own in every check: a cache line apart, lanes never share one.
struct alignas(64) Lane {
  TimingWheel wheel;
  std::vector<std::uint32_t> work;  // the ids taken from the wheel for this step
  std::vector<Vec3> hit_a, hit_b;   // the coefficients of its hits in the current anchor
  std::vector<fast::Window> hit_windows;
  std::vector<std::uint32_t> expiring;  // the ids of an expired anchor's particles (expire)
  std::array<std::vector<std::uint32_t>, kLookahead + 1> lookahead;
  std::vector<Hit> hits;
  // The hits in particle-id order once the checks are done: id << 32 | place in `hits` (sorted
  // as integers: cheaper than moving the hits).
  std::vector<std::uint64_t> order, order_scratch;
  // The sums of this lane's hits and of every lane's before it, in id order: each lane carries
  // the sums of the one before it on over its own hits, on its own thread, whose cache holds
  // them (check_lane). `summed` says which step they are of.
  HitSums sums;
  SummedStep summed;
  std::int64_t checks = 0;
#ifdef __EMSCRIPTEN__
  double touched = 0;  // keeps the browser build's early loads (check_lane) from being dropped
#endif
};

// [SECTION] Engine

class FastEngine final : public Engine {
 public:
  FastEngine(System initial, const EngineConfig& config)
      : config_(config),
        lanes_(lane_count(config.threads)),
        anchors_(initial.particles.size(), lanes_.size()),
        pool_(config.threads) {
    if (!fast_engine_applies(config))
      throw std::invalid_argument("the fast engine runs the analytic method with paper collisions");
    if (initial.particles.size() > kMaxFastEngineParticles)
      throw std::invalid_argument("the fast engine takes at most 2^26 particles");
    J_ = initial.J;
    t_ = initial.t;
    M_ = total_mass(initial);
    k_ = J_ * M_;
    forced_ = config.forces.any();
    gamma_ = config.forces.drag ? config.forces.drag->gamma : 0.0;
    two_omega_ = 2 * std::sqrt(std::abs(k_));
    // The windows see the damped oscillation as a free one of stiffness k - (gamma / 2)^2
    // under a decaying envelope (fast_engine_window.h).
    const double eta = 0.5 * gamma_;
    window_k_ = k_ - eta * eta;
    spring_ = {window_k_, window_k_ != 0 ? 1 / std::sqrt(std::abs(window_k_)) : 0.0, eta};
    phase_per_time_ = window_k_ != 0 ? 2 * std::sqrt(std::abs(window_k_)) : 1.0;
    checks_more_ = gamma_ > 0 || config.floor;
    off_centre_anchors_ = forced_ && gamma_ == 0 && k_ >= 0;
    if (config.floor) floor_windows_.resize(initial.particles.size());
    motion_.R_cm = cm_position(initial);
    motion_.V_cm = cm_velocity(initial);
    motion_.g = config.forces.gravity;
    orbits_.resize(initial.particles.size());
    for (std::size_t i = 0; i < orbits_.size(); ++i) {
      const Particle& p = initial.particles[i];
      orbits_[i] = {p.r - motion_.R_cm, p.v - motion_.V_cm, p.m, kParked, {kUnknown, kUnknown}};
      swarm_size_ = std::max(swarm_size_, orbits_[i].a.norm());
    }
    if (!(swarm_size_ > 0)) swarm_size_ = 1;
    if (!config.wall_moves.empty() && config.container_radius)
      path_.emplace(*config.container_radius, config.wall_moves);
    wall_ = sphere_wall();
    lane_size_ = std::max<std::size_t>(1, (orbits_.size() + lanes_.size() - 1) / lanes_.size());
    for (Lane& lane : lanes_) lane.wheel = TimingWheel(lane_size_);

    cache_ = std::move(initial);
    cache_valid_ = true;
    start_epoch();
    start_anchor();
  }

  WallTally step(double dt) override {
    WallTally tally;
    cache_valid_ = false;
    if (!has_walls() || orbits_.empty()) {
      if (epoch_too_old(dt)) rebase();
      if (path_) config_.container_radius = path_->radius_at(t_ + dt);
      finish_step(flow_at(tau_), flow_at(tau_ + dt), ForcedFlow::over(k_, gamma_, dt), dt,
                  Vec3::Zero(), 1, tally);
      flow_carried_ = false;
      return tally;
    }
    if (dt != dt_) {
      dt_ = dt;
      steps_per_phase_ = 1 / (phase_per_time_ * dt_);
      for (std::size_t j = 0; j < flows_ahead_.size(); ++j)
        flows_ahead_[j] = ForcedFlow::over(k_, gamma_, double(j) * dt);
      schedule_all_pending_ = true;
    }
    fast::StepData& d = now_;
    const WallRadii radii = wall_radii(dt);
    // The flow at the step's end; at its start it is the last step's end, unless a re-base
    // restarted the epoch's time since.
    const ForcedFlow last_end = d.f1;
    d.f1 = flow_at(tau_ + dt);
    const ForcedFlow& step_flow = flows_ahead_[1];
    // For J >= 0 a new anchor comes with a re-base, which also renews the margin's statistics.
    // For J < 0 the anchors are renewed without one, but Y, which the kicks make grow like
    // exp(Omega tau), must stay small: measured on the fireball, letting |Y| reach 0.02 R
    // instead of 0.005 R makes the energy drift 40 times larger. Under gravity or drag the
    // CM keeps moving against the wall (the wall holds the swarm up; drag slows it), so an
    // anchor lives only a few dozen steps and is renewed without a re-base too. A moving wall
    // spends the anchor's margin too (Anchor::margin_at, Anchor::wants_renewal).
    const bool anchors_in_o1 = k_ < 0 || forced_;
    const Anchor& current = anchors_.current();
    const bool rebased =
        epoch_too_old(dt) ||
        (!anchors_in_o1
             ? current.wants_renewal(current.offset(motion_, d.f1, step_flow), radii.end)
             : k_ < 0 && (d.f1.xc * motion_.aY + d.f1.xs * motion_.bY).norm() >
                             kMaxRepulsiveY * length());
    if (rebased) {
      rebase();
      d.f1 = flow_at(tau_ + dt);
    }
    d.f0 = rebased || !flow_carried_ ? flow_at(tau_) : last_end;
    flow_carried_ = true;
    if (gamma_ > 0) growth_ = portable::exp(gamma_ * tau_);
    lookahead_.prepare(motion_, d.f1, flows_ahead_, omega(), radii.ahead,
                       config_.floor ? config_.floor->z : -std::numeric_limits<double>::infinity());
    if (schedule_all_pending_)
      schedule_all();
    else if (anchors_in_o1 &&
             ((k_ < 0 && step_ - anchors_.current().start >= kRepulsiveAnchorSteps) ||
              step_ >= anchors_.current().renew_at ||
              anchors_.current().wants_renewal(anchors_.current().offset(motion_, d.f1, step_flow),
                                               radii.end)))
      next_anchor();
    redo_lookahead_if_kicks_too_large(radii.around);

    d.o0 = motion_.offset_at(d.f0, flows_ahead_[0]);
    d.o0v = motion_.offset_velocity_at(d.f0);
    d.o1 = motion_.offset_at(d.f1, step_flow);
    d.determinant = d.f0.xc * d.f0.vs - d.f0.vc * d.f0.xs;
    wall_.R2 = config_.container_radius ? radii.end * radii.end
                                        : std::numeric_limits<double>::infinity();
    wall_.u = path_ ? (radii.end - *config_.container_radius) / dt : 0.0;
    wall_.step = std::uint64_t(step_);
    anchors_.drop_expired(motion_, d.f1, step_flow, radii.end,
                          [this](std::uint8_t id) { expire(id); });

    std::size_t pending = 0;
    for (const Lane& lane : lanes_) pending += lane.wheel.waiting(step_);
    if (pool_.run(
            lanes_.size(), [this](std::size_t lane) { check_lane(lane); },
            pending >= kParallelChecks))
      ++stats_.parallel_steps;
    // The last lane's sums are those of every hit, in id order, whatever the number of lanes.
    const HitSums& all = lanes_.back().sums;
    tally = all.tally;
    const Vec3 kick = all.kick;  // sum of m dv / M: the change of V_cm (and of Y')
    if (gamma_ > 0) sums_ = all.sums;
    for (const Lane& lane : lanes_) stats_.checks += lane.checks;
    stats_.hits += tally.hits;
    finish_step(d.f0, d.f1, step_flow, dt, kick, d.determinant, tally);
    if (path_) config_.container_radius = radii.end;
    return tally;
  }

  const System& system() override {
    if (!cache_valid_) {
      const ForcedFlow f = flow_at(tau_);
      const Vec3 o = motion_.offset_at(f, ForcedFlow{}), ov = motion_.offset_velocity_at(f);
      cache_.J = J_;
      cache_.t = t_;
      cache_.particles.resize(orbits_.size());
      pool_.run(lanes_.size(), [&](std::size_t lane) {
        for (std::size_t i = lane_begin(lane); i < lane_end(lane); ++i)
          cache_.particles[i] = fast::particle_of(orbits_[i], f, o, ov);
      });
      cache_valid_ = true;
    }
    return cache_;
  }

  double time() const override { return t_; }

  void set_container_radius(std::optional<double> R) override {
    config_.container_radius = R;
    path_.reset();  // a wall that was moving stops
    wall_ = sphere_wall();
    // A new wall invalidates every schedule; start from a fresh anchor sized for it.
    rebase_pending_ = true;
    schedule_all_pending_ = true;
  }

  std::optional<double> container_radius() const override { return config_.container_radius; }
  const EngineConfig& config() const override { return config_; }
  std::unique_ptr<Engine> clone() const override { return std::make_unique<FastEngine>(*this); }
  FastEngineStats stats() const {
    FastEngineStats stats = stats_;
    stats.wall_push = wall_push_;
    return stats;
  }

 private:
  // [SECTION] Checks

  /// Appendix A for lane `index`: the particles predicted outside at t + dt and moving outward
  /// now are reflected now. Their predictions all use the state before any of this step's
  /// hits, so the lanes are independent, up to the sums of their hits (sum_hits).
  void check_lane(std::size_t index) {
    Lane& lane = lanes_[index];
    const fast::StepData& d = now_;
    lane.hits.clear();
    lane.checks = 0;
    lane.wheel.take(step_, lane.work);
    const std::size_t count = lane.work.size();
#ifdef __EMSCRIPTEN__
    lane.touched = fast::load_early(orbits_.data(), lane.work.data(), count);
#endif
    for (std::size_t j = 0; j < std::min(count, kPrefetch); ++j)
      fast::prefetch(&orbits_[lane.work[j]]);
    // In chunks of the work list: first every check, then the new windows of those hit, then
    // every schedule, each in the order of the work list (so the wheel's order is as if each
    // particle were done in turn): the windows' long chains of dependent operations then
    // overlap from one particle to the next. A schedule is for the next step on, so it does
    // not touch the ids of this one still to be checked.
    std::size_t checked = 0;
    WallTally one;  // a hit's own tally
    for (std::size_t start = 0; start < count; start += kCheckChunk) {
      const std::size_t stop = std::min(count, start + kCheckChunk);
      const std::size_t chunk_checked = checked, chunk_hits = lane.hits.size();
      for (std::size_t j = start; j < stop; ++j) {
        if (j + kPrefetch < count) fast::prefetch(&orbits_[lane.work[j + kPrefetch]]);
        const std::uint32_t i = lane.work[j];
        Body& o = orbits_[i];
        if (o.due != step_) continue;  // rescheduled since it was put here
        o.due = step_ + 1;             // checked: a second entry of i in this step is stale
        lane.work[checked++] = i;
        Vec3 dv;
        if (checks_more_) {
          Hit hit{i, Vec3::Zero(), WallTally{}, {}};
          if (check_under_forces(o, hit)) lane.hits.push_back(hit);
        } else if (fast::reflect_if_leaving(o, i, d, wall_, one, dv)) {
          lane.hits.push_back({i, (o.m / M_) * dv, one});
          one = WallTally{};
        }
      }
      make_windows(index, lane.hits.size() - chunk_hits,
                   [&](std::size_t j) { return lane.hits[chunk_hits + j].id; });
      for (std::size_t j = chunk_checked; j < checked; ++j)
        schedule(lane.work[j], step_ + 1, index);
    }
    lane.checks = std::int64_t(checked);
    lane.order.clear();
    for (std::size_t h = 0; h < lane.hits.size(); ++h)
      lane.order.push_back(std::uint64_t(lane.hits[h].id) << 32 | h);
    fast::sort_by_id(lane.order, lane.order_scratch);
    lane.work.clear();
    fast::release_if_large(lane.work, lane_size_);
    sum_hits(index);
  }

  /// Adds lane `index`'s hits, in id order, to the sums of the lanes before it (waiting for
  /// them): the lanes are consecutive ranges of ids, so in lane order the hits come in id
  /// order, and the sums are the same whatever the number of lanes. Each lane adds its own on
  /// its own thread, where they are in cache; only the sums go from thread to thread.
  void sum_hits(std::size_t index) {
    Lane& lane = lanes_[index];
    HitSums sums;
    if (index == 0) {
      sums.sums = sums_;
    } else {
      const Lane& before = lanes_[index - 1];
      fast::LanePool::wait_for(before.summed.step, std::uint64_t(step_));
      sums = before.sums;
    }
    for (const std::uint64_t key : lane.order) {
      const Hit& hit = lane.hits[key & 0xffffffff];
      sums.tally.add(hit.tally);
      sums.kick += hit.kick;
      if (gamma_ > 0) sums.sums.add(hit.sums_change);
    }
    lane.sums = sums;
    lane.summed.step.store(std::uint64_t(step_), std::memory_order_release);
  }

  /// check_lane's check of one particle with a floor or under drag: the wall, then the floor
  /// on the same prediction (the reference engine's order), and what the hits changed in the
  /// drag's energy sums, all into `hit`. Says whether the particle hit either.
  bool check_under_forces(Body& o, Hit& hit) {
    const Body before = o;
    Vec3 dv;
    bool any = false;
    if (fast::reflect_if_leaving(o, hit.id, now_, wall_, hit.tally, dv)) {
      hit.kick += (o.m / M_) * dv;
      any = true;
    }
    if (config_.floor && fast::bounce_if_falling(o, before, now_, *config_.floor, hit.tally, dv)) {
      hit.kick += (o.m / M_) * dv;
      any = true;
    }
    if (any && gamma_ > 0) hit.sums_change.replace(before, o);
    return any;
  }

  /// One lane per thread, at most LanePool::kMaxLanes.
  static std::size_t lane_count(int threads) {
    return std::clamp<std::size_t>(std::size_t(std::max(threads, 1)), 1, fast::LanePool::kMaxLanes);
  }
  /// The particles of lane `lane`: [begin, end).
  std::size_t lane_begin(std::size_t lane) const {
    return std::min(lane * lane_size_, orbits_.size());
  }
  std::size_t lane_end(std::size_t lane) const { return lane_begin(lane + 1); }
  /// The lane of particle i (a division: the lanes' own loops pass their index instead).
  std::size_t lane_index(std::uint32_t i) const { return i / lane_size_; }

  // [SECTION] Shared motion

  /// R_cm and Y take the same velocity kick at tau_, so o keeps its position and velocity.
  /// Y's coefficients change exactly as the sum of the y_i's do, i.e. by the kick divided by
  /// the flow's computed determinant (see check_lane), so that R_cm stays the particles' CM.
  /// Then the CM moves on over the step (step: the flow over dt); under drag the energy it
  /// takes, the drop of the energy from f0 to f1, goes into tally's books.
  void finish_step(const ForcedFlow& f0, const ForcedFlow& f1, const ForcedFlow& step, double dt,
                   const Vec3& kick, double determinant, WallTally& tally) {
    motion_.V_cm += kick;
    const Vec3 jump = kick / determinant;
    motion_.aY -= f0.xs * jump;
    motion_.bY += f0.xc * jump;
    if (!forced_) {
      motion_.R_cm += motion_.V_cm * dt;
    } else {
      const double energy_before = gamma_ > 0 ? energy_at(f0) : 0.0;
      motion_.R_cm += motion_.V_cm * step.cm_v + step.cm_g * motion_.g;
      motion_.V_cm = step.cm_vv * motion_.V_cm + step.cm_vg * motion_.g;
      if (gamma_ > 0) tally.books.drag_loss += energy_before - energy_at(f1);
    }
    if (off_centre_anchors_ && dt > 0)
      wall_push_ += (kick / dt - wall_push_) * std::min(1.0, dt / fit_horizon());
    lookahead_.record_kick(step_, kick.norm());
    tau_ += dt;
    t_ += dt;
    ++step_;
  }

  /// sqrt|k|: omega for J > 0, Omega for J < 0, 0 for J = 0.
  double omega() const { return 0.5 * two_omega_; }

  /// Whether there is a wall or a floor to check.
  bool has_walls() const { return config_.container_radius || config_.floor; }

  /// The length the schedule's margins and budgets scale with: the wall's radius, or without
  /// one (a floor alone) the swarm's size at the start.
  double length() const { return config_.container_radius.value_or(swarm_size_); }

  /// How far ahead an off-centre anchor's forecast looks (time), at most (OffsetFit).
  double fit_horizon() const { return k_ > 0 ? kFitTimes / omega() : kFitSteps * dt_; }

  /// The flow of the y_i over the time tau since the epoch began.
  ForcedFlow flow_at(double tau) const { return ForcedFlow::over(k_, gamma_, tau); }

  /// The system's energy (kinetic, the springs' and gravity's) at the time of flow f, with
  /// R_cm and V_cm as they are then: O(1) from the sums of the y_i's coefficients. With x_i =
  /// y_i - Y, sum m (|x'|^2 + k |x|^2) = sum m (|y'|^2 + k |y|^2) - M (|Y'|^2 + k |Y|^2).
  double energy_at(const ForcedFlow& f) const {
    const double own = (f.vc * f.vc + k_ * f.xc * f.xc) * sums_.aa +
                       2 * (f.vc * f.vs + k_ * f.xc * f.xs) * sums_.ab +
                       (f.vs * f.vs + k_ * f.xs * f.xs) * sums_.bb;
    const Vec3 Y = f.xc * motion_.aY + f.xs * motion_.bY;
    const Vec3 Yv = f.vc * motion_.aY + f.vs * motion_.bY;
    const double about_cm = 0.5 * (own - M_ * (Yv.squaredNorm() + k_ * Y.squaredNorm()));
    return about_cm + 0.5 * M_ * motion_.V_cm.squaredNorm() - M_ * motion_.g.dot(motion_.R_cm);
  }

  // [SECTION] The wall: where it is, for the hits and for the schedules

  /// The wall's radius at the end of the step of length dt that starts now, and, for the
  /// lookahead, the least it has over the next kLookahead + 1 steps (ahead) and over those and
  /// the last kLookahead + 1 steps (around), whose lookaheads are still relied on. Without a
  /// wall (a floor alone) all three are length(), the size the anchors were made for.
  struct WallRadii {
    double end, ahead, around;
  };
  WallRadii wall_radii(double dt) const {
    const double R = length();
    if (!path_) return {R, R, R};
    const double span = (kLookahead + 1) * dt;
    return {path_->radius_at(t_ + dt), path_->lowest_between(t_, t_ + span),
            path_->lowest_between(t_ - span, t_ + span)};
  }

  /// The hit's rules that stay from step to step (fast_engine_wall.h); the step sets the rest.
  fast::SphereWall sphere_wall() const {
    fast::SphereWall wall;
    wall.moving = path_.has_value();
    wall.temperature = config_.wall_temperature.value_or(0.0);
    wall.stream = config_.wall_stream;
    return wall;
  }

  // [SECTION] Epochs and anchors

  bool epoch_too_old(double dt) const {
    if (rebase_pending_) return true;
    if (gamma_ * (tau_ + dt) > kMaxDragDecay) return true;
    if (k_ > 0) return omega() * (tau_ + dt) > kMaxAttractivePhase;
    if (k_ < 0) return omega() * (tau_ + dt) > kMaxRepulsivePhase;
    return tau_ + dt > kMaxFreeSteps * dt;
  }

  /// Starts a new epoch at the current time, in one pass over the particles: applies a
  /// re-base's shift if there is one, recomputes Y from the y_i (it is zero up to rounding
  /// right after a re-base) and, for J > 0, tallies how far short of the wall each particle's
  /// largest |y| falls, for the next anchor's margin.
  void start_epoch(const fast::Shift* shift = nullptr) {
    constexpr int kBins = fast::GapHistogram::kBins;
    const double Rw = config_.container_radius.value_or(0.0);
    const double reach = std::max(Rw - motion_.R_cm.norm(), 1e-300);
    const double bins_per_length = kBins / (0.5 * std::max(Rw, 1e-300));
    const double inv_omega = spring_.inv_omega, eta = spring_.eta;
    const bool histogram = window_k_ > 0 && Rw > 0;
    const bool drag = gamma_ > 0;
    // Sums over fixed blocks, combined in block order: the rounding does not depend on the
    // threads. (The histogram's counts are integers.)
    const std::size_t blocks = (orbits_.size() + kSumBlock - 1) / kSumBlock;
    std::vector<Vec3> sum_a(blocks), sum_b(blocks);
    std::vector<fast::CoefficientSums> sums(drag ? blocks : 0);
    std::vector<fast::GapHistogram> gaps(histogram ? blocks : 0);
    pool_.run(blocks, [&](std::size_t block) {
      Vec3 sa = Vec3::Zero(), sb = Vec3::Zero();
      const std::size_t end = std::min(orbits_.size(), (block + 1) * kSumBlock);
      for (std::size_t i = block * kSumBlock; i < end; ++i) {
        Body& o = orbits_[i];
        if (shift) fast::shift(o, *shift);
        sa += o.m * o.a;
        sb += o.m * o.b;
        if (drag) sums[block].include(o);
        if (!histogram) continue;
        // Under drag the largest |y| to come is at most that of the free oscillation the
        // windows see (fast_engine_window.h).
        const fast::Swing swing =
            fast::swing_of(o.a, drag ? Vec3(o.b + eta * o.a) : o.b, inv_omega);
        gaps[block].counts[fast::GapHistogram::bin_of(swing.P + swing.A, reach, bins_per_length)]++;
      }
      sum_a[block] = sa;
      sum_b[block] = sb;
    });
    sums_ = {};
    for (const fast::CoefficientSums& block : sums) sums_.add(block);
    gaps_.counts.fill(0);
    for (const auto& block : gaps)
      for (int b = 0; b < kBins; ++b) gaps_.counts[std::size_t(b)] += block.counts[std::size_t(b)];
    Vec3 total_a = Vec3::Zero(), total_b = Vec3::Zero();
    for (std::size_t block = 0; block < blocks; ++block) {
      total_a += sum_a[block];
      total_b += sum_b[block];
    }
    motion_.aY = total_a / M_;
    motion_.bY = total_b / M_;
    epoch_start_ += tau_;
    tau_ = 0;
  }

  /// Makes a new anchor current, taking p, q from Y now and a margin sized for the wall (see
  /// fast::anchor_with_margin). A moving wall's anchor is made for the smaller of its radii
  /// now and at the end of the step (of the last step's length), so that a wall moving in
  /// spends none of the margin in the step the anchor starts in.
  void start_anchor() {
    Anchor next;
    next.id = anchors_.next_id();
    next.start = step_;
    next.p = motion_.aY;
    next.q = motion_.bY;
    const ForcedFlow now = flow_at(tau_);
    Vec3 offset = next.offset(motion_, now, ForcedFlow{});
    double R = length(), wall_step = 0;
    if (path_ && dt_ > 0) {
      const double R_end = path_->radius_at(t_ + dt_);
      wall_step = std::abs(R_end - R);
      R = std::min(R, R_end);
    }
    fast::OffsetFit fit;
    if (off_centre_anchors_) {
      // The offset is R_cm now and moves as the CM does under g, less the wall's recent mean
      // push, which moves R_cm and Y alike but Y as an oscillator.
      double horizon = fit_horizon();
      fit = fast::fit_offset_path(offset, motion_.V_cm, motion_.g, wall_push_, k_, horizon);
      // Strong gravity on a loose swarm (g / k, or g horizon^2 for J = 0, of the order of R):
      // a shorter horizon until the anchor's margin, which has a cap, holds what the fit
      // leaves; else the anchor would start with its offset outside its own margin.
      while (fit.residual > fast::largest_fit_residual(R) && horizon > dt_) {
        horizon *= 0.5;
        fit = fast::fit_offset_path(offset, motion_.V_cm, motion_.g, wall_push_, k_, horizon);
      }
      // The reference path less F: in the epoch's flow, F's coefficients are the inverse flow
      // of (A, B) now.
      const double det = now.xc * now.vs - now.vc * now.xs;
      next.p -= (now.vs * fit.A - now.xs * fit.B) / det;
      next.q -= (now.xc * fit.B - now.vc * fit.A) / det;
      offset = fit.centre;
      if (dt_ > 0) next.renew_at = step_ + StepIndex(horizon / dt_);
    }
    const fast::MarginInputs margin{R,
                                    wall_step,
                                    k_,
                                    omega(),
                                    motion_.V_cm.norm(),
                                    config_.floor.has_value(),
                                    off_centre_anchors_,
                                    fit.residual,
                                    orbits_.size(),
                                    &gaps_};
    anchors_.make_current(fast::anchor_with_margin(next, offset, margin));
  }

  /// A new current anchor without a re-base (J < 0, or under gravity or drag): O(1).
  void next_anchor() {
    anchors_.retire_current();
    start_anchor();
  }

  /// Folds Y into every y_i (O(N)) so that y_i is again the oscillation about the CM, and
  /// starts a new anchor; the old one stays valid while its own offset stays within its margin.
  void rebase() {
    ++stats_.rebases;
    rebase_pending_ = false;
    const ForcedFlow f = flow_at(tau_);
    const Vec3 Y = f.xc * motion_.aY + f.xs * motion_.bY;
    const Vec3 Yv = f.vc * motion_.aY + f.vs * motion_.bY;
    const bool keep_schedules = has_walls() && !schedule_all_pending_;
    const fast::Shift shift{f, Y, Yv, !keep_schedules};
    if (keep_schedules) {
      // Every y_i moved by the flow of (-Y, -Y'): the anchors' p, q move with them.
      anchors_.retire_current();
      for (Anchor& a : anchors_.old()) {
        const Vec3 p = f.xc * a.p + f.xs * a.q - Y;
        const Vec3 q = f.vc * a.p + f.vs * a.q - Yv;
        a.p = p;
        a.q = q;
      }
    } else {
      anchors_.old().clear();
      schedule_all_pending_ = true;
    }
    start_epoch(&shift);
    start_anchor();
  }

  /// Reschedules, in the current anchor, every particle still scheduled in anchor id: their
  /// windows all at once (make_windows), then their schedules in id order.
  void expire(std::uint8_t id) {
    std::vector<std::int64_t> expired(lanes_.size());
    pool_.run(lanes_.size(), [&](std::size_t lane) {
      std::vector<std::uint32_t>& ids = lanes_[lane].expiring;
      ids.clear();
      const std::size_t end = lane_end(lane);
      for (std::size_t i = anchors_.next_relying(id, lane_begin(lane), end); i < end;
           i = anchors_.next_relying(id, i + 1, end))
        ids.push_back(std::uint32_t(i));
      expired[lane] = std::int64_t(ids.size());
      make_windows(lane, ids.size(), [&](std::size_t j) { return ids[j]; });
      for (const std::uint32_t i : ids) schedule(i, step_, lane);
      fast::release_if_large(ids, lane_size_);
    });
    for (const std::int64_t n : expired) stats_.expired += n;
  }

  void schedule_all() {
    ++stats_.reschedules;
    schedule_all_pending_ = false;
    for (Lane& lane : lanes_) {
      lane.wheel.clear();
      for (auto& list : lane.lookahead) list.clear();
    }
    // With the old anchors gone, no window may rely on one: every particle gets a window in
    // the current anchor.
    std::vector<std::size_t> lane_sizes(lanes_.size());
    for (std::size_t lane = 0; lane < lanes_.size(); ++lane)
      lane_sizes[lane] = lane_end(lane) - lane_begin(lane);
    anchors_.move_all_to_current(lane_sizes);
    pool_.run(lanes_.size(), [&](std::size_t lane) {
      for (std::size_t i = lane_begin(lane); i < lane_end(lane); ++i) {
        orbits_[i].window.first = kUnknown;
        schedule(std::uint32_t(i), step_, lane);
      }
    });
  }

  // [SECTION] Scheduling

  /// Puts particle i (of lane `lane`) in the bucket of the first step >= first (step_ or
  /// step_ + 1) in which it can hit the wall, as far as the schedule can tell.
  void schedule(std::uint32_t i, StepIndex first, std::size_t lane) {
    Body& o = orbits_[i];
    // A particle keeps its window, and with it the anchor it relies on, until it hits the
    // wall or that anchor expires: re-bases and new anchors leave the window as it was.
    if (std::isnan(o.window.first)) make_window(i, lane);
    fast::Span span = span_at(i, first);
    StepIndex due = window_begin(span, first);
    if (due <= step_ + kLookahead) {
      // Only the steps in the window can hit: once it has begun, the lookahead goes on to
      // its end at most (just after a hit, on the way in, that is a step or two).
      const StepIndex last =
          std::min(step_ + kLookahead, first + StepIndex(std::min(span.end, 1e9)) + 1);
      due = look_ahead(o, due, last, lane);
      // Nothing until then: carry on with the window from the first step after.
      if (due > last) due = window_begin(span_at(i, due), due);
    }
    if (due == kParked) {
      o.due = kParked;  // until its anchor expires
      return;
    }
    due = std::min(due, step_ + TimingWheel::kHorizon);
    o.due = due;
    enqueue(i, due, lane);
  }

  /// Particle i's (of lane `lane`) window in the current anchor, which it relies on from now
  /// on (with a floor, its floor window too).
  void make_window(std::uint32_t i, std::size_t lane) {
    Body& o = orbits_[i];
    if (!anchors_.relies_on_current(i)) anchors_.move_to_current(i, int(lane));
    const Anchor& current = anchors_.current();
    const double phase_origin = phase_per_time_ * epoch_start_;
    o.window = !config_.container_radius ? fast::never_window(window_k_)
               : current.threshold <= 0 ? fast::always_window(window_k_)
               : current.centred()
                   ? fast::window_of(o.a - current.p, o.b - current.q, spring_, current.threshold2,
                                     phase_origin, growth_)
                   : fast::off_centre_window_of(o.a - current.p, o.b - current.q, current.centre,
                                                spring_, current.threshold2, phase_origin);
    if (config_.floor) make_floor_window(i);
  }

  /// Particle i's floor window in the current anchor.
  void make_floor_window(std::uint32_t i) {
    const Body& o = orbits_[i];
    const Anchor& current = anchors_.current();
    floor_windows_[i] = fast::floor_window_of(
        o.a.z() - current.p.z(), o.b.z() - current.q.z(), spring_,
        config_.floor->z - current.floor_low,
        fast::floor_clock(clock_at(step_)).phase_per_time * epoch_start_, growth_);
  }

  /// The new windows of n particles of lane `index`, the jth being id_of(j), all at once
  /// (fast_engine_window_batch.h): a step's hits, or the particles of an expired anchor; with
  /// a floor, their floor windows one by one. One by one under drag or without a wall, which
  /// the batch does not know.
  template <class IdOf>
  void make_windows(std::size_t index, std::size_t n, const IdOf& id_of) {
    Lane& lane = lanes_[index];
    const Anchor& current = anchors_.current();
    if (current.threshold <= 0 || gamma_ > 0 || !config_.container_radius) {
      for (std::size_t j = 0; j < n; ++j) make_window(id_of(j), index);
      return;
    }
    lane.hit_a.resize(n);
    lane.hit_b.resize(n);
    lane.hit_windows.resize(n);
    for (std::size_t j = 0; j < n; ++j) {
      const std::uint32_t i = id_of(j);
      if (!anchors_.relies_on_current(i)) anchors_.move_to_current(i, int(index));
      lane.hit_a[j] = orbits_[i].a - current.p;
      lane.hit_b[j] = orbits_[i].b - current.q;
    }
    const double phase_origin = phase_per_time_ * epoch_start_;
    if (current.centred())
      fast::windows_of(lane.hit_a.data(), lane.hit_b.data(), n, spring_, current.threshold2,
                       phase_origin, lane.hit_windows.data());
    else
      fast::off_centre_windows_of(lane.hit_a.data(), lane.hit_b.data(), n, current.centre,
                                  spring_, current.threshold2, phase_origin,
                                  lane.hit_windows.data());
    for (std::size_t j = 0; j < n; ++j) orbits_[id_of(j)].window = lane.hit_windows[j];
    if (config_.floor)
      for (std::size_t j = 0; j < n; ++j) make_floor_window(id_of(j));
  }

  /// Where particle i's windows lie, seen from the end of step m: the wall's, or with a floor
  /// the one that begins first, merged with the other where they overlap.
  fast::Span span_at(std::uint32_t i, StepIndex m) const {
    const fast::Clock clock = clock_at(m);
    const fast::Span wall = fast::span_of(orbits_[i].window, clock);
    if (!config_.floor) return wall;
    const fast::Span floor = fast::span_of(floor_windows_[i], fast::floor_clock(clock));
    const fast::Span& early = wall.begin <= floor.begin ? wall : floor;
    const fast::Span& late = wall.begin <= floor.begin ? floor : wall;
    return {early.begin, late.begin <= early.end ? std::max(early.end, late.end) : early.end};
  }

  /// The time at the end of step m, as the windows count it.
  fast::Clock clock_at(StepIndex m) const {
    return {window_k_, phase_per_time_, steps_per_phase_,
            epoch_start_ + tau_ + double(m - step_ + 1) * dt_};
  }

  /// The first step >= first at whose end |y| can be >= T (the anchor's wall threshold), or
  /// kParked; span is the window seen from the end of step `first`.
  static StepIndex window_begin(const fast::Span& span, StepIndex first) {
    if (span.begin == std::numeric_limits<double>::infinity()) return kParked;
    // A thousandth of a step covers the rounding of the closed forms. Clamped first, so that
    // truncating is rounding down (std::floor is a library call on x86-64 without SSE4.1).
    return first +
           StepIndex(std::clamp(span.begin - 1e-3, 0.0, double(TimingWheel::kHorizon)));
  }

  /// The first step from `from` to `last` (at most step_ + kLookahead) whose predicted end
  /// position can be outside the wall, or last + 1. Recorded, in case the kicks exceed the
  /// budget the prediction relies on.
  StepIndex look_ahead(const Body& o, StepIndex from, StepIndex last, std::size_t lane) {
    const StepIndex due = lookahead_.first_reach(o.a, o.b, from, last, step_);
    if (due > from) {
      const auto i = std::uint32_t(&o - orbits_.data());
      lanes_[lane].lookahead[std::size_t(step_) % (kLookahead + 1)].push_back(i);
    }
    return due;
  }

  /// The lookahead of the last kLookahead + 1 steps relied on their kicks staying within
  /// budget (made for a wall of radius R at least). If they did not, every particle it skipped
  /// ahead is rescheduled without it.
  void redo_lookahead_if_kicks_too_large(double R) {
    if (k_ == 0 || lookahead_.kicks_within_budget(omega(), R)) {
      // The schedules made kLookahead + 1 steps ago no longer rely on anything unchecked.
      for (Lane& lane : lanes_) lane.lookahead[std::size_t(step_) % (kLookahead + 1)].clear();
      return;
    }
    std::vector<std::uint32_t> ids;
    for (Lane& lane : lanes_)
      for (auto& list : lane.lookahead) {
        ids.insert(ids.end(), list.begin(), list.end());
        list.clear();
      }
    for (const std::uint32_t i : ids)
      if (orbits_[i].due != kParked && orbits_[i].due >= step_) {
        orbits_[i].due = step_;  // schedule(i, step_) without the lookahead
        enqueue(i, step_, lane_index(i));
      }
    lookahead_.forget_kicks();
  }

  /// Puts particle i, due in step `due` (step_ <= due <= step_ + kHorizon), in its lane's
  /// wheel. Particles rescheduled before their step leave stale entries; they are weeded out
  /// before they cost memory (anchors expire often when J < 0).
  void enqueue(std::uint32_t i, StepIndex due, std::size_t lane) {
    TimingWheel& wheel = lanes_[lane].wheel;
    if (wheel.push(i, due, step_))
      wheel.compact([this](std::uint32_t id) { return orbits_[id].due; });
  }

  EngineConfig config_;
  std::optional<WallPath> path_;  ///< a moving wall's radius over time
  fast::SphereWall wall_;         ///< the wall as this step's hits see it
  double J_ = 0, M_ = 0, k_ = 0, t_ = 0;
  double two_omega_ = 0;  // 2 sqrt|k|
  bool forced_ = false;   // gravity or drag
  double gamma_ = 0;      // mass-proportional drag rate (1/time)
  double window_k_ = 0;   // k - (gamma / 2)^2: the stiffness the windows see
  fast::Spring spring_;   // the windows'
  double growth_ = 1;     // exp(gamma tau_): the windows' envelope now (fast_engine_window.h)
  fast::CoefficientSums sums_;  // under drag: for energy_at
  bool checks_more_ = false;    // a floor or drag: check_under_forces
  // Under gravity (without drag, J >= 0) the anchors are made about the swarm's offset from
  // the container's centre (fast_engine_anchor.h): J < 0 and drag keep centred ones, for
  // which off_centre_window_of has no tighter window.
  bool off_centre_anchors_ = false;
  // Off-centre: the push of the wall and the floor on the CM (their kicks a time,
  // length/time^2), a running mean over the fit's horizon: the CM's forecast falls with g less
  // what they hold up.
  Vec3 wall_push_ = Vec3::Zero();
  double swarm_size_ = 0;       // the largest distance from the CM at the start
  std::vector<fast::Window> floor_windows_;  // with a floor: each particle's, as its window
  std::vector<Body> orbits_;

  // Shared motion, in the current epoch (tau_ is the time since it began).
  double tau_ = 0;
  double epoch_start_ = 0;  // when the current epoch began, in time counted from the first
  fast::SharedMotion motion_;

  // The schedule.
  StepIndex step_ = 0;
  double dt_ = 0;
  std::vector<Lane> lanes_;
  std::size_t lane_size_ = 1;  // particles per lane (the last may have fewer)
  fast::StepData now_{};
  bool flow_carried_ = false;  // now_.f1 holds the flow at tau_
  fast::Anchors anchors_;
  bool schedule_all_pending_ = true, rebase_pending_ = false;
  fast::Lookahead lookahead_;
  double phase_per_time_ = 1;  // the windows' phase per unit time
  double steps_per_phase_ = 0;
  fast::Lookahead::FlowsAhead flows_ahead_{};  // the flows over 0, 1, ... steps of dt_
  fast::GapHistogram gaps_;  // J > 0: from the current epoch's start

  System cache_;
  bool cache_valid_ = false;
  FastEngineStats stats_;
  // Last, so that it is destroyed first: its threads stop before the data they work on goes.
  fast::LanePool pool_;
};

}  // namespace

// [SECTION] Factory

bool fast_engine_applies(const EngineConfig& config) {
  // Gravity moves only the CM, and mass-proportional drag makes every y_i a damped oscillator
  // about a decaying CM motion: both keep a particle's motion between hits in closed form.
  // Drag b on chosen particles does not: with a rate of its own for each particle the CM no
  // longer separates from the motion about it, the y_i couple through the CM, so a hit is no
  // longer O(1) and there is no closed form per particle.
  if (config.forces.drag && !config.forces.drag->mass_proportional()) return false;
  // An elastic floor is a plane wall: a particle falls through it at a crossing time of its
  // closed-form path. On an inelastic one particles come to rest (rest_on_floor), held up
  // out of any closed form.
  if (config.floor && config.floor->restitution != 1) return false;
  // Hard spheres touch every particle in every step (their contacts are between particles,
  // not with the wall), so no schedule of wall windows can skip them (docs/architecture.md).
  // A moving wall (its radius bracketed over each schedule's life, fast_engine_anchor.h) and a
  // thermal wall (a hit re-emits the particle onto a new orbit, fast_engine_wall.h) run here,
  // with forces and a floor or without: the hit only needs dv, whatever the wall does.
  return config.method == Method::analytic && config.collisions == CollisionMode::paper &&
         !config.sphere_radius;
}

std::unique_ptr<Engine> make_fast_engine(System initial, const EngineConfig& config) {
  return std::make_unique<FastEngine>(std::move(initial), config);
}

std::optional<FastEngineStats> fast_engine_stats(const Engine& engine) {
  if (const auto* fast = dynamic_cast<const FastEngine*>(&engine)) return fast->stats();
  return std::nullopt;
}

}  // namespace swarm
