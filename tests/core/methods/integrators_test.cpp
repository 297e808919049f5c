#include "swarm/methods/integrators.h"

#include <doctest/doctest.h>

#include <cmath>

#include "swarm/physics/analytic.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/run/side_by_side.h"
#include "test_systems.h"

using namespace swarm;
using doctest::Approx;

namespace {

double error_after(Method m, const System& s, double t_end, int steps) {
  System n = s;
  for (int i = 0; i < steps; ++i) step(m, n, t_end / steps);
  return max_position_difference(n, AnalyticSolution(s).at(t_end));
}

}  // namespace

TEST_CASE("pairwise accelerations equal the pull towards the CM, -J M (r - R_cm) (eq. 6)") {
  const System s = testing::random_swarm(50, 0.8, 3);
  std::vector<Vec3> a;
  pairwise_accelerations(s, a);
  const Vec3 R = cm_position(s);
  for (std::size_t i = 0; i < s.particles.size(); ++i)
    CHECK((a[i] + stiffness(s) * (s.particles[i].r - R)).norm() < 1e-11);
}

TEST_CASE("numerical methods converge to the analytic orbit with their expected orders") {
  const System s = testing::four_masses(0.5);
  // Not a whole period: there Euler-Cromer's first-order phase error happens to cancel.
  const double t_end = 0.37 * AnalyticSolution(s).period();
  struct Expect {
    Method method;
    int order;
    int steps;
  };
  for (const Expect& e : {Expect{Method::euler, 1, 4000}, Expect{Method::euler_cromer, 1, 4000},
                          Expect{Method::verlet, 2, 400}, Expect{Method::rk4, 4, 100}}) {
    CAPTURE(name_of(e.method));
    const double coarse = error_after(e.method, s, t_end, e.steps);
    const double fine = error_after(e.method, s, t_end, 2 * e.steps);
    const double measured_order = std::log2(coarse / fine);
    CHECK(measured_order == Approx(e.order).epsilon(0.1));
    CHECK(order_of(e.method) == e.order);
  }
  CHECK(error_after(Method::analytic, s, t_end, 7) < 1e-12);
}

TEST_CASE("Euler's energy drifts while Euler-Cromer's stays bounded") {
  const System s = testing::four_masses(1.0);
  const double E0 = total_energy(s);
  const double period = AnalyticSolution(s).period(), dt = period / 200;
  System euler = s, cromer = s;
  double cromer_early = 0, cromer_late = 0;
  for (int i = 0; i < 200 * 40; ++i) {
    step_euler(euler, dt);
    step_euler_cromer(cromer, dt);
    const double dev = std::abs(total_energy(cromer) - E0) / std::abs(E0);
    (i < 200 * 5 ? cromer_early : cromer_late) =
        std::max(i < 200 * 5 ? cromer_early : cromer_late, dev);
  }
  // Euler multiplies the energy by about (1 + (omega dt)^2) per step: exp(40 periods * 200 *
  // (2 pi / 200)^2) is e^{7.9}.
  CHECK(total_energy(euler) / E0 > 100);
  CHECK(cromer_late < 1.1 * cromer_early);  // no secular growth
  CHECK(cromer_late < 0.1);
}
