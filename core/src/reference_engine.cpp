#include <cmath>
#include <stdexcept>

#include "swarm/engine.h"
#include "swarm/flow.h"
#include "swarm/integrators.h"
#include "swarm/regime.h"

namespace swarm {
namespace {

bool moving_outward(const Particle& p) { return p.v.dot(p.r) > 0; }

/// Appendix A with any trajectory map: the straightforward O(N) (analytic) or O(N^2)
/// (pairwise) reference against which faster engines are checked.
class ReferenceEngine final : public Engine {
 public:
  ReferenceEngine(System initial, const EngineConfig& config)
      : system_(std::move(initial)), config_(config) {
    if (config.collisions == CollisionMode::exact && config.method != Method::analytic)
      throw std::invalid_argument("exact collisions need the analytic method");
  }

  WallTally step(double dt) override {
    WallTally tally;
    if (!config_.container_radius) {
      swarm::step(config_.method, system_, dt, config_.threads);
    } else if (config_.collisions == CollisionMode::paper) {
      reflect_predicted_leavers(dt, tally);
      swarm::step(config_.method, system_, dt, config_.threads);
    } else {
      step_with_exact_hits(dt, tally);
    }
    return tally;
  }

  const System& system() override { return system_; }
  double time() const override { return system_.t; }
  void set_container_radius(std::optional<double> R) override { config_.container_radius = R; }
  std::optional<double> container_radius() const override { return config_.container_radius; }
  const EngineConfig& config() const override { return config_; }
  std::unique_ptr<Engine> clone() const override {
    return std::make_unique<ReferenceEngine>(*this);
  }

 private:
  /// Appendix A: a particle whose position at t + dt would lie outside the wall, and that is
  /// moving outward now, is reflected now, at its position at t. The summed impulses reach
  /// the centre-of-mass velocity because the step recomputes it from the particles.
  void reflect_predicted_leavers(double dt, WallTally& tally) {
    const double R2 = *config_.container_radius * *config_.container_radius;
    // The prediction is the method's own step, taken on a copy before anyone is reflected.
    System predicted = system_;
    swarm::step(config_.method, predicted, dt, config_.threads);
    for (std::size_t i = 0; i < system_.particles.size(); ++i) {
      auto& p = system_.particles[i];
      if (predicted.particles[i].r.squaredNorm() > R2 && moving_outward(p))
        reflect_at_wall(p, tally);
    }
  }

  /// Event by event: advance everyone to the earliest wall contact inside the step, reflect
  /// that particle there, and repeat with the changed centre-of-mass motion.
  void step_with_exact_hits(double dt, WallTally& tally) {
    const double Rw = *config_.container_radius;
    double left = dt;
    for (;;) {
      const Vec3 R = cm_position(system_);
      const Vec3 V = cm_velocity(system_);
      const double k = stiffness(system_);
      auto position_after = [&](const Particle& p, double tau) {
        const Flow f = Flow::over(k, tau);
        return Vec3(R + V * tau + f.c * (p.r - R) + f.s * (p.v - V));
      };
      double first = left;
      std::size_t who = system_.particles.size();
      for (std::size_t i = 0; i < system_.particles.size(); ++i) {
        const Particle& p = system_.particles[i];
        const bool outside_now = p.r.norm() >= Rw;
        if (outside_now) {
          if (moving_outward(p)) first = 0, who = i;
          continue;
        }
        if (position_after(p, left).norm() <= Rw) continue;  // grazing exits are missed
        double lo = 0, hi = left;                            // inside at lo, outside at hi
        for (int it = 0; it < 64 && hi - lo > 0; ++it) {
          const double mid = 0.5 * (lo + hi);
          (position_after(p, mid).norm() > Rw ? hi : lo) = mid;
        }
        if (hi < first) first = hi, who = i;
      }
      if (first > 0) step_analytic(system_, first);
      left -= first;
      if (who == system_.particles.size()) return;
      Particle& hit = system_.particles[who];
      if (moving_outward(hit)) reflect_at_wall(hit, tally);
      if (left <= 0) return;
    }
  }

  System system_;
  EngineConfig config_;
};

}  // namespace

std::unique_ptr<Engine> make_reference_engine(System initial, const EngineConfig& config) {
  return std::make_unique<ReferenceEngine>(std::move(initial), config);
}

}  // namespace swarm
