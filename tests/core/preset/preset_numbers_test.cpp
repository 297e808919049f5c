#include "preset/preset_numbers.h"

#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "swarm/methods/method.h"

using namespace swarm;

namespace {

// Each limit below is computed here from the rule the header states (every derived number
// <= 1e300, the radius in [1e-100, 1e100]) and the bound the check uses, then a preset is put
// just inside and just outside it. A relative step of 1e-9 is far wider than the rounding of
// the check's logarithms (about 1e-16 of ln 1e300 = 690.8) and far narrower than any slack.
constexpr double kInside = 1 - 1e-9, kOutside = 1 + 1e-9;
const double kLnLargest = std::log(1e300);

/// An isolated preset of explicit particles run for `duration` at `dt` by the exact map.
Preset preset_of(double J, std::vector<Particle> particles, double dt = 1e-3,
                 double duration = 1.0) {
  Preset p;
  p.J = J;
  p.particles = std::move(particles);
  p.dt = dt;
  p.duration = duration;
  return p;
}

/// Two unit masses at +-x on the x axis, at rest (M = 2, r_max = x, v_max = 0).
std::vector<Particle> pair_at_rest(double x) {
  return {{1.0, {x, 0, 0}, {0, 0, 0}}, {1.0, {-x, 0, 0}, {0, 0, 0}}};
}

/// The bound the check puts on the energies and the sums behind them (sum m v^2, sum m r^2 and
/// |J| M sum m r^2) for particles of total mass M within r of the centre of mass at speeds up
/// to v: M v^2 + (1 + |k|) M (2 r)^2 with k = J M (preset_numbers.cpp, energy_scale). An
/// initial |r_i| <= r_max puts every particle within 2 r_max of the CM.
double energy_bound(double M, double k, double r, double v) {
  return M * v * v + (1 + std::abs(k)) * M * (2 * r) * (2 * r);
}

/// The bound over a run without a container for J != 0: about the CM every particle stays
/// within the amplitude A = 2 r_max + v_max / omega of the orbit (ellipse, or for J < 0 the
/// coefficient of exp(Omega t)), with speed up to v_max + omega A, while the CM drifts v_max T.
double run_bound(double M, double J, double r_max, double v_max, double T) {
  const double k = J * M, omega = std::sqrt(std::abs(k));
  const double A = 2 * r_max + v_max / omega;
  return energy_bound(M, k, A + v_max * T, v_max + omega * A);
}

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.rfind(prefix, 0) == 0;
}

std::string g4(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

/// Largest |eigenvalue| of one step of method m on x'' = -k x, from the step's own 2x2 matrix
/// on (x, v), written out here from integrators.h: the factor by which it can grow an
/// amplitude each step.
double growth_per_step(Method m, double k, double dt) {
  Eigen::Matrix2d step;
  switch (m) {
    case Method::euler:  // x += v dt, v += -k x_old dt
      step << 1, dt, -k * dt, 1;
      break;
    case Method::euler_cromer:  // v += -k x dt, x += v_new dt
      step << 1 - k * dt * dt, dt, -k * dt, 1;
      break;
    case Method::verlet:  // half kick, drift, half kick
      step << 1 - k * dt * dt / 2, dt, -k * dt * (1 - k * dt * dt / 4), 1 - k * dt * dt / 2;
      break;
    case Method::rk4: {  // the fourth-order Taylor polynomial of exp(dt A) for a linear system
      Eigen::Matrix2d A;
      A << 0, 1, -k, 0;
      const Eigen::Matrix2d H = dt * A;
      step = Eigen::Matrix2d::Identity() + H + H * H / 2 + H * H * H / 6 + H * H * H * H / 24;
      break;
    }
    case Method::analytic:
      step = Eigen::Matrix2d::Identity();
      break;
  }
  // Eigenvalues of a 2x2 matrix from its trace and determinant.
  const double half_trace = step.trace() / 2, det = step.determinant();
  const double disc = half_trace * half_trace - det;
  if (disc < 0) return std::sqrt(det);  // a complex pair, |lambda|^2 = det
  return std::max(std::abs(half_trace + std::sqrt(disc)), std::abs(half_trace - std::sqrt(disc)));
}

}  // namespace

TEST_CASE("preset numbers: an ordinary preset has nothing to report") {
  Preset p;  // the default: a generated swarm of 100, attractive, the exact map
  CHECK(unrepresentable_numbers(p) == "");
  p.container_radius = 1.0;
  p.compare = {Method::euler, Method::verlet, Method::rk4};
  CHECK(unrepresentable_numbers(p) == "");
}

TEST_CASE("preset numbers: the total mass M stays <= 1e300") {
  // One particle at rest at the origin, J = 1e-300 so that J M stays of order one.
  auto one_mass = [](double m) { return preset_of(1e-300, {{m, {0, 0, 0}, {0, 0, 0}}}); };
  CHECK(unrepresentable_numbers(one_mass(1e300)) == "");
  const std::string error = unrepresentable_numbers(one_mass(std::nextafter(1e300, 2e300)));
  CHECK(starts_with(error, "particles: the total mass M = 1e+300 must stay <= 1e300"));
  // A generated swarm bounds M by count * mass_max, and names the field that sets it.
  SwarmSpec spec;
  spec.count = 1000;
  spec.mass_min = 1;
  spec.position_radius = 0;
  spec.speed = 0;
  Preset swarm;
  swarm.J = 1e-300;
  spec.mass_max = 1e297 * kInside;
  swarm.particles = spec;
  CHECK(unrepresentable_numbers(swarm) == "");
  spec.mass_max = 1e297 * kOutside;
  swarm.particles = spec;
  CHECK(starts_with(unrepresentable_numbers(swarm), "particles.mass: the total mass M ="));
}

TEST_CASE("preset numbers: k = J M stays within +-1e300") {
  const double above = std::nextafter(1e300, 2e300);
  auto at_rest = [](double J, double dt) {
    return preset_of(J, {{1.0, {0, 0, 0}, {0, 0, 0}}}, dt, dt);
  };
  CHECK(unrepresentable_numbers(at_rest(1e300, 1e-3)) == "");
  CHECK(starts_with(unrepresentable_numbers(at_rest(above, 1e-3)), "J: J * M = 1e+300"));
  // Repulsive: Omega = 1e150, so a step short enough that exp(Omega t) stays near one.
  CHECK(unrepresentable_numbers(at_rest(-1e300, 1e-160)) == "");
  CHECK(starts_with(unrepresentable_numbers(at_rest(-above, 1e-160)), "J: J * M = -1e+300"));
}

TEST_CASE("preset numbers: the energies at t = 0 stay <= 1e300") {
  // In a unit container the bound over the run adds only (1 + |k|) M 4 R^2 to the one at
  // t = 0, so the limit found is the initial energies'.
  auto moving = [](double J, double m, double r, double v) {
    Preset p = preset_of(J, {{m, {r, 0, 0}, {v, 0, 0}}});
    p.container_radius = 1.0;
    return p;
  };
  // Speed: M v^2 <= 1e300 with M = 2, J = 0.
  const double v_limit = std::sqrt(1e300 / 2);
  CHECK(unrepresentable_numbers(moving(0, 2, 0, v_limit * kInside)) == "");
  CHECK(starts_with(unrepresentable_numbers(moving(0, 2, 0, v_limit * kOutside)),
                    "particles: the energies at t = 0 could reach"));
  // Position: (1 + J M) M (2 r)^2 <= 1e300 with M = 2, J = 3 (the particle need not fit the
  // container for this rule).
  const double r_limit = std::sqrt(1e300 / ((1 + 3 * 2) * 2)) / 2;
  CHECK(unrepresentable_numbers(moving(3, 2, r_limit * kInside, 0)) == "");
  CHECK(starts_with(unrepresentable_numbers(moving(3, 2, r_limit * kOutside, 0)),
                    "particles: the energies at t = 0 could reach"));
}

TEST_CASE("preset numbers: the container's radius stays within [1e-100, 1e100]") {
  auto in_container = [](double R) {
    Preset p = preset_of(1, {{1.0, {0, 0, 0}, {0, 0, 0}}});
    p.container_radius = R;
    return p;
  };
  CHECK(unrepresentable_numbers(in_container(kSmallestRadius)) == "");
  CHECK(unrepresentable_numbers(in_container(kLargestRadius)) == "");
  CHECK(starts_with(unrepresentable_numbers(in_container(std::nextafter(1e-100, 0.0))),
                    "container.radius: must be >= 1e-100"));
  CHECK(starts_with(unrepresentable_numbers(in_container(std::nextafter(1e100, 1e101))),
                    "container.radius: must be <= 1e100"));
  // The reason for the range: R^2 and V = 4/3 pi R^3 are normal doubles at both ends.
  for (double R : {kSmallestRadius, kLargestRadius}) {
    CAPTURE(R);
    CHECK(kSmallestRadius == 1e-100);
    CHECK(kLargestRadius == 1e100);
    CHECK(std::isnormal(R * R));
    CHECK(std::isnormal(4.0 / 3 * M_PI * R * R * R));
  }
}

TEST_CASE("preset numbers: an expansion grows the container to at most 1e100") {
  // R = 1 and 11 stages of one step: the last stage's radius is factor^10, 1e100 at 1e10.
  auto expanding = [](double factor) {
    Preset p = preset_of(1, {{1.0, {0, 0, 0}, {0, 0, 0}}});
    p.container_radius = 1.0;
    p.expansion = ExpansionProtocol{factor, 11, p.dt, 0.8};
    return p;
  };
  const double factor_limit = std::pow(1e100, 1.0 / 10);
  CHECK(unrepresentable_numbers(expanding(factor_limit * kInside)) == "");
  CHECK(starts_with(
      unrepresentable_numbers(expanding(factor_limit * kOutside)),
      "expansion.factor: the container would grow to R * factor^(stages - 1) = 1e+100"));
}

TEST_CASE("preset numbers: without a container the energies over the run stay <= 1e300") {
  SUBCASE("J = 0: particles fly straight, |r| up to r_max + v_max T") {
    // One particle of unit mass at the origin at 1e10: 1e20 + 4 (1e10 T)^2 <= 1e300, in one step.
    const double v = 1e10, T_limit = std::sqrt((1e300 - v * v) / 4) / v;
    auto flying = [&](double T) { return preset_of(0, {{1.0, {0, 0, 0}, {v, 0, 0}}}, T, T); };
    CHECK(unrepresentable_numbers(flying(T_limit * kInside)) == "");
    CHECK(starts_with(unrepresentable_numbers(flying(T_limit * kOutside)),
                      "particles: the energies over the run could reach"));
  }
  SUBCASE("J != 0: the orbit's amplitude 2 r_max + v_max / omega, the CM drifting v_max T") {
    // A unit mass at the origin at speed V, J = +-1 (omega = 1), over one step of 1e-12 (so
    // that the repulsive exact map's growth, exp(2e-12), stays inside the margin).
    const double T = 1e-12;
    for (double J : {1.0, -1.0}) {
      CAPTURE(J);
      const double V_limit = std::sqrt(1e300 / run_bound(1, J, 0, 1, T));
      auto moving = [&](double V) { return preset_of(J, {{1.0, {0, 0, 0}, {V, 0, 0}}}, T, T); };
      CHECK(unrepresentable_numbers(moving(V_limit * kInside)) == "");
      CHECK(starts_with(unrepresentable_numbers(moving(V_limit * kOutside)),
                        "particles: the energies over the run could reach"));
    }
  }
}

TEST_CASE("preset numbers: an isolated repulsive pair under the exact map, Omega t to the limit") {
  // Two unit masses at +-1/2 at rest, J = -1: Omega = sqrt(2). x(t) = cosh(Omega t) / 2 and the
  // energies grow as exp(2 Omega t) from the run bound S (here 28), so the limit on Omega t is
  // (ln 1e300 - ln S) / 2 = 343.7. In whole steps of dt: the largest count inside, one more out.
  const double Omega = std::sqrt(2.0), dt = 0.01, h = Omega * dt;
  const double S = run_bound(2, -1, 0.5, 0, 0);
  CHECK(S == doctest::Approx(28));
  const double limit = (kLnLargest - std::log(S)) / 2;
  const double steps_inside = std::floor(limit / h);
  REQUIRE(limit - steps_inside * h > 1e-6);  // not so close to a step that rounding decides
  auto pushing_apart = [&](double steps) {
    return preset_of(-1, pair_at_rest(0.5), dt, steps * dt);
  };
  CHECK(unrepresentable_numbers(pushing_apart(steps_inside)) == "");
  const std::string error = unrepresentable_numbers(pushing_apart(steps_inside + 1));
  CHECK(starts_with(error,
                    "duration: an isolated repulsive system's energies grow as exp(2 Omega t)"));
  CHECK(error.find("Omega * duration must be <= " + g4(limit)) != std::string::npos);

  // What the run computes at the accepted end is finite: the positions cosh(Omega T) / 2 and
  // the kinetic energy sinh^2(Omega T) / 2 (both unit masses moving at sinh(Omega T) / sqrt 2).
  const double x = steps_inside * h;
  CHECK(std::isfinite(0.5 * std::sinh(x) * std::sinh(x)));
  CHECK(0.5 * std::sinh(x) * std::sinh(x) < 1e300);
  // Where a double would give out: the kinetic energy overflows at sinh(x)^2 / 2 = DBL_MAX,
  // that is e^x / 2 = sqrt(2 DBL_MAX) this far out (x = 355.9), and exp(Omega t) itself at
  // Omega t = ln DBL_MAX = 709.78. Both are refused.
  const double energy_overflow = std::log(2.0) + 0.5 * (std::log(2.0) + std::log(DBL_MAX));
  const double exp_overflow = std::log(DBL_MAX);
  CHECK(exp_overflow == doctest::Approx(709.78).epsilon(1e-4));
  CHECK(limit < energy_overflow);
  for (double x_far : {energy_overflow, exp_overflow - 0.1}) {
    CAPTURE(x_far);
    CHECK_FALSE(unrepresentable_numbers(pushing_apart(std::ceil(x_far / h))).empty());
  }

  // In a container the wall bounds the energies: no limit on Omega t for the exact map.
  Preset contained = pushing_apart(std::ceil(1000 / h));
  contained.container_radius = 1.0;
  CHECK(unrepresentable_numbers(contained) == "");
}

TEST_CASE("preset numbers: each numerical method may grow the energies by |lambda|^(2N) to 1e300") {
  // Two unit masses at +-0.1 at rest, J = +-1: M = 2, k = +-2. The check bounds the energies
  // at S |lambda_max|^(2 N) over N steps, lambda_max the step's largest eigenvalue on
  // x'' = -k x (computed here from each scheme's matrix). Limit: N <= (ln 1e300 - ln S) /
  // (2 ln |lambda_max|). The attractive cases use omega dt past each scheme's stability edge
  // (Euler always grows; Euler-Cromer and Verlet beyond 2; RK4 beyond 2 sqrt 2).
  struct Case {
    Method method;
    double J, omega_dt;
  };
  const Case cases[] = {{Method::euler, 1, 1.0},        {Method::euler, -1, 0.5},
                        {Method::euler_cromer, 1, 2.5}, {Method::euler_cromer, -1, 1.0},
                        {Method::verlet, 1, 2.5},       {Method::verlet, -1, 1.0},
                        {Method::rk4, 1, 3.0},          {Method::rk4, -1, 1.0}};
  for (const Case& c : cases) {
    CAPTURE(name_of(c.method));
    CAPTURE(c.J);
    const double k = 2 * c.J, omega = std::sqrt(2.0), dt = c.omega_dt / omega;
    const double S = run_bound(2, c.J, 0.1, 0, 0);
    const double lambda = growth_per_step(c.method, k, dt);
    REQUIRE(lambda > 1);
    const double N_limit = (kLnLargest - std::log(S)) / (2 * std::log(lambda));
    const double N_inside = std::floor(N_limit);
    CAPTURE(N_limit);
    REQUIRE(N_limit - N_inside > 1e-9);
    auto run_for = [&](double N) {
      Preset p = preset_of(c.J, pair_at_rest(0.1), dt, N * dt);
      p.method = c.method;
      return p;
    };
    CHECK(unrepresentable_numbers(run_for(N_inside)) == "");
    CHECK(starts_with(
        unrepresentable_numbers(run_for(N_inside + 1)),
        "dt: \"" + std::string(name_of(c.method)) + "\" at omega dt = " + g4(c.omega_dt)));
    // A method only compared with is judged alike.
    Preset compared = run_for(N_inside + 1);
    compared.method = Method::analytic;
    compared.compare = {c.method};
    if (c.J > 0) {  // (repulsive, the exact map has its own, shorter limit)
      CHECK(starts_with(unrepresentable_numbers(compared),
                        "dt: \"" + std::string(name_of(c.method)) + "\""));
    }
  }
  // Within the stability edge an attractive run may be as long as it likes.
  for (Method m : {Method::euler_cromer, Method::verlet, Method::rk4}) {
    CAPTURE(name_of(m));
    const double dt = 1.0 / std::sqrt(2.0);
    CHECK(growth_per_step(m, 2, dt) <= 1 + 1e-15);
    Preset p = preset_of(1, pair_at_rest(0.1), dt, 1e8 * dt);
    p.method = m;
    CHECK(unrepresentable_numbers(p) == "");
  }
}

TEST_CASE("preset numbers: the wall pressure of one step stays <= 1e300") {
  // Every particle's momentum reversed in one step at the container: the impulse is at most
  // 2 sum m |v| <= 2 sqrt(M sum m v^2) <= 2 sqrt(M S), over the area 4 pi R^2 and the time dt.
  // A mass 2 at speed 3 in a container of 1e-50, J = 1: S = 2 * 9 + (1 + 2) 2 (2e-50)^2 = 18.
  const double R = 1e-50, M = 2;
  const double S = energy_bound(M, 2, 0, 3) + energy_bound(M, 2, R, 0);
  const double dt_limit = 2 * std::sqrt(M * S) / (4 * M_PI * R * R * 1e300);
  auto one_step = [&](double dt) {
    Preset p = preset_of(1, {{M, {0, 0, 0}, {3, 0, 0}}}, dt, dt);
    p.container_radius = R;
    return p;
  };
  CHECK(unrepresentable_numbers(one_step(dt_limit * kOutside)) == "");
  CHECK(starts_with(unrepresentable_numbers(one_step(dt_limit * kInside)),
                    "dt: the wall pressure of one step (momentum / (4 pi R^2 dt)) could reach"));
}
