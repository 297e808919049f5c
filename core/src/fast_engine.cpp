#include "swarm/fast_engine.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <vector>
#ifndef __EMSCRIPTEN__
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#endif

#include "fast_engine_window.h"
#include "swarm/flow.h"
#include "swarm/regime.h"

namespace swarm {
namespace {

// [SECTION] Tuning

using StepIndex = std::int64_t;
constexpr StepIndex kParked = std::numeric_limits<StepIndex>::max();
// The schedule is a two-level timing wheel: one bucket per step for the current and the next
// block of kBlock steps, one bucket per block for the kFarBlocks blocks after that (moved into
// the step buckets a block ahead). Pushes then land in a few hundred hot bucket tails rather
// than in thousands of cold ones. A particle due later still waits at the horizon and is
// looked at again then.
constexpr int kBlockBits = 6;
constexpr StepIndex kBlock = StepIndex(1) << kBlockBits;
constexpr StepIndex kFarBlocks = 64;
constexpr StepIndex kHorizon = (kFarBlocks - 1) * kBlock;
// Once a particle's wall window is less than this many steps away, its exact predicted lab
// positions at the next step ends are checked one by one (the "lookahead"), so that it is
// checked again only in a step in which it can actually hit.
constexpr int kLookahead = 16;
// The lookahead assumes that the centre-of-mass kicks of any kLookahead + 1 consecutive steps
// sum to at most kKickBudget * sqrt|k| * R in size; this is checked, and the lookahead
// schedules are redone when it fails (tiny N).
constexpr double kKickBudget = 0.2;
// A frame's margin above the CM's distance from the centre, as a fraction of the wall radius,
// at least; and how many time units 1 / sqrt|k| of CM drift it should absorb.
constexpr double kMarginFloor = 0.004;
constexpr double kMarginDriftTimes = 4;
// At most N / kShellBudget particles within reach of a widened margin (J > 0).
constexpr std::size_t kShellBudget = 100;
constexpr int kGapBins = 128;
// For J < 0 the runaway amplifies the kicks like exp(Omega tau), so a frame's offset soon
// outgrows any margin. A particle relies on the frame it was last scheduled in, so a new frame
// starts at least every kRepulsiveFrameSteps steps (in O(1): it records Y's path from then
// on) and a schedule relies only on the kicks of the next couple of hundred steps.
constexpr StepIndex kRepulsiveFrameSteps = 16;
// Frames without particles are dropped; beyond this many, the oldest is expired.
constexpr int kMaxOldFrames = 64;
// Re-base before exp(Omega tau) eats more than a few bits of the y_i (J < 0), and before the
// phase omega tau or the drift b tau gets large enough to cost digits (J >= 0).
constexpr double kMaxRepulsivePhase = 2.5;
constexpr double kMaxRepulsiveY = 0.005;  // times the wall radius
constexpr double kMaxAttractivePhase = 512;
constexpr double kMaxFreeSteps = 1024;
// How many ids ahead of the one being checked the particle data is fetched.
constexpr std::size_t kPrefetch = 8;
// The particles are split into kLanes halves by index, each with its own buckets and sums, so
// that a step's checks can run on two cores; the sums are always combined in lane order, so
// the numbers do not depend on how many threads ran (one in the browser).
constexpr int kLanes = 2;
// Steps with fewer checks than this run on one thread. With the busy-polling hand-over below
// even a step of a few dozen checks gains from the second core (the headline: about 40 per
// step), so only steps without any run on one.
constexpr std::size_t kParallelChecks = 1;
// A waiting thread yields this many times before it sleeps on a condition variable.
[[maybe_unused]] constexpr int kSpins = 20000;  // threads only exist natively
// Before that, it polls this many times without giving up the core.
[[maybe_unused]] constexpr int kBusySpins = 4000;

[[maybe_unused]] inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

inline void prefetch(const void* p) {
#if defined(__GNUC__)
  __builtin_prefetch(p);
  __builtin_prefetch(static_cast<const char*>(p) + 64);
#else
  (void)p;
#endif
}

// [SECTION] State

/// Everything the scheduler touches for one particle, together (80 bytes): a check is then
/// one or two cache lines, fetched ahead of time (the ids due in a step are known in advance).
struct Body {
  Vec3 a, b;  ///< y_i(tau) = c(tau) a + s(tau) b: the free oscillation about the CM path
  double m;
  StepIndex due;        ///< the step in whose bucket the particle waits, or kParked
  fast::Window window;  ///< valid in the particle's frame until its next hit; NaN: unknown
};

constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
static_assert(sizeof(Body) == 80, "a Body should stay within 80 bytes");

/// A choice of coordinates y_i - (c p + s q) for the particles (c, s the flow in the current
/// epoch's time). Schedules made in it assume that the frame's offset, o + c p + s q with
/// o = r_i - y_i, stays within its margin at every step end. A frame takes p, q from Y when it
/// starts, so that its offset then moves only with the CM and the later kicks; re-bases
/// carry p, q over into the new epoch.
struct Frame {
  std::uint8_t id = 0;
  StepIndex start = 0;
  double margin = 0;
  double threshold = 0, threshold2 = 0;  ///< T = R - margin and T^2: the windows' radius
  double renew_level = 0;  ///< while current: start a new frame when the offset passes this
  Vec3 p = Vec3::Zero(), q = Vec3::Zero();
};

/// A particle waiting in a block bucket: its id and its step within the block, packed into
/// 32 bits so that moving it to its step bucket does not touch the particle's record.
using FarEntry = std::uint32_t;
constexpr FarEntry far_entry(std::uint32_t id, StepIndex due) {
  return (id << kBlockBits) | FarEntry(due & (kBlock - 1));
}
static_assert(kMaxFastEngineParticles <= (std::size_t(1) << (32 - kBlockBits)),
              "particle ids must fit a FarEntry");

/// One lane of the schedule: a two-level timing wheel and the sums of one step.
struct Lane {
  std::array<std::vector<std::uint32_t>, 2 * kBlock> near;
  std::array<std::vector<FarEntry>, kFarBlocks> far;
  std::size_t far_entries = 0;  // in all block buckets, stale ones included
  std::vector<std::uint32_t> work;
  std::array<std::vector<std::uint32_t>, kLookahead + 1> lookahead;
  WallTally tally;
  Vec3 kick = Vec3::Zero();
  std::int64_t checks = 0;
  std::array<std::int32_t, 256> in_frame{};
#ifdef __EMSCRIPTEN__
  double touched = 0;  // keeps the browser build's early loads (check_lane) from being dropped
#endif                 // how many of the lane's particles rely on each frame
};

/// What every check of one step reads: the flow and the shared offset at its start and end.
struct StepData {
  Flow f0, f1;
  Vec3 o0, o0v, o1;
  double R2;
  double determinant;  ///< c^2 - dc s of f0, 1 up to rounding
};

/// Flow values and the predicted shared offset at the end of the next few steps.
struct Ahead {
  double c, s;
  Vec3 offset;
};

// [SECTION] Engine

class FastEngine final : public Engine {
 public:
  FastEngine(System initial, const EngineConfig& config) : config_(config) {
    if (!fast_engine_applies(config))
      throw std::invalid_argument("the fast engine runs the analytic method with paper collisions");
    if (initial.particles.size() > kMaxFastEngineParticles)
      throw std::invalid_argument("the fast engine takes at most 2^26 particles");
    J_ = initial.J;
    t_ = initial.t;
    M_ = total_mass(initial);
    k_ = J_ * M_;
    two_rate_ = 2 * std::sqrt(std::abs(k_));
    spring_ = {k_, k_ != 0 ? 1 / std::sqrt(std::abs(k_)) : 0.0};
    phase_rate_ = k_ != 0 ? two_rate_ : 1.0;
    R_cm_ = cm_position(initial);
    V_cm_ = cm_velocity(initial);
    orbits_.resize(initial.particles.size());
    for (std::size_t i = 0; i < orbits_.size(); ++i) {
      const Particle& p = initial.particles[i];
      orbits_[i] = {p.r - R_cm_, p.v - V_cm_, p.m, kParked, {kUnknown, kUnknown}};
    }
    frame_of_.assign(orbits_.size(), 0);
    lane_split_ = orbits_.size() / 2;

    cache_ = std::move(initial);
    cache_valid_ = true;
    start_epoch();
    start_frame();
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
      schedule_all_pending_ = true;
    }
    StepData& d = now_;
    // The flow at the step's end; at its start it is the last step's end, unless a re-base
    // restarted the epoch's time since.
    const Flow last_end = d.f1;
    d.f1 = Flow::over(k_, tau_ + dt);
    // For J >= 0 a new frame comes with a re-base, which also renews the margin's statistics.
    // For J < 0 the frames are renewed without one, but Y, which the kicks make grow like
    // exp(Omega tau), must stay small: measured on the fireball, letting |Y| reach 0.02 R
    // instead of 0.005 R makes the energy drift 40 times larger.
    const bool rebased = epoch_too_old(dt) ||
                         (k_ >= 0 ? frame_offset(current_, d.f1, dt).norm() > current_.renew_level
                                  : (d.f1.c * aY_ + d.f1.s * bY_).norm() >
                                        kMaxRepulsiveY * *config_.container_radius);
    if (rebased) {
      rebase();
      d.f1 = Flow::over(k_, tau_ + dt);
    }
    d.f0 = rebased || !flow_carried_ ? Flow::over(k_, tau_) : last_end;
    flow_carried_ = true;
    fill_ahead(d.f1);
    if (schedule_all_pending_)
      schedule_all();
    else if (k_ < 0 && (step_ - current_.start >= kRepulsiveFrameSteps ||
                        frame_offset(current_, d.f1, dt).norm() > current_.renew_level))
      next_frame();
    redo_lookahead_if_kicks_too_large();

    d.o0 = offset_at(d.f0, 0);
    d.o0v = offset_velocity_at(d.f0);
    d.o1 = offset_at(d.f1, dt);
    d.R2 = *config_.container_radius * *config_.container_radius;
    d.determinant = d.f0.c * d.f0.c - d.f0.dc() * d.f0.s;
    expire_frames(d.f1, dt);

    std::size_t pending = 0;
    for (const Lane& lane : lanes_) pending += lane.near[near_slot(step_)].size();
    if (on_both_lanes([this](int lane) { check_lane(lanes_[lane]); }, pending >= kParallelChecks))
      ++stats_.parallel_steps;
    Vec3 kick = Vec3::Zero();  // sum of m dv / M: the change of V_cm (and of Y')
    for (const Lane& lane : lanes_) {
      tally.add(lane.tally);
      kick += lane.kick;
      stats_.checks += lane.checks;
    }
    stats_.hits += tally.hits;
    finish_step(d.f0, kick, dt, d.determinant);
    return tally;
  }

  ~FastEngine() override { stop_worker(); }

  const System& system() override {
    if (!cache_valid_) {
      const Flow f = Flow::over(k_, tau_);
      const Vec3 o = offset_at(f, 0), ov = offset_velocity_at(f);
      cache_.J = J_;
      cache_.t = t_;
      cache_.particles.resize(orbits_.size());
      on_both_lanes([&](int lane) {
        for (std::size_t i = lane_begin(lane); i < lane_end(lane); ++i) {
          const Body& b = orbits_[i];
          Particle& p = cache_.particles[i];
          p.m = b.m;
          p.r = f.c * b.a + f.s * b.b + o;
          p.v = f.dc() * b.a + f.c * b.b + ov;
        }
      });
      cache_valid_ = true;
    }
    return cache_;
  }

  double time() const override { return t_; }

  void set_container_radius(std::optional<double> R) override {
    config_.container_radius = R;
    // A new wall invalidates every schedule; start from a fresh frame sized for it.
    rebase_pending_ = true;
    schedule_all_pending_ = true;
  }

  std::optional<double> container_radius() const override { return config_.container_radius; }
  const EngineConfig& config() const override { return config_; }
  const FastEngineStats& stats() const { return stats_; }

 private:
  // [SECTION] Shared motion

  // [SECTION] Checks

  /// Appendix A for one lane: the particles predicted outside at t + dt and moving outward
  /// now are reflected now. Their predictions all use the state before any of this step's
  /// hits, so the lanes are independent.
  void check_lane(Lane& lane) {
    const StepData& d = now_;
    lane.tally = WallTally{};
    lane.kick = Vec3::Zero();
    lane.checks = 0;
    if ((step_ & (kBlock - 1)) == 0) bring_near(lane, step_ / kBlock + 1);
    lane.work.swap(lane.near[near_slot(step_)]);
    const std::size_t count = lane.work.size();
#ifdef __EMSCRIPTEN__
    // WebAssembly has no prefetch instruction. Loads of every body due in this step, issued
    // together and independent of each other, overlap their cache misses in the same way
    // (at N = 1,000,000 this made the browser build's steps about twice as fast).
    double touched = 0;
    for (std::size_t j = 0; j < count; ++j) {
      const Body& o = orbits_[lane.work[j]];
      touched += o.a.x() + o.window.second;  // the first and the last cache line of the body
    }
    lane.touched = touched;
#endif
    for (std::size_t j = 0; j < std::min(count, kPrefetch); ++j) prefetch(&orbits_[lane.work[j]]);
    for (std::size_t j = 0; j < count; ++j) {
      if (j + kPrefetch < count) prefetch(&orbits_[lane.work[j + kPrefetch]]);
      const std::uint32_t i = lane.work[j];
      Body& o = orbits_[i];
      if (o.due != step_) continue;  // rescheduled since it was put here
      ++lane.checks;
      const Vec3 r1 = d.f1.c * o.a + d.f1.s * o.b + d.o1;
      if (r1.squaredNorm() > d.R2) {
        const Vec3 r0 = d.f0.c * o.a + d.f0.s * o.b + d.o0;
        const Vec3 v0 = d.f0.dc() * o.a + d.f0.c * o.b + d.o0v;
        if (v0.dot(r0) > 0) {
          const Vec3 dv = wall_reflection(o.m, r0, v0, lane.tally);
          // y_i's velocity jumps by dv at tau_: in coefficients, the inverse flow of dv. The
          // flow's determinant c^2 + k s^2 is 1 only up to rounding, which for J < 0 (cosh^2 -
          // sinh^2) is a bias of its own: dividing by its computed value keeps the evaluated
          // velocity jump dv, and the energy, unbiased.
          const Vec3 jump = dv / d.determinant;
          o.a -= d.f0.s * jump;
          o.b += d.f0.c * jump;
          o.window.first = kUnknown;
          lane.kick += (o.m / M_) * dv;
        }
      }
      schedule(i, step_ + 1);
    }
    lane.work.clear();
    release_if_large(lane.work);
  }

  // [SECTION] The second thread

  /// Runs task(0) and task(1), on two threads when parallel and possible (lane 1 on the
  /// worker). Says whether it used two.
  template <class Task>
  bool on_both_lanes(Task&& task, bool parallel = true) {
    if (parallel && start_worker()) {
#ifndef __EMSCRIPTEN__
      worker_task_ = [&task](int lane) { task(lane); };
#endif
      run_on_worker();
      task(0);
      // Whichever thread claims lane 1 first runs it: a worker that is slow to wake (or whose
      // core the host has taken away) then costs one thread's time, not a wait.
      if (claim_current())
        task(1);
      else
        wait_for_worker();
      return true;
    }
    task(0);
    task(1);
    return false;
  }

  /// The particles of lane `lane`: [begin, end).
  std::size_t lane_begin(int lane) const { return lane == 0 ? 0 : lane_split_; }
  std::size_t lane_end(int lane) const { return lane == 0 ? lane_split_ : orbits_.size(); }

#ifndef __EMSCRIPTEN__
  bool start_worker() {
    if (thread_limit() < 2) return false;
    if (worker_.joinable()) return true;
    worker_ = std::thread([this] { worker_loop(); });
    return true;
  }

  void worker_loop() {
    std::uint64_t seen = 0;
    for (;;) {
      wait_until([&] { return go_.load(std::memory_order_acquire) != seen; });
      seen = go_.load(std::memory_order_acquire);
      if (stop_.load(std::memory_order_acquire)) return;
      if (!claim(seen)) continue;
      worker_task_(1);
      done_.store(seen, std::memory_order_release);
      std::lock_guard<std::mutex> lock(mutex_);
      cv_.notify_all();
    }
  }

  /// Spins a little (first busily: the other thread's half of a step takes microseconds),
  /// then yielding the core, then sleeps until ready().
  template <class Ready>
  void wait_until(Ready ready) {
    for (int i = 0; i < kBusySpins && !ready(); ++i) cpu_relax();
    for (int i = 0; i < kSpins && !ready(); ++i) std::this_thread::yield();
    if (!ready()) {
      std::unique_lock<std::mutex> lock(mutex_);
      cv_.wait(lock, ready);
    }
  }

  void run_on_worker() {
    go_.store(++generation_, std::memory_order_release);
    std::lock_guard<std::mutex> lock(mutex_);
    cv_.notify_all();
  }

  /// Claims lane 1 of task generation g for the calling thread. Each generation is claimed
  /// exactly once, before the next starts, so the claims go 1, 2, 3, ...
  bool claim(std::uint64_t g) {
    std::uint64_t expected = g - 1;
    return claimed_.compare_exchange_strong(expected, g, std::memory_order_acq_rel);
  }

  bool claim_current() { return claim(generation_); }

  void wait_for_worker() {
    wait_until([&] { return done_.load(std::memory_order_acquire) == generation_; });
  }

  void stop_worker() {
    if (!worker_.joinable()) return;
    stop_.store(true, std::memory_order_release);
    run_on_worker();
    worker_.join();
  }
#else
  bool start_worker() { return false; }
  void run_on_worker() {}
  void wait_for_worker() {}
  bool claim_current() { return true; }
  void stop_worker() {}
#endif

  // [SECTION] Buckets

  static std::size_t near_slot(StepIndex s) { return std::size_t(s & (2 * kBlock - 1)); }
  static std::size_t far_slot(StepIndex block) { return std::size_t(block % kFarBlocks); }
  Lane& lane_of(std::uint32_t i) { return lanes_[i < lane_split_ ? 0 : 1]; }

  /// Puts particle i, due in step `due` (step_ <= due <= step_ + kHorizon), in its bucket.
  void enqueue(std::uint32_t i, StepIndex due) {
    Lane& lane = lane_of(i);
    if (due / kBlock <= step_ / kBlock + 1)
      lane.near[near_slot(due)].push_back(i);
    else {
      lane.far[far_slot(due / kBlock)].push_back(far_entry(i, due));
      // Particles rescheduled before their step leave stale entries; weed them out before
      // they cost memory (frames expire often when J < 0).
      if (++lane.far_entries > lane_split_ + lane_split_ / 2 + 4096) compact(lane);
    }
  }

  /// Moves the particles due in `block` from its block bucket to the step buckets. Those
  /// rescheduled since are weeded out when their step comes.
  void bring_near(Lane& lane, StepIndex block) {
    auto& bucket = lane.far[far_slot(block)];
    const StepIndex first = block * kBlock;
    for (const FarEntry e : bucket)
      lane.near[near_slot(first + StepIndex(e & (kBlock - 1)))].push_back(e >> kBlockBits);
    lane.far_entries -= bucket.size();
    bucket.clear();
    release_if_large(bucket);
  }

  /// Frees an emptied bucket that once held far more than its share: bursts (a new wall, an
  /// expired frame) would otherwise leave every bucket holding memory for a large part of N.
  template <class Bucket>
  void release_if_large(Bucket& bucket) const {
    if (bucket.capacity() > lane_split_ / 16 + 4096) Bucket().swap(bucket);
  }

  /// Drops the stale entries of every block bucket of lane.
  void compact(Lane& lane) {
    lane.far_entries = 0;
    for (std::size_t b = 0; b < lane.far.size(); ++b) {
      auto& bucket = lane.far[b];
      bucket.erase(std::remove_if(bucket.begin(), bucket.end(),
                                  [&](FarEntry e) {
                                    const StepIndex due = orbits_[e >> kBlockBits].due;
                                    return due == kParked || far_slot(due / kBlock) != b ||
                                           far_entry(e >> kBlockBits, due) != e;
                                  }),
                   bucket.end());
      lane.far_entries += bucket.size();
      if (bucket.capacity() > 2 * bucket.size() + 4096) bucket.shrink_to_fit();
    }
  }

  /// The shared offset o = R_cm - Y at tau_ + dt_ahead, f being the flow at that time:
  /// r_i = y_i + o. R_cm moves uniformly; Y = sum m_i y_i / M = c aY + s bY.
  Vec3 offset_at(const Flow& f, double dt_ahead) const {
    return R_cm_ + V_cm_ * dt_ahead - (f.c * aY_ + f.s * bY_);
  }
  Vec3 offset_velocity_at(const Flow& f) const { return V_cm_ - (f.dc() * aY_ + f.c * bY_); }
  Vec3 frame_offset(const Frame& fr, const Flow& f, double dt_ahead) const {
    return offset_at(f, dt_ahead) + f.c * fr.p + f.s * fr.q;
  }

  /// R_cm and Y take the same velocity kick at tau_, so o keeps its position and velocity.
  /// Y's coefficients change exactly as the sum of the y_i's do, i.e. by the kick divided by
  /// the flow's computed determinant (see check_lane), so that R_cm stays the particles' CM.
  void finish_step(const Flow& f0, const Vec3& kick, double dt, double determinant = 1) {
    V_cm_ += kick;
    const Vec3 jump = kick / determinant;
    aY_ -= f0.s * jump;
    bY_ += f0.c * jump;
    R_cm_ += V_cm_ * dt;
    recent_kicks_[std::size_t(step_) % recent_kicks_.size()] = kick.norm();
    tau_ += dt;
    t_ += dt;
    ++step_;
  }

  double rate() const { return 0.5 * two_rate_; }

  // [SECTION] Epochs and frames

  bool epoch_too_old(double dt) const {
    if (rebase_pending_) return true;
    if (k_ > 0) return rate() * (tau_ + dt) > kMaxAttractivePhase;
    if (k_ < 0) return rate() * (tau_ + dt) > kMaxRepulsivePhase;
    return tau_ + dt > kMaxFreeSteps * dt;
  }

  /// A re-base's change of every y_i: to the oscillation about the CM from now on.
  struct Shift {
    Flow f;       ///< at the re-base
    Vec3 Y, Yv;   ///< Y and its velocity then
    bool forget;  ///< also drop every window (the schedules are being rebuilt)
  };

  /// Starts a new epoch at the current time, in one pass over the particles: applies a
  /// re-base's shift if there is one, recomputes Y from the y_i (it is zero up to rounding
  /// right after a re-base) and, for J > 0, tallies how far short of the wall each particle's
  /// largest |y| falls, for the next frame's margin.
  void start_epoch(const Shift* shift = nullptr) {
    const double Rw = config_.container_radius.value_or(0.0);
    const double reach = std::max(Rw - R_cm_.norm(), 1e-300);
    const double bins_per_length = kGapBins / (0.5 * std::max(Rw, 1e-300));
    const double inv_rate = spring_.inv_rate;
    const bool histogram = k_ > 0 && Rw > 0;
    // Per-lane sums, combined in lane order: the rounding does not depend on the threads.
    std::array<Vec3, kLanes> sum_a, sum_b;
    std::array<std::array<std::size_t, kGapBins>, kLanes> counts{};
    on_both_lanes([&](int lane) {
      Vec3 sa = Vec3::Zero(), sb = Vec3::Zero();
      auto& count = counts[std::size_t(lane)];
      for (std::size_t i = lane_begin(lane); i < lane_end(lane); ++i) {
        Body& o = orbits_[i];
        if (shift) {
          const Flow& f = shift->f;
          const Vec3 y = f.c * o.a + f.s * o.b - shift->Y;
          const Vec3 yv = f.dc() * o.a + f.c * o.b - shift->Yv;
          o.a = y;
          o.b = yv;
          // Dropped schedules are rebuilt from scratch: frame ids are 8 bits and wrap, so
          // after 256 re-bases without a wall an old window could pass for a current one.
          if (shift->forget) o.window.first = kUnknown;
        }
        sa += o.m * o.a;
        sb += o.m * o.b;
        if (!histogram) continue;
        // (reach^2 - max |y|^2) / (2 reach) is at most the gap, which errs on the safe side.
        const fast::Swing swing = fast::swing_of(o.a, o.b, inv_rate);
        const double max_y2 = swing.P + swing.A;
        const double gap = (reach * reach - max_y2) / (2 * reach);
        count[std::size_t(std::clamp(gap * bins_per_length, 0.0, kGapBins - 1.0))]++;
      }
      sum_a[std::size_t(lane)] = sa;
      sum_b[std::size_t(lane)] = sb;
    });
    gap_histogram_.fill(0);
    for (const auto& count : counts)
      for (int b = 0; b < kGapBins; ++b) gap_histogram_[std::size_t(b)] += count[std::size_t(b)];
    aY_ = (sum_a[0] + sum_a[1]) / M_;
    bY_ = (sum_b[0] + sum_b[1]) / M_;
    epoch_start_ += tau_;
    tau_ = 0;
  }

  /// A new current frame. Its margin covers the CM's distance from the centre now, the drift
  /// of the CM over a few time units, and, when few particles can come near the wall (the
  /// attractive expansion's later stages), as much more as leaves at most N / kShellBudget
  /// of them within reach: a wide margin then costs little and lets the frame live long.
  void start_frame() {
    const double Rw = config_.container_radius.value_or(1.0);
    Frame next;
    next.id = next_frame_id_++;
    next.start = step_;
    next.p = aY_;
    next.q = bY_;
    const double base = frame_offset(next, Flow::over(k_, tau_), 0).norm();
    double extra = kMarginFloor * Rw;
    if (k_ != 0) extra = std::max(extra, kMarginDriftTimes * V_cm_.norm() / rate());
    if (k_ > 0) {
      const std::size_t budget = std::max<std::size_t>(64, orbits_.size() / kShellBudget);
      std::size_t within = 0;
      int bin = 0;
      while (bin < kGapBins && within + gap_histogram_[bin] <= budget)
        within += gap_histogram_[bin++];
      extra = std::max(extra, 0.5 * Rw * bin / kGapBins);
    }
    extra = std::min(extra, 0.5 * Rw);
    next.margin = base + extra;
    next.threshold = Rw - next.margin;
    next.threshold2 = next.threshold * next.threshold;
    next.renew_level = base + 0.5 * extra;
    current_ = next;
  }

  /// A new current frame without a re-base (J < 0): O(1).
  void next_frame() {
    old_frames_.push_back(current_);
    start_frame();
  }

  /// Folds Y into every y_i (O(N)) so that y_i is again the oscillation about the CM, and
  /// starts a new frame; the old one stays valid while its own offset stays within its margin.
  void rebase() {
    ++stats_.rebases;
    rebase_pending_ = false;
    const Flow f = Flow::over(k_, tau_);
    const Vec3 Y = f.c * aY_ + f.s * bY_, Yv = f.dc() * aY_ + f.c * bY_;
    const bool keep_schedules = config_.container_radius && !schedule_all_pending_;
    const Shift shift{f, Y, Yv, !keep_schedules};
    if (keep_schedules) {
      // Every y_i moved by the free flow of (-Y, -Y'): the frames' p, q move with them.
      old_frames_.push_back(current_);
      for (Frame& fr : old_frames_) {
        const Vec3 p = f.c * fr.p + f.s * fr.q - Y;
        const Vec3 q = f.dc() * fr.p + f.c * fr.q - Yv;
        fr.p = p;
        fr.q = q;
      }
    } else {
      old_frames_.clear();
      schedule_all_pending_ = true;
    }
    start_epoch(&shift);
    start_frame();
  }

  /// Drops the old frames no particle relies on any more, and expires those whose offset
  /// leaves their margin at the end of this step (and the oldest, beyond kMaxOldFrames).
  void expire_frames(const Flow& f1, double dt) {
    for (std::size_t j = 0; j < old_frames_.size();) {
      const Frame& fr = old_frames_[j];
      std::int64_t relying = 0;
      for (const Lane& lane : lanes_) relying += lane.in_frame[fr.id];
      const bool too_many = j == 0 && old_frames_.size() > std::size_t(kMaxOldFrames);
      if (relying == 0 || too_many ||
          frame_offset(fr, f1, dt).squaredNorm() > fr.margin * fr.margin) {
        if (relying > 0) expire(fr.id);
        old_frames_.erase(old_frames_.begin() + long(j));
      } else {
        ++j;
      }
    }
  }

  /// Reschedules, in the current frame, every particle still scheduled in frame id.
  void expire(std::uint8_t id) {
    std::array<std::int64_t, kLanes> expired{};
    on_both_lanes([&](int lane) {
      for (std::size_t i = lane_begin(lane); i < lane_end(lane); ++i)
        if (frame_of_[i] == id) {
          ++expired[std::size_t(lane)];
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
      for (auto& bucket : lane.near) bucket.clear();
      for (auto& bucket : lane.far) bucket.clear();
      lane.far_entries = 0;
      for (auto& list : lane.lookahead) list.clear();
      lane.in_frame.fill(0);
    }
    // With the old frames gone, no window may rely on one: every particle gets a window in
    // the current frame.
    old_frames_.clear();
    std::fill(frame_of_.begin(), frame_of_.end(), current_.id);
    for (int lane = 0; lane < kLanes; ++lane)
      lanes_[std::size_t(lane)].in_frame[current_.id] =
          std::int32_t(lane_end(lane) - lane_begin(lane));
    on_both_lanes([&](int lane) {
      for (std::size_t i = lane_begin(lane); i < lane_end(lane); ++i) {
        orbits_[i].window.first = kUnknown;
        schedule(std::uint32_t(i), step_);
      }
    });
  }

  // [SECTION] Scheduling

  /// The flow and the predicted offset at the ends of steps step_ .. step_ + kLookahead, from
  /// the state before this step's hits.
  void fill_ahead(const Flow& step_end) {
    if (dt_ != ahead_dt_) {
      // How far the offset at those step ends can move away from the prediction, given the
      // kick budget: each kick kappa moves it by kappa (u - s(u)), u the time since the kick.
      ahead_dt_ = dt_;
      step_flow_ = Flow::over(k_, dt_);
      steps_per_phase_ = 1 / (phase_rate_ * dt_);
      const double u = (kLookahead + 1) * dt_;
      kick_drift_ = std::abs(u - Flow::over(k_, u).s);
    }
    const Flow& step_flow = step_flow_;
    Flow f = step_end;
    for (int j = 0; j <= kLookahead; ++j) {
      ahead_[j] = {f.c, f.s, offset_at(f, (j + 1) * dt_)};
      // c(tau + dt) = c c_dt - k s s_dt, s(tau + dt) = s c_dt + c s_dt (addition theorems).
      const double c = f.c * step_flow.c - k_ * f.s * step_flow.s;
      const double s = f.s * step_flow.c + f.c * step_flow.s;
      f.c = c;
      f.s = s;
    }
    const double Rw = *config_.container_radius;
    const double slack = kKickBudget * rate() * Rw * kick_drift_ + 1e-12 * Rw;
    lookahead_limit2_ = (Rw - slack) * (Rw - slack);
  }

  /// Puts particle i in the bucket of the first step >= first (step_ or step_ + 1) in which
  /// it can hit the wall, as far as the schedule can tell.
  void schedule(std::uint32_t i, StepIndex first) {
    Body& o = orbits_[i];
    // A particle keeps its window, and with it the frame it relies on, until it hits the wall
    // or that frame expires: re-bases and new frames leave the window as it was.
    if (std::isnan(o.window.first)) {
      if (frame_of_[i] != current_.id) move_to_current_frame(i);
      o.window = current_.threshold > 0
                     ? fast::window_of(o.a - current_.p, o.b - current_.q, spring_,
                                       current_.threshold2, phase_rate_ * epoch_start_)
                     : fast::always_window(k_);
    }
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
      o.due = kParked;  // until its frame expires
      return;
    }
    due = std::min(due, step_ + kHorizon);
    o.due = due;
    enqueue(i, due);
  }

  /// The time at the end of step m, as the windows count it.
  fast::Clock clock_at(StepIndex m) const {
    return {k_, phase_rate_, steps_per_phase_, epoch_start_ + tau_ + double(m - step_ + 1) * dt_};
  }

  /// The first step >= first at whose end |y| can be >= T (the frame's wall threshold), or
  /// kParked; span is the window seen from the end of step `first`.
  static StepIndex window_begin(const fast::Span& span, StepIndex first) {
    if (span.begin == std::numeric_limits<double>::infinity()) return kParked;
    // A thousandth of a step covers the rounding of the closed forms.
    return first + StepIndex(std::clamp(std::floor(span.begin - 1e-3), 0.0, double(kHorizon)));
  }

  /// The first step from `from` to `last` (at most step_ + kLookahead) whose predicted end
  /// position can be outside the wall, or last + 1. Recorded, in case the kicks exceed the
  /// budget the prediction relies on.
  StepIndex look_ahead(const Body& o, StepIndex from, StepIndex last) {
    const double limit = lookahead_limit2_;
    StepIndex due = last + 1;
    for (StepIndex m = from; m <= last; ++m) {
      const Ahead& x = ahead_[m - step_];
      if ((x.c * o.a + x.s * o.b + x.offset).squaredNorm() >= limit) {
        due = m;
        break;
      }
    }
    if (due > from) {
      const auto i = std::uint32_t(&o - orbits_.data());
      lane_of(i).lookahead[std::size_t(step_) % (kLookahead + 1)].push_back(i);
    }
    return due;
  }

  /// The lookahead of the last kLookahead + 1 steps relied on their kicks staying within
  /// budget. If they did not, every particle it skipped ahead is rescheduled without it.
  void redo_lookahead_if_kicks_too_large() {
    double sum = 0;
    for (double kick : recent_kicks_) sum += kick;
    if (k_ == 0 || sum <= kKickBudget * rate() * *config_.container_radius) {
      // The schedules made kLookahead + 1 steps ago no longer rely on anything unchecked.
      for (Lane& lane : lanes_) lane.lookahead[std::size_t(step_) % (kLookahead + 1)].clear();
      return;
    }
    ++stats_.lookahead_redone;
    std::vector<std::uint32_t> ids;
    for (Lane& lane : lanes_)
      for (auto& list : lane.lookahead) {
        ids.insert(ids.end(), list.begin(), list.end());
        list.clear();
      }
    for (const std::uint32_t i : ids)
      if (orbits_[i].due != kParked && orbits_[i].due >= step_) schedule_plain(i);
    recent_kicks_.fill(0);
  }

  /// schedule(i, step_) without the lookahead.
  void schedule_plain(std::uint32_t i) {
    Body& o = orbits_[i];
    o.due = step_;
    enqueue(i, step_);
  }

  void move_to_current_frame(std::uint32_t i) {
    auto& in_frame = lane_of(i).in_frame;
    --in_frame[frame_of_[i]];
    ++in_frame[current_.id];
    frame_of_[i] = current_.id;
  }

  EngineConfig config_;
  double J_ = 0, M_ = 0, k_ = 0, t_ = 0;
  double two_rate_ = 0;  // 2 sqrt|k|
  fast::Spring spring_;
  std::vector<Body> orbits_;
  std::vector<std::uint8_t> frame_of_;  // the frame each schedule relies on; scanned on expiry

  // Shared motion, in the current epoch (tau_ is the time since it began).
  double tau_ = 0;
  double epoch_start_ = 0;  // when the current epoch began, in time counted from the first
  Vec3 R_cm_ = Vec3::Zero(), V_cm_ = Vec3::Zero();  // at the current time
  Vec3 aY_ = Vec3::Zero(), bY_ = Vec3::Zero();      // Y(tau) = c aY + s bY

  // The schedule.
  StepIndex step_ = 0;
  double dt_ = 0;
  std::array<Lane, kLanes> lanes_;
  std::size_t lane_split_ = 0;  // particles below it are in lane 0
  StepData now_{};
  bool flow_carried_ = false;  // now_.f1 holds the flow at tau_
  Frame current_;
  std::vector<Frame> old_frames_;
  std::uint8_t next_frame_id_ = 0;
  bool schedule_all_pending_ = true, rebase_pending_ = false;
  std::array<Ahead, kLookahead + 1> ahead_{};
  double lookahead_limit2_ = 0;  // (R - slack)^2: the kicks within budget move |r| less than slack
  double ahead_dt_ = 0, kick_drift_ = 0;
  double phase_rate_ = 1, steps_per_phase_ = 0;  // the windows' phase per time, steps per phase
  Flow step_flow_;
  std::array<double, kLookahead + 1> recent_kicks_{};
  // How many particles' largest |y| (J > 0) falls short of the reach R - |R_cm| by
  // 0.5 R bin / kGapBins.
  std::array<std::size_t, kGapBins> gap_histogram_{};

  System cache_;
  bool cache_valid_ = false;
  FastEngineStats stats_;

#ifndef __EMSCRIPTEN__
  std::thread worker_;
  std::atomic<std::uint64_t> go_{0}, done_{0}, claimed_{0};
  std::atomic<bool> stop_{false};
  std::uint64_t generation_ = 0;
  std::function<void(int)> worker_task_;
  std::mutex mutex_;
  std::condition_variable cv_;
#endif
};

}  // namespace

namespace {
#ifndef __EMSCRIPTEN__
std::atomic<int> g_thread_limit{std::thread::hardware_concurrency() >= 2 ? 2 : 1};
#else
int g_thread_limit = 1;
#endif
}  // namespace

void set_thread_limit(int threads) {
#ifndef __EMSCRIPTEN__
  g_thread_limit = std::clamp(threads, 1, 2);
#else
  (void)threads;
#endif
}

int thread_limit() { return g_thread_limit; }

bool fast_engine_applies(const EngineConfig& config) {
  return config.method == Method::analytic && config.collisions == CollisionMode::paper;
}

std::unique_ptr<Engine> make_fast_engine(System initial, const EngineConfig& config) {
  return std::make_unique<FastEngine>(std::move(initial), config);
}

std::optional<FastEngineStats> fast_engine_stats(const Engine& engine) {
  if (const auto* fast = dynamic_cast<const FastEngine*>(&engine)) return fast->stats();
  return std::nullopt;
}

}  // namespace swarm
