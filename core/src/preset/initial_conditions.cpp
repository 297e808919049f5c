#include "swarm/preset/initial_conditions.h"

#include <cmath>
#include <random>

#include "math/portable_math.h"

namespace swarm {
namespace {

// std::uniform_real_distribution and std::normal_distribution differ between standard
// libraries, so the native and WebAssembly builds would draw different swarms from one seed;
// libm's log and cos differ in the last bit between them too, hence portable_math.h.
class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  /// Uniform in [0, 1) with 53 random bits.
  double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  /// Standard normal by the Box-Muller transform.
  double normal() {
    const double u1 = 1.0 - uniform();  // in (0, 1], so the log is finite
    const double u2 = uniform();
    return std::sqrt(-2 * portable::log(u1)) * portable::cos(2 * M_PI * u2);
  }
  /// Three draws in a fixed order: the order in which function arguments are evaluated is
  /// unspecified (g++ and clang differ), so Vec3(draw(), draw(), draw()) is not reproducible.
  template <class Draw>
  static Vec3 triple(Draw draw) {
    const double x = draw();
    const double y = draw();
    const double z = draw();
    return {x, y, z};
  }
  /// Uniform in the ball of radius r, by rejection from the enclosing cube.
  Vec3 in_ball(double r) {
    for (;;) {
      const Vec3 p = triple([this] { return uniform(-1, 1); });
      if (p.squaredNorm() <= 1) return r * p;
    }
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace

System generate_swarm(const SwarmSpec& spec) {
  Random rng(spec.seed);
  System s;
  s.particles.resize(std::size_t(spec.count));
  for (auto& p : s.particles) p.m = rng.uniform(spec.mass_min, spec.mass_max);
  for (auto& p : s.particles) p.r = rng.in_ball(spec.position_radius);
  for (auto& p : s.particles) {
    if (spec.velocities == SwarmSpec::Velocities::ball) {
      p.v = rng.in_ball(spec.speed);
    } else {
      const double sigma = std::sqrt(spec.temperature / p.m);
      p.v = sigma * Random::triple([&rng] { return rng.normal(); });
    }
  }
  if (spec.cm_at_rest) {
    const Vec3 V = cm_velocity(s);
    for (auto& p : s.particles) p.v -= V;
  }
  return s;
}

}  // namespace swarm
