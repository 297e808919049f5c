#include "preset/preset_numbers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

// The core's own exp and log, so that a preset at a limit is judged alike natively and in wasm.
#include "math/portable_math.h"

namespace swarm {
namespace {

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

/// Upper bounds on the particles at t = 0, from the list or from the generator's parameters.
struct Extent {
  double M = 0;      ///< total mass
  double r_max = 0;  ///< largest |r|
  double v_max = 0;  ///< largest |v|
  const char* field = "particles";
};

Extent extent_of(const Preset& p) {
  Extent e;
  if (const auto* list = std::get_if<std::vector<Particle>>(&p.particles)) {
    for (const Particle& q : *list) {
      e.M += q.m;
      e.r_max = std::max(e.r_max, q.r.norm());  // inf when |r|^2 overflows
      e.v_max = std::max(e.v_max, q.v.norm());
    }
    return e;
  }
  const SwarmSpec& s = std::get<SwarmSpec>(p.particles);
  e.M = double(s.count) * s.mass_max;
  e.r_max = s.position_radius;
  // Maxwellian components have variance T / m: 20 standard deviations bound 1e7 draws.
  e.v_max = s.velocities == SwarmSpec::Velocities::ball
                ? s.speed
                : 20 * std::sqrt(3 * s.temperature / s.mass_min);
  e.field = "particles.mass";
  return e;
}

/// Bound on the energies and on the intermediate sums behind them (sum m v^2, sum m r^2,
/// |J| M sum m r^2) for particles within r of the centre of mass moving at most v.
double energy_scale(double M, double k, double r, double v) {
  return M * v * v + (1 + std::abs(k)) * M * (2 * r) * (2 * r);
}

/// Largest |eigenvalue| of one step of method m on x'' = -k x (k = J M), h = sqrt|k| dt: the
/// factor by which the method can grow an amplitude each step. The analytic map's growth is
/// exp(Omega dt) for k < 0 and none otherwise (the caller handles it).
double amplification(Method m, double h, bool repulsive) {
  switch (m) {
    case Method::analytic:
      return repulsive ? portable::exp(h) : 1.0;
    case Method::euler:
      return repulsive ? 1 + h : std::sqrt(1 + h * h);
    case Method::euler_cromer:
    case Method::verlet: {  // both have the characteristic polynomial l^2 - b l + 1
      const double b = repulsive ? 2 + h * h : 2 - h * h;
      return std::abs(b) <= 2 ? 1.0 : (std::abs(b) + std::sqrt(b * b - 4)) / 2;
    }
    case Method::rk4: {
      if (repulsive) return 1 + h + h * h / 2 + h * h * h / 6 + h * h * h * h / 24;
      const double h2 = h * h, h6 = h2 * h2 * h2;
      return std::sqrt(std::max(1.0, 1 - h6 / 72 + h6 * h2 / 576));
    }
  }
  return portable::exp(h);
}

}  // namespace

std::string unrepresentable_numbers(const Preset& p) {
  const double ln_largest = portable::log(kLargestDerived);
  const Extent x = extent_of(p);
  if (!(x.M <= kLargestDerived))
    return std::string(x.field) + ": the total mass M = " + number(x.M) + " must stay <= 1e300";
  const double k = p.J * x.M;
  if (!(std::abs(k) <= kLargestDerived))
    return "J: J * M = " + number(k) + " must stay within +-1e300 (omega = sqrt(|J| M))";
  const double omega = std::sqrt(std::abs(k));
  const double S0 = energy_scale(x.M, k, x.r_max, x.v_max);
  if (!(S0 <= kLargestDerived))
    return "particles: the energies at t = 0 could reach " + number(S0) +
           " (masses, positions, speeds or J too large): they must stay <= 1e300";

  const long steps = step_count(p);
  const double T = double(steps) * p.dt;
  const bool repulsive = p.J < 0;

  // The container: its radius and volume over the whole expansion.
  double R_final = 0;
  if (p.container_radius) {
    const double R = *p.container_radius;
    if (R < kSmallestRadius)
      return "container.radius: must be >= 1e-100 (so that R^2 and the volume stay normal doubles)";
    if (R > kLargestRadius)
      return "container.radius: must be <= 1e100 (so that the volume 4/3 pi R^3 stays finite)";
    double ln_R_final = portable::log(R);
    if (p.expansion) ln_R_final += double(p.expansion->stages - 1) * portable::log(p.expansion->factor);
    if (ln_R_final > portable::log(kLargestRadius))
      return "expansion.factor: the container would grow to R * factor^(stages - 1) = " +
             number(portable::exp(ln_R_final)) + ", beyond 1e100 (so that V = 4/3 pi R^3 stays finite)";
    R_final = portable::exp(ln_R_final);
  }

  // Bound on the energies over the run before any growth: positions stay within the
  // container, or move about the centre of mass on ellipses, straight lines or hyperbolas.
  double S_run = S0;
  if (p.container_radius) {
    S_run = S0 + energy_scale(x.M, k, R_final, 0);  // energy conservation bounds the speeds
  } else if (p.J > 0) {
    const double amplitude = 2 * x.r_max + x.v_max / omega;
    S_run = energy_scale(x.M, k, amplitude + x.v_max * T, x.v_max + omega * amplitude);
  } else if (p.J == 0) {
    S_run = energy_scale(x.M, k, x.r_max + x.v_max * T, x.v_max);
  } else {
    const double amplitude = 2 * x.r_max + x.v_max / omega;  // exp(Omega t) coefficient
    S_run = energy_scale(x.M, k, amplitude + x.v_max * T, x.v_max + omega * amplitude);
  }
  if (!(S_run <= kLargestDerived))
    return "particles: the energies over the run could reach " + number(S_run) +
           " (masses, positions, speeds, J or duration too large): they must stay <= 1e300";

  // The largest factor by which a method grows the energies: exp(2 Omega t) for the exact
  // repulsive motion, the method's amplification squared per step for the numerical ones.
  const double h = omega * p.dt;
  std::vector<Method> methods = p.compare;
  methods.push_back(p.method);
  for (Method m : methods) {
    if (m == Method::analytic && (p.container_radius || !repulsive)) continue;
    const double ln_growth = 2 * double(steps) * portable::log(amplification(m, h, repulsive));
    if (portable::log(S_run) + ln_growth <= ln_largest) continue;
    if (m == Method::analytic) {
      const double allowed = (ln_largest - portable::log(S_run)) / 2;
      return "duration: an isolated repulsive system's energies grow as exp(2 Omega t) and must "
             "stay <= 1e300: with these particles Omega * duration must be <= " +
             number(allowed) + " (got " + number(omega * T) + ")";
    }
    return "dt: \"" + std::string(name_of(m)) + "\" at omega dt = " + number(h) +
           " can grow the energies by exp(" + number(ln_growth) +
           ") over the run, beyond 1e300; lower dt or shorten the run";
  }

  // The wall pressure of a single step: every particle's momentum reversed at the smallest radius.
  if (p.container_radius) {
    const double ln_P = portable::log(2.0) + 0.5 * (portable::log(x.M) + portable::log(S_run)) -
                        portable::log(4 * M_PI) - 2 * portable::log(*p.container_radius) - portable::log(p.dt);
    if (ln_P > ln_largest)
      return "dt: the wall pressure of one step (momentum / (4 pi R^2 dt)) could reach " +
             number(portable::exp(std::min(ln_P, 700.0))) +
             ", beyond 1e300; raise dt or container.radius";
  }
  return {};
}

}  // namespace swarm
