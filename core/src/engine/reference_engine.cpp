#include <cmath>
#include <stdexcept>

#include "swarm/engine/engine.h"
#include "swarm/methods/integrators.h"
#include "swarm/physics/flow.h"
#include "swarm/physics/hard_spheres.h"
#include "swarm/physics/regime.h"
#include "swarm/physics/thermal_wall.h"

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
    const bool appendix_b =
        !config.wall_moves.empty() || config.wall_temperature || config.sphere_radius;
    if (config.collisions == CollisionMode::exact && appendix_b)
      throw std::invalid_argument(
          "moving and thermal walls and hard spheres need paper collisions");
    if (!config.wall_moves.empty() && config.container_radius)
      path_.emplace(*config.container_radius, config.wall_moves);
    if (config.sphere_radius) spheres_.emplace(*config.sphere_radius);
  }

  WallTally step(double dt) override {
    WallTally tally;
    if (!config_.container_radius && !config_.floor) {
      move(system_, dt, tally);
    } else if (config_.collisions == CollisionMode::paper) {
      reflect_predicted_leavers(dt, tally);
      move(system_, dt, tally);
    } else {
      step_with_exact_hits(dt, tally);
    }
    if (config_.floor) rest_on_floor(system_, *config_.floor, config_.forces.gravity, tally);
    if (spheres_) spheres_->collide(system_.particles);
    ++steps_;
    return tally;
  }

  const System& system() override { return system_; }
  double time() const override { return system_.t; }
  void set_container_radius(std::optional<double> R) override {
    config_.container_radius = R;
    path_.reset();
  }
  std::optional<double> container_radius() const override { return config_.container_radius; }
  const EngineConfig& config() const override { return config_; }
  std::unique_ptr<Engine> clone() const override {
    return std::make_unique<ReferenceEngine>(*this);
  }

 private:
  /// The trajectory map over dt: the method's own step, or under gravity and drag the same
  /// step with them (the energy the drag takes goes into the tally's books).
  void move(System& s, double dt, WallTally& tally) const {
    if (!config_.forces.any())
      swarm::step(config_.method, s, dt, config_.threads);
    else
      tally.books.drag_loss += step_with_forces(config_.method, s, dt, config_.threads, config_.forces);
  }

  /// Appendix A: a particle whose position at t + dt would lie outside the wall, and that is
  /// moving outward now, is reflected now, at its position at t. The summed impulses reach
  /// the centre-of-mass velocity because the step recomputes it from the particles.
  ///
  /// A moving wall is checked at its radius at t + dt and moves at its mean velocity u over
  /// the step; a particle leaves when it moves outward relative to the wall. A hard sphere
  /// reaches the wall when its centre is at R - a.
  void reflect_predicted_leavers(double dt, WallTally& tally) {
    // The prediction is the method's own step, taken on a copy before anyone is reflected.
    System predicted = system_;
    if (config_.forces.any() && config_.method == Method::analytic) {
      step_analytic_forced(predicted, dt, config_.forces);  // the same map, without booking
    } else {
      WallTally unused;
      move(predicted, dt, unused);
    }
    if (config_.container_radius) {
      const double R_next = path_ ? path_->radius_at(system_.t + dt) : *config_.container_radius;
      const double u = path_ ? (R_next - *config_.container_radius) / dt : 0;
      const double reach = R_next - config_.sphere_radius.value_or(0.0);
      const double R2 = reach * reach;
      for (std::size_t i = 0; i < system_.particles.size(); ++i) {
        auto& p = system_.particles[i];
        if (!(predicted.particles[i].r.squaredNorm() > R2)) continue;
        if (config_.wall_temperature) {
          if (moving_outward(p))
            reemit_from_thermal_wall(p, *config_.wall_temperature,
                                     {steps_, i, config_.wall_stream}, tally);
        } else if (path_) {
          if (p.v.dot(p.r.normalized()) > u) reflect_off_moving_wall(p, u, tally);
        } else if (moving_outward(p)) {
          reflect_at_wall(p, tally);
        }
      }
      if (path_) config_.container_radius = R_next;
    }
    // The floor is a second wall, judged on the same prediction (after the sphere's reflection,
    // with the velocity the particle now has).
    if (config_.floor)
      for (std::size_t i = 0; i < system_.particles.size(); ++i) {
        auto& p = system_.particles[i];
        if (falling_through(*config_.floor, predicted.particles[i].r, p.v))
          bounce_on_floor(p, *config_.floor, tally);
      }
  }

  /// Event by event: advance everyone to the earliest wall (or floor) contact inside the step,
  /// reflect that particle there, and repeat with the changed centre-of-mass motion.
  void step_with_exact_hits(double dt, WallTally& tally) {
    const std::optional<double> Rw = config_.container_radius;
    const Floor* floor = config_.floor ? &*config_.floor : nullptr;
    const bool forced = config_.forces.any();
    const double gamma = config_.forces.drag ? config_.forces.drag->gamma : 0.0;
    const Vec3 g = config_.forces.gravity;
    auto outside = [&](const Vec3& r) {
      return (Rw && r.norm() > *Rw) || (floor && r.z() < floor->z);
    };
    double left = dt;
    for (;;) {
      const Vec3 R = cm_position(system_);
      const Vec3 V = cm_velocity(system_);
      const double k = stiffness(system_);
      auto position_after = [&](const Particle& p, double tau) {
        if (forced) {
          const ForcedFlow m = ForcedFlow::over(k, gamma, tau);
          return Vec3(R + m.cm_v * V + m.cm_g * g + m.xc * (p.r - R) + m.xs * (p.v - V));
        }
        const Flow f = Flow::over(k, tau);
        return Vec3(R + V * tau + f.c * (p.r - R) + f.s * (p.v - V));
      };
      double first = left;
      std::size_t who = system_.particles.size();
      bool who_at_floor = false;  // whether the earliest contact is with the floor
      for (std::size_t i = 0; i < system_.particles.size(); ++i) {
        const Particle& p = system_.particles[i];
        const bool at_wall = Rw && p.r.norm() >= *Rw;
        const bool at_floor = floor && p.r.z() <= floor->z;
        if (at_wall || at_floor) {
          if (at_floor && p.v.z() < 0)
            first = 0, who = i, who_at_floor = true;
          else if (at_wall && moving_outward(p))
            first = 0, who = i, who_at_floor = false;
          continue;
        }
        if (!outside(position_after(p, left))) continue;  // grazing exits are missed
        double lo = 0, hi = left;                          // inside at lo, outside at hi
        for (int it = 0; it < 64 && hi - lo > 0; ++it) {
          const double mid = 0.5 * (lo + hi);
          (outside(position_after(p, mid)) ? hi : lo) = mid;
        }
        if (hi < first)
          first = hi, who = i, who_at_floor = floor && position_after(p, hi).z() < floor->z;
      }
      if (first > 0) advance_exactly(first, tally);
      left -= first;
      if (who == system_.particles.size()) return;
      Particle& hit = system_.particles[who];
      if (who_at_floor) {
        if (hit.v.z() < 0) bounce_on_floor(hit, *floor, tally);
      } else if (moving_outward(hit)) {
        reflect_at_wall(hit, tally);
      }
      if (left <= 0) return;
    }
  }

  /// The exact map over tau, with the forces when there are any.
  void advance_exactly(double tau, WallTally& tally) {
    if (config_.forces.any())
      tally.books.drag_loss += step_with_forces(Method::analytic, system_, tau, 1, config_.forces);
    else
      step_analytic(system_, tau);
  }

  System system_;
  EngineConfig config_;
  std::optional<WallPath> path_;        ///< a moving wall's radius over time
  std::optional<HardSpheres> spheres_;  ///< contacts between the particles
  std::uint64_t steps_ = 0;             ///< steps taken: the thermal wall's draws are keyed on it
};

}  // namespace

std::unique_ptr<Engine> make_reference_engine(System initial, const EngineConfig& config) {
  return std::make_unique<ReferenceEngine>(std::move(initial), config);
}

}  // namespace swarm
