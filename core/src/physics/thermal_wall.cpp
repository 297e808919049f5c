#include "swarm/physics/thermal_wall.h"

#include <cmath>

#include "math/portable_math.h"
#include "math/splitmix.h"

namespace swarm {
namespace {

/// (0, 1]: the top 53 bits, plus one, over 2^53; never 0, so its log is finite.
double unit_interval(std::uint64_t bits) { return double((bits >> 11) + 1) * 0x1.0p-53; }

}  // namespace

void thermal_uniforms(const ThermalDraw& key, double u[3]) {
  // The finaliser maps stream 0 to 0: a run without a stream draws as before streams existed.
  const std::uint64_t base =
      splitmix64_mix(splitmix64(key.step) ^ key.particle ^ splitmix64_mix(key.stream));
  for (int i = 0; i < 3; ++i)
    u[i] = unit_interval(splitmix64_mix(base + std::uint64_t(i + 1) * kSplitmix64Gamma));
}

void reemit_from_thermal_wall(Particle& p, double Tw, const ThermalDraw& key, WallTally& tally) {
  p.v = thermal_reemission(p.m, p.r, p.v, Tw, key, tally);
}

Vec3 thermal_reemission(double m, const Vec3& r, const Vec3& v, double Tw, const ThermalDraw& key,
                        WallTally& tally) {
  const Vec3 n = r.normalized();
  const double v_r = v.dot(n);
  const double kinetic_before = 0.5 * m * v.squaredNorm();

  double u[3];
  thermal_uniforms(key, u);
  const double sigma = std::sqrt(Tw / m);
  // Rayleigh by inversion; the tangential pair by Box-Muller.
  const double v_n = sigma * std::sqrt(-2 * portable::log(u[0]));
  const double g = sigma * std::sqrt(-2 * portable::log(u[1]));
  double s = 0, c = 0;
  portable::sincos(2 * M_PI * u[2], &s, &c);
  // Two unit tangents: n x a with a the axis least aligned with n, then n x t1.
  const Vec3 a = std::abs(n.x()) < 0.5 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 t1 = n.cross(a).normalized();
  const Vec3 t2 = n.cross(t1);
  const Vec3 v_out = -v_n * n + g * c * t1 + g * s * t2;

  const Vec3 dv = v_out - v;
  tally.hits += 1;
  tally.radial_impulse += m * (std::abs(v_r) + v_n);
  tally.hit_kinetic_energy += kinetic_before;
  tally.wall_momentum -= m * dv;
  tally.books.wall_heat += 0.5 * m * v_out.squaredNorm() - kinetic_before;
  return v_out;
}

}  // namespace swarm
