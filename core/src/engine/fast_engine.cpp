// The fast engine: Appendix A with the analytic method at a cost that grows with the number
// of wall hits rather than with N times the number of steps (see swarm/engine/fast_engine.h).
//
// Index
// [SECTION] Tuning
// [SECTION] State: a lane of the schedule (a particle: fast_engine_body.h)
// [SECTION] Engine: construction, step, system()
// [SECTION] Checks: Appendix A for the particles due in a step
// [SECTION] Shared motion: the CM, Y and the step's end
// [SECTION] Epochs and anchors: re-bases, new anchors, expiry
// [SECTION] Scheduling: windows, the lookahead, the timing wheel
// [SECTION] Factory

#include "swarm/engine/fast_engine.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "engine/fast_engine_anchor.h"
#include "engine/fast_engine_body.h"
#include "engine/fast_engine_lookahead.h"
#include "engine/fast_engine_window.h"
#include "engine/fast_engine_window_batch.h"
#include "engine/id_sort.h"
#include "engine/lane_pool.h"
#include "engine/timing_wheel.h"
#include "swarm/physics/flow.h"
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
// How many ids ahead of the one being checked the particle data is fetched.
constexpr std::size_t kPrefetch = 8;
// The particles are split by index into one lane per thread, each with its own buckets, so
// that a step's checks run on all the threads. No number depends on that split: a step's hits
// are combined in particle-id order (the reference engine's order), and the epoch's sums over
// all particles in blocks of kSumBlock particles, in block order.
constexpr std::size_t kSumBlock = 4096;
// Steps with fewer checks than this run on one thread. With the pool's busy-polling hand-over
// even a step of a few dozen checks gains from a second core (the headline: about 40 per
// step), so only steps without any run on one.
constexpr std::size_t kParallelChecks = 1;

// [SECTION] State

/// A hit of one step, kept apart until the step's hits are combined in particle-id order.
struct Hit {
  std::uint32_t id;
  Vec3 kick;  // m dv / M: its share of the change of V_cm
  WallTally tally;
};

/// One lane of the schedule: its timing wheel and the hits of one step. Each lane's thread
/// writes its own in every check: a cache line apart, lanes never share one.
struct alignas(64) Lane {
  TimingWheel wheel;
  std::vector<std::uint32_t> work;  // the ids taken from the wheel for this step
  std::vector<Vec3> hit_a, hit_b;   // the coefficients of its hits in the current anchor
  std::vector<fast::Window> hit_windows;
  std::array<std::vector<std::uint32_t>, kLookahead + 1> lookahead;
  std::vector<Hit> hits;
  // The hits in particle-id order once the checks are done: id << 32 | place in `hits` (sorted
  // as integers: cheaper than moving the hits).
  std::vector<std::uint64_t> order, order_scratch;
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
    two_omega_ = 2 * std::sqrt(std::abs(k_));
    spring_ = {k_, k_ != 0 ? 1 / std::sqrt(std::abs(k_)) : 0.0};
    phase_per_time_ = k_ != 0 ? two_omega_ : 1.0;
    motion_.R_cm = cm_position(initial);
    motion_.V_cm = cm_velocity(initial);
    orbits_.resize(initial.particles.size());
    for (std::size_t i = 0; i < orbits_.size(); ++i) {
      const Particle& p = initial.particles[i];
      orbits_[i] = {p.r - motion_.R_cm, p.v - motion_.V_cm, p.m, kParked, {kUnknown, kUnknown}};
    }
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
    if (!config_.container_radius || orbits_.empty()) {
      if (epoch_too_old(dt)) rebase();
      finish_step(Flow::over(k_, tau_), Vec3::Zero(), dt);
      flow_carried_ = false;
      return tally;
    }
    if (dt != dt_) {
      dt_ = dt;
      steps_per_phase_ = 1 / (phase_per_time_ * dt_);
      schedule_all_pending_ = true;
    }
    fast::StepData& d = now_;
    // The flow at the step's end; at its start it is the last step's end, unless a re-base
    // restarted the epoch's time since.
    const Flow last_end = d.f1;
    d.f1 = Flow::over(k_, tau_ + dt);
    // For J >= 0 a new anchor comes with a re-base, which also renews the margin's statistics.
    // For J < 0 the anchors are renewed without one, but Y, which the kicks make grow like
    // exp(Omega tau), must stay small: measured on the fireball, letting |Y| reach 0.02 R
    // instead of 0.005 R makes the energy drift 40 times larger.
    const Anchor& current = anchors_.current();
    const bool rebased = epoch_too_old(dt) ||
                         (k_ >= 0 ? current.offset(motion_, d.f1, dt).norm() > current.renew_level
                                  : (d.f1.c * motion_.aY + d.f1.s * motion_.bY).norm() >
                                        kMaxRepulsiveY * *config_.container_radius);
    if (rebased) {
      rebase();
      d.f1 = Flow::over(k_, tau_ + dt);
    }
    d.f0 = rebased || !flow_carried_ ? Flow::over(k_, tau_) : last_end;
    flow_carried_ = true;
    lookahead_.prepare(motion_, d.f1, k_, omega(), dt, *config_.container_radius);
    if (schedule_all_pending_)
      schedule_all();
    else if (k_ < 0 &&
             (step_ - anchors_.current().start >= kRepulsiveAnchorSteps ||
              anchors_.current().offset(motion_, d.f1, dt).norm() > anchors_.current().renew_level))
      next_anchor();
    redo_lookahead_if_kicks_too_large();

    d.o0 = motion_.offset_at(d.f0, 0);
    d.o0v = motion_.offset_velocity_at(d.f0);
    d.o1 = motion_.offset_at(d.f1, dt);
    d.R2 = *config_.container_radius * *config_.container_radius;
    d.determinant = d.f0.c * d.f0.c - d.f0.dc() * d.f0.s;
    anchors_.drop_expired(motion_, d.f1, dt, [this](std::uint8_t id) { expire(id); });

    std::size_t pending = 0;
    for (const Lane& lane : lanes_) pending += lane.wheel.waiting(step_);
    if (pool_.run(
            lanes_.size(), [this](std::size_t lane) { check_lane(lanes_[lane]); },
            pending >= kParallelChecks))
      ++stats_.parallel_steps;
    // The lanes are consecutive ranges of ids, each with its hits sorted: in lane order the
    // hits come in id order, whatever the number of lanes.
    Vec3 kick = Vec3::Zero();  // sum of m dv / M: the change of V_cm (and of Y')
    for (const Lane& lane : lanes_) {
      for (const std::uint64_t key : lane.order) {
        const Hit& hit = lane.hits[key & 0xffffffff];
        tally.add(hit.tally);
        kick += hit.kick;
      }
      stats_.checks += lane.checks;
    }
    stats_.hits += tally.hits;
    finish_step(d.f0, kick, dt, d.determinant);
    return tally;
  }

  const System& system() override {
    if (!cache_valid_) {
      const Flow f = Flow::over(k_, tau_);
      const Vec3 o = motion_.offset_at(f, 0), ov = motion_.offset_velocity_at(f);
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
    // A new wall invalidates every schedule; start from a fresh anchor sized for it.
    rebase_pending_ = true;
    schedule_all_pending_ = true;
  }

  std::optional<double> container_radius() const override { return config_.container_radius; }
  const EngineConfig& config() const override { return config_; }
  std::unique_ptr<Engine> clone() const override { return std::make_unique<FastEngine>(*this); }
  const FastEngineStats& stats() const { return stats_; }

 private:
  // [SECTION] Checks

  /// Appendix A for one lane: the particles predicted outside at t + dt and moving outward
  /// now are reflected now. Their predictions all use the state before any of this step's
  /// hits, so the lanes are independent.
  void check_lane(Lane& lane) {
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
    // First every check, then the new windows of those hit, then every schedule, each in the
    // order of the work list (so the wheel's order is as if each particle were done in turn):
    // the windows' long chains of dependent operations then overlap from one particle to the
    // next.
    std::size_t checked = 0;
    WallTally one;  // a hit's own tally
    for (std::size_t j = 0; j < count; ++j) {
      if (j + kPrefetch < count) fast::prefetch(&orbits_[lane.work[j + kPrefetch]]);
      const std::uint32_t i = lane.work[j];
      Body& o = orbits_[i];
      if (o.due != step_) continue;  // rescheduled since it was put here
      o.due = step_ + 1;             // checked: a second entry of i in this step is stale
      lane.work[checked++] = i;
      Vec3 dv;
      if (fast::reflect_if_leaving(o, d, one, dv)) {
        lane.hits.push_back({i, (o.m / M_) * dv, one});
        one = WallTally{};
      }
    }
    lane.checks = std::int64_t(checked);
    make_windows(lane);
    for (std::size_t j = 0; j < checked; ++j) schedule(lane.work[j], step_ + 1);
    lane.order.clear();
    for (std::size_t h = 0; h < lane.hits.size(); ++h)
      lane.order.push_back(std::uint64_t(lane.hits[h].id) << 32 | h);
    fast::sort_by_id(lane.order, lane.order_scratch);
    lane.work.clear();
    fast::release_if_large(lane.work, lane_size_);
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
  int lane_index(std::uint32_t i) const { return int(i / lane_size_); }
  Lane& lane_of(std::uint32_t i) { return lanes_[std::size_t(lane_index(i))]; }

  // [SECTION] Shared motion

  /// R_cm and Y take the same velocity kick at tau_, so o keeps its position and velocity.
  /// Y's coefficients change exactly as the sum of the y_i's do, i.e. by the kick divided by
  /// the flow's computed determinant (see check_lane), so that R_cm stays the particles' CM.
  void finish_step(const Flow& f0, const Vec3& kick, double dt, double determinant = 1) {
    motion_.V_cm += kick;
    const Vec3 jump = kick / determinant;
    motion_.aY -= f0.s * jump;
    motion_.bY += f0.c * jump;
    motion_.R_cm += motion_.V_cm * dt;
    lookahead_.record_kick(step_, kick.norm());
    tau_ += dt;
    t_ += dt;
    ++step_;
  }

  /// sqrt|k|: omega for J > 0, Omega for J < 0, 0 for J = 0.
  double omega() const { return 0.5 * two_omega_; }

  // [SECTION] Epochs and anchors

  bool epoch_too_old(double dt) const {
    if (rebase_pending_) return true;
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
    const double inv_omega = spring_.inv_omega;
    const bool histogram = k_ > 0 && Rw > 0;
    // Sums over fixed blocks, combined in block order: the rounding does not depend on the
    // threads. (The histogram's counts are integers.)
    const std::size_t blocks = (orbits_.size() + kSumBlock - 1) / kSumBlock;
    std::vector<Vec3> sum_a(blocks), sum_b(blocks);
    std::vector<fast::GapHistogram> gaps(histogram ? blocks : 0);
    pool_.run(blocks, [&](std::size_t block) {
      Vec3 sa = Vec3::Zero(), sb = Vec3::Zero();
      const std::size_t end = std::min(orbits_.size(), (block + 1) * kSumBlock);
      for (std::size_t i = block * kSumBlock; i < end; ++i) {
        Body& o = orbits_[i];
        if (shift) fast::shift(o, *shift);
        sa += o.m * o.a;
        sb += o.m * o.b;
        if (!histogram) continue;
        const fast::Swing swing = fast::swing_of(o.a, o.b, inv_omega);
        gaps[block].counts[fast::GapHistogram::bin_of(swing.P + swing.A, reach, bins_per_length)]++;
      }
      sum_a[block] = sa;
      sum_b[block] = sb;
    });
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
  /// fast::anchor_with_margin).
  void start_anchor() {
    Anchor next;
    next.id = anchors_.next_id();
    next.start = step_;
    next.p = motion_.aY;
    next.q = motion_.bY;
    const double base = next.offset(motion_, Flow::over(k_, tau_), 0).norm();
    const fast::MarginInputs margin{config_.container_radius.value_or(1.0),
                                    k_,
                                    omega(),
                                    motion_.V_cm.norm(),
                                    orbits_.size(),
                                    &gaps_};
    anchors_.make_current(fast::anchor_with_margin(next, base, margin));
  }

  /// A new current anchor without a re-base (J < 0): O(1).
  void next_anchor() {
    anchors_.retire_current();
    start_anchor();
  }

  /// Folds Y into every y_i (O(N)) so that y_i is again the oscillation about the CM, and
  /// starts a new anchor; the old one stays valid while its own offset stays within its margin.
  void rebase() {
    ++stats_.rebases;
    rebase_pending_ = false;
    const Flow f = Flow::over(k_, tau_);
    const Vec3 Y = f.c * motion_.aY + f.s * motion_.bY;
    const Vec3 Yv = f.dc() * motion_.aY + f.c * motion_.bY;
    const bool keep_schedules = config_.container_radius && !schedule_all_pending_;
    const fast::Shift shift{f, Y, Yv, !keep_schedules};
    if (keep_schedules) {
      // Every y_i moved by the free flow of (-Y, -Y'): the anchors' p, q move with them.
      anchors_.retire_current();
      for (Anchor& a : anchors_.old()) {
        const Vec3 p = f.c * a.p + f.s * a.q - Y;
        const Vec3 q = f.dc() * a.p + f.c * a.q - Yv;
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

  /// Reschedules, in the current anchor, every particle still scheduled in anchor id.
  void expire(std::uint8_t id) {
    std::vector<std::int64_t> expired(lanes_.size());
    pool_.run(lanes_.size(), [&](std::size_t lane) {
      for (std::size_t i = lane_begin(lane); i < lane_end(lane); ++i)
        if (anchors_.anchor_of(i) == id) {
          ++expired[lane];
          orbits_[i].window.first = kUnknown;
          schedule(std::uint32_t(i), step_);
        }
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
        schedule(std::uint32_t(i), step_);
      }
    });
  }

  // [SECTION] Scheduling

  /// Puts particle i in the bucket of the first step >= first (step_ or step_ + 1) in which
  /// it can hit the wall, as far as the schedule can tell.
  void schedule(std::uint32_t i, StepIndex first) {
    Body& o = orbits_[i];
    // A particle keeps its window, and with it the anchor it relies on, until it hits the
    // wall or that anchor expires: re-bases and new anchors leave the window as it was.
    if (std::isnan(o.window.first)) make_window(i);
    fast::Span span = fast::span_of(o.window, clock_at(first));
    StepIndex due = window_begin(span, first);
    if (due <= step_ + kLookahead) {
      // Only the steps in the window can hit: once it has begun, the lookahead goes on to
      // its end at most (just after a hit, on the way in, that is a step or two).
      const StepIndex last =
          std::min(step_ + kLookahead, first + StepIndex(std::min(span.end, 1e9)) + 1);
      due = look_ahead(o, due, last);
      // Nothing until then: carry on with the window from the first step after.
      if (due > last) due = window_begin(fast::span_of(o.window, clock_at(due)), due);
    }
    if (due == kParked) {
      o.due = kParked;  // until its anchor expires
      return;
    }
    due = std::min(due, step_ + TimingWheel::kHorizon);
    o.due = due;
    enqueue(i, due);
  }

  /// Particle i's window in the current anchor, which it relies on from now on.
  void make_window(std::uint32_t i) {
    Body& o = orbits_[i];
    if (!anchors_.relies_on_current(i)) anchors_.move_to_current(i, lane_index(i));
    const Anchor& current = anchors_.current();
    o.window = current.threshold > 0
                   ? fast::window_of(o.a - current.p, o.b - current.q, spring_, current.threshold2,
                                     phase_per_time_ * epoch_start_)
                   : fast::always_window(k_);
  }

  /// The new windows of a lane's hits, all at once (fast_engine_window_batch.h).
  void make_windows(Lane& lane) {
    const std::size_t n = lane.hits.size();
    const Anchor& current = anchors_.current();
    if (current.threshold <= 0) {
      for (const Hit& hit : lane.hits) make_window(hit.id);
      return;
    }
    lane.hit_a.resize(n);
    lane.hit_b.resize(n);
    lane.hit_windows.resize(n);
    for (std::size_t j = 0; j < n; ++j) {
      const std::uint32_t i = lane.hits[j].id;
      if (!anchors_.relies_on_current(i)) anchors_.move_to_current(i, lane_index(i));
      lane.hit_a[j] = orbits_[i].a - current.p;
      lane.hit_b[j] = orbits_[i].b - current.q;
    }
    fast::windows_of(lane.hit_a.data(), lane.hit_b.data(), n, spring_, current.threshold2,
                     phase_per_time_ * epoch_start_, lane.hit_windows.data());
    for (std::size_t j = 0; j < n; ++j) orbits_[lane.hits[j].id].window = lane.hit_windows[j];
  }

  /// The time at the end of step m, as the windows count it.
  fast::Clock clock_at(StepIndex m) const {
    return {k_, phase_per_time_, steps_per_phase_,
            epoch_start_ + tau_ + double(m - step_ + 1) * dt_};
  }

  /// The first step >= first at whose end |y| can be >= T (the anchor's wall threshold), or
  /// kParked; span is the window seen from the end of step `first`.
  static StepIndex window_begin(const fast::Span& span, StepIndex first) {
    if (span.begin == std::numeric_limits<double>::infinity()) return kParked;
    // A thousandth of a step covers the rounding of the closed forms.
    return first +
           StepIndex(std::clamp(std::floor(span.begin - 1e-3), 0.0, double(TimingWheel::kHorizon)));
  }

  /// The first step from `from` to `last` (at most step_ + kLookahead) whose predicted end
  /// position can be outside the wall, or last + 1. Recorded, in case the kicks exceed the
  /// budget the prediction relies on.
  StepIndex look_ahead(const Body& o, StepIndex from, StepIndex last) {
    const StepIndex due = lookahead_.first_reach(o.a, o.b, from, last, step_);
    if (due > from) {
      const auto i = std::uint32_t(&o - orbits_.data());
      lane_of(i).lookahead[std::size_t(step_) % (kLookahead + 1)].push_back(i);
    }
    return due;
  }

  /// The lookahead of the last kLookahead + 1 steps relied on their kicks staying within
  /// budget. If they did not, every particle it skipped ahead is rescheduled without it.
  void redo_lookahead_if_kicks_too_large() {
    if (k_ == 0 || lookahead_.kicks_within_budget(omega(), *config_.container_radius)) {
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
        enqueue(i, step_);
      }
    lookahead_.forget_kicks();
  }

  /// Puts particle i, due in step `due` (step_ <= due <= step_ + kHorizon), in its lane's
  /// wheel. Particles rescheduled before their step leave stale entries; they are weeded out
  /// before they cost memory (anchors expire often when J < 0).
  void enqueue(std::uint32_t i, StepIndex due) {
    TimingWheel& wheel = lane_of(i).wheel;
    if (wheel.push(i, due, step_))
      wheel.compact([this](std::uint32_t id) { return orbits_[id].due; });
  }

  EngineConfig config_;
  double J_ = 0, M_ = 0, k_ = 0, t_ = 0;
  double two_omega_ = 0;  // 2 sqrt|k|
  fast::Spring spring_;
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
  // Gravity, drag and a floor change every particle's orbit or add a second wall that the
  // closed-form wall windows do not know: those run on the reference engine, O(N) a step.
  if (config.forces.any() || config.floor) return false;
  return config.method == Method::analytic && config.collisions == CollisionMode::paper &&
         // Its windows assume a wall that stands still, and hard spheres touch every particle
         // in every step (docs/architecture.md); the thermal wall is left to the reference
         // engine until the fast engine's hit takes a wall model (its draws are keyed on step
         // and particle so that it could).
         config.wall_moves.empty() && !config.wall_temperature && !config.sphere_radius;
}

std::unique_ptr<Engine> make_fast_engine(System initial, const EngineConfig& config) {
  return std::make_unique<FastEngine>(std::move(initial), config);
}

std::optional<FastEngineStats> fast_engine_stats(const Engine& engine) {
  if (const auto* fast = dynamic_cast<const FastEngine*>(&engine)) return fast->stats();
  return std::nullopt;
}

}  // namespace swarm
