#include "swarm/fast_engine.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "fast_engine_window.h"
#include "swarm/regime.h"

namespace swarm {
namespace {

using StepIndex = std::int64_t;
constexpr StepIndex kParked = std::numeric_limits<StepIndex>::max();
// Buckets for the next kRingSize steps; a particle due later is parked at the ring's far end
// and looked at again then.
constexpr StepIndex kRingSize = 4096;
constexpr int kMaxOldFrames = 6;
// A frame's margin, as a fraction of the container radius, at least.
constexpr double kMarginFloor = 0.004;
// Re-base before exp(Omega tau) eats more than a few bits of the h_i (J < 0), and before the
// phase omega tau or the drift b tau gets large enough to cost digits (J >= 0).
constexpr double kMaxRepulsivePhase = 2.5;
constexpr double kMaxAttractivePhase = 512;
constexpr double kMaxFreeSteps = 1024;

/// Particle i's free oscillator: h_i(tau) = c(tau) a + s(tau) b about the origin.
struct Orbit {
  Vec3 a, b;
  double m;
};

/// A choice of the h_i. Schedules made in it assume |g_frame| <= margin at every step end;
/// g_frame - g_current = c p + s q is a free oscillator in the current epoch's time.
struct Frame {
  std::uint8_t id = 0;
  double margin = 0;
  Vec3 p = Vec3::Zero(), q = Vec3::Zero();
};

class FastEngine final : public Engine {
 public:
  FastEngine(System initial, const EngineConfig& config) : config_(config) {
    if (!fast_engine_applies(config))
      throw std::invalid_argument("the fast engine runs the analytic method with paper collisions");
    J_ = initial.J;
    t_ = initial.t;
    M_ = total_mass(initial);
    k_ = J_ * M_;
    orbits_.resize(initial.particles.size());
    for (std::size_t i = 0; i < orbits_.size(); ++i) {
      const Particle& p = initial.particles[i];
      orbits_[i] = {p.r, p.v, p.m};
    }
    due_.assign(orbits_.size(), kParked);
    frame_of_.assign(orbits_.size(), 0);
    ring_.resize(kRingSize);
    cache_ = std::move(initial);
    cache_valid_ = true;
    start_epoch();
    current_ = {next_frame_id_++, fresh_margin(), Vec3::Zero(), Vec3::Zero()};
    schedule_all_pending_ = true;
  }

  WallTally step(double dt) override {
    WallTally tally;
    cache_valid_ = false;
    if (!config_.container_radius || orbits_.empty()) {
      if (epoch_too_old(dt)) rebase();
      R_cm_ += V_cm_ * dt;
      tau_ += dt;
      t_ += dt;
      ++step_;
      return tally;
    }
    if (dt != dt_) {
      dt_ = dt;
      schedule_all_pending_ = true;
    }
    const double Rw = *config_.container_radius;
    if (epoch_too_old(dt) || g_at(tau_ + dt, dt).norm() > 0.5 * current_.margin) rebase();
    if (schedule_all_pending_) schedule_all();

    const Flow f0 = Flow::over(k_, tau_), f1 = Flow::over(k_, tau_ + dt);
    const Vec3 g0 = g_at(f0, 0), g0v = g_velocity_at(f0), g1 = g_at(f1, dt);
    expire_violated_frames(f1, g1);

    // Appendix A: the particles predicted outside at t + dt and moving outward now are
    // reflected now. Their predictions all use the state before any of this step's hits.
    const double R2 = Rw * Rw;
    Vec3 kick = Vec3::Zero();  // sum of m dv / M: the change of V_cm (and of H')
    work_.swap(ring_[slot(step_)]);
    for (const std::uint32_t i : work_) {
      if (due_[i] != step_) continue;  // rescheduled since it was put here
      ++stats_.checks;
      Orbit& o = orbits_[i];
      const Vec3 r1 = f1.c * o.a + f1.s * o.b + g1;
      if (r1.squaredNorm() > R2) {
        const Vec3 r0 = f0.c * o.a + f0.s * o.b + g0;
        const Vec3 v0 = f0.dc() * o.a + f0.c * o.b + g0v;
        if (v0.dot(r0) > 0) {
          const Vec3 dv = reflect(o.m, r0, v0, tally);
          // The velocity of h_i jumps by dv at tau_: in coefficients, the inverse flow of dv.
          o.a -= f0.s * dv;
          o.b += f0.c * dv;
          kick += (o.m / M_) * dv;
        }
      }
      schedule(i, step_ + 1);
    }
    work_.clear();

    // R_cm and H take the same velocity kick, so g = R_cm - H keeps its position and velocity.
    V_cm_ += kick;
    aH_ -= f0.s * kick;
    bH_ += f0.c * kick;
    R_cm_ += V_cm_ * dt;
    tau_ += dt;
    t_ += dt;
    ++step_;
    stats_.hits += tally.hits;
    return tally;
  }

  const System& system() override {
    if (!cache_valid_) {
      const Flow f = Flow::over(k_, tau_);
      const Vec3 g = g_at(f, 0), gv = g_velocity_at(f);
      cache_.J = J_;
      cache_.t = t_;
      cache_.particles.resize(orbits_.size());
      for (std::size_t i = 0; i < orbits_.size(); ++i) {
        const Orbit& o = orbits_[i];
        Particle& p = cache_.particles[i];
        p.m = o.m;
        p.r = f.c * o.a + f.s * o.b + g;
        p.v = f.dc() * o.a + f.c * o.b + gv;
      }
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
  static std::size_t slot(StepIndex s) { return std::size_t(s & (kRingSize - 1)); }

  /// g = R_cm - H at tau_ + dt_ahead, where f is the flow at that time. R_cm moves uniformly.
  Vec3 g_at(const Flow& f, double dt_ahead) const {
    return R_cm_ + V_cm_ * dt_ahead - (f.c * aH_ + f.s * bH_);
  }
  Vec3 g_at(double tau, double dt_ahead) const { return g_at(Flow::over(k_, tau), dt_ahead); }
  Vec3 g_velocity_at(const Flow& f) const { return V_cm_ - (f.dc() * aH_ + f.c * bH_); }

  /// reflect_at_wall, returning the velocity change.
  static Vec3 reflect(double m, const Vec3& r, const Vec3& v, WallTally& tally) {
    const Vec3 n = r.normalized();
    const double v_r = v.dot(n);
    const Vec3 dv = -2 * v_r * n;
    tally.hits += 1;
    tally.radial_impulse += std::abs(2 * m * v_r);
    tally.hit_kinetic_energy += 0.5 * m * v.squaredNorm();
    tally.wall_momentum -= m * dv;
    return dv;
  }

  double rate() const { return std::sqrt(std::abs(k_)); }

  bool epoch_too_old(double dt) const {
    if (rebase_pending_) return true;
    if (k_ > 0) return rate() * (tau_ + dt) > kMaxAttractivePhase;
    if (k_ < 0) return rate() * (tau_ + dt) > kMaxRepulsivePhase;
    return tau_ + dt > kMaxFreeSteps * dt;
  }

  /// The margin of a new frame: g starts at zero and, from there, is driven by the CM's
  /// offset from the origin and its velocity. At least a small fraction of the wall radius.
  double fresh_margin() const {
    const double Rw = config_.container_radius.value_or(1.0);
    double m = kMarginFloor * Rw;
    if (k_ != 0) m = std::max(m, 2 * (R_cm_.norm() + V_cm_.norm() / rate()));
    return std::min(m, 0.5 * Rw);
  }

  /// Starts a new epoch at the current time with h_i = r_i, so g = 0: R_cm and V_cm are
  /// recomputed from the particles, as the reference engine does every step.
  void start_epoch() {
    Vec3 sum_r = Vec3::Zero(), sum_v = Vec3::Zero();
    for (const Orbit& o : orbits_) {
      sum_r += o.m * o.a;
      sum_v += o.m * o.b;
    }
    R_cm_ = aH_ = sum_r / M_;
    V_cm_ = bH_ = sum_v / M_;
    tau_ = 0;
  }

  /// Folds g into every h_i (O(N)) and starts a new frame; the old one stays valid while its
  /// own g stays within its margin.
  void rebase() {
    ++stats_.rebases;
    rebase_pending_ = false;
    const Flow f = Flow::over(k_, tau_);
    const Vec3 g = g_at(f, 0), gv = g_velocity_at(f);
    for (Orbit& o : orbits_) {
      const Vec3 r = f.c * o.a + f.s * o.b + g;
      const Vec3 v = f.dc() * o.a + f.c * o.b + gv;
      o.a = r;
      o.b = v;
    }
    const bool keep_schedules = config_.container_radius && !schedule_all_pending_;
    if (keep_schedules) {
      // Every h_i moved by the free flow of (g, g'): so did every old frame's offset.
      for (Frame& fr : old_frames_) {
        const Vec3 p = f.c * fr.p + f.s * fr.q + g;
        const Vec3 q = f.dc() * fr.p + f.c * fr.q + gv;
        fr.p = p;
        fr.q = q;
      }
      current_.p = g;
      current_.q = gv;
      old_frames_.push_back(current_);
    } else {
      old_frames_.clear();
      schedule_all_pending_ = true;
    }
    start_epoch();
    current_ = {next_frame_id_++, fresh_margin(), Vec3::Zero(), Vec3::Zero()};
    if (int(old_frames_.size()) > kMaxOldFrames) {
      expire(old_frames_.front().id);
      drop_frame(0);
    }
  }

  void drop_frame(std::size_t index) { old_frames_.erase(old_frames_.begin() + long(index)); }

  void expire_violated_frames(const Flow& f1, const Vec3& g1) {
    for (std::size_t j = 0; j < old_frames_.size();) {
      const Frame& fr = old_frames_[j];
      if ((g1 + f1.c * fr.p + f1.s * fr.q).norm() > fr.margin) {
        expire(fr.id);
        drop_frame(j);
      } else {
        ++j;
      }
    }
  }

  /// Reschedules, in the current frame, every particle still scheduled in frame id.
  void expire(std::uint8_t id) {
    for (std::size_t i = 0; i < orbits_.size(); ++i)
      if (frame_of_[i] == id) {
        ++stats_.expired;
        schedule(std::uint32_t(i), step_);
      }
  }

  void schedule_all() {
    ++stats_.reschedules;
    schedule_all_pending_ = false;
    for (auto& bucket : ring_) bucket.clear();
    old_frames_.clear();
    for (std::size_t i = 0; i < orbits_.size(); ++i) schedule(std::uint32_t(i), step_);
  }

  /// Puts particle i in the bucket of the first step >= first at whose end |h_i| can reach
  /// the wall minus the current frame's margin. Step s ends at tau_ + (s + 1 - step_) dt_.
  void schedule(std::uint32_t i, StepIndex first) {
    frame_of_[i] = current_.id;
    const double T = *config_.container_radius - current_.margin;
    StepIndex due = first;
    if (T > 0) {
      const Orbit& o = orbits_[i];
      const double tau_from = tau_ + double(first + 1 - step_) * dt_;
      const double entry = fast::window_entry(o.a, o.b, k_, tau_from, T * T);
      if (entry == std::numeric_limits<double>::infinity()) {
        due = kParked;
      } else {
        // One part in a million of a step covers the rounding of the closed forms.
        const double ahead = std::floor((entry - tau_from) / dt_ - 1e-6);
        due = first + StepIndex(std::clamp(ahead, 0.0, double(kRingSize)));
      }
    }
    due_[i] = due;
    if (due == kParked) return;  // until its frame expires
    due = std::min(due, step_ + kRingSize - 1);
    due_[i] = due;
    ring_[slot(due)].push_back(i);
  }

  EngineConfig config_;
  double J_ = 0, M_ = 0, k_ = 0, t_ = 0;
  std::vector<Orbit> orbits_;

  // Shared motion, in the current epoch (tau_ is the time since it began).
  double tau_ = 0;
  Vec3 R_cm_ = Vec3::Zero(), V_cm_ = Vec3::Zero();  // at the current time
  Vec3 aH_ = Vec3::Zero(), bH_ = Vec3::Zero();      // H(tau) = c aH + s bH

  // The schedule.
  StepIndex step_ = 0;
  double dt_ = 0;
  std::vector<StepIndex> due_;
  std::vector<std::uint8_t> frame_of_;
  std::vector<std::vector<std::uint32_t>> ring_;
  std::vector<std::uint32_t> work_;
  Frame current_;
  std::vector<Frame> old_frames_;
  std::uint8_t next_frame_id_ = 0;
  bool schedule_all_pending_ = true, rebase_pending_ = false;

  System cache_;
  bool cache_valid_ = false;
  FastEngineStats stats_;
};

}  // namespace

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
