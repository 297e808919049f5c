// The paper's qualitative results (Section III and Appendices A, C) on small, fast versions of
// its runs, so that a regression in the physics shows up in CI rather than in a figure.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "swarm/physics/analytic.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/run/run.h"
#include "test_systems.h"

using namespace swarm;

namespace {

/// The paper's swarm, scaled down: masses in [4, 5], positions and speeds up to 1, and J set so
/// that omega (or Omega) = sqrt(|J| M) = 1.
System paper_swarm(long n, double sign, std::uint64_t seed) {
  return testing::crowded_swarm(n, sign, seed, /*speed=*/1.0);
}

/// The paper's swarm made point-symmetric: each particle has a twin at -r with -v. The CM then
/// stays at the centre of the container (twins hit the wall together with opposite impulses),
/// so the wall's reach is set by the orbits alone, as in the paper's argument.
System mirrored_swarm(long pairs, std::uint64_t seed) {
  System s = testing::random_swarm(pairs, 1.0, seed);
  const std::size_t n = s.particles.size();
  for (std::size_t i = 0; i < n; ++i) {
    Particle twin = s.particles[i];
    twin.r = -twin.r;
    twin.v = -twin.v;
    s.particles.push_back(twin);
  }
  s.J = 1 / total_mass(s);
  return s;
}

RunPlan expansion_plan(double factor, long stages, double tau) {
  RunPlan plan;
  plan.engine = {Method::analytic, CollisionMode::paper, 1.0};
  plan.dt = 0.01;
  plan.expansion = ExpansionProtocol{factor, stages, tau, 0.8};
  plan.steps = stages * steps_per_stage(*plan.expansion, plan.dt);
  plan.sample_every = plan.steps;
  return plan;
}

}  // namespace

TEST_CASE("attractive expansion: T and P fall as V grows, so P and T rise together (Fig. 2)") {
  // Below the critical size, so every stage has wall hits.
  Run run(paper_swarm(1000, +1, 11), expansion_plan(1.03, 8, 30));
  run.finish();
  const StageFits f = run.fits();
  REQUIRE(f.T_V.valid);
  REQUIRE(f.P_V.valid);
  REQUIRE(f.P_T.valid);
  // Signs, each by more than five standard errors (seeds 1 to 11 give ten or more).
  CHECK(f.T_V.slope < -5 * f.T_V.slope_stderr);
  CHECK(f.P_V.slope < -5 * f.P_V.slope_stderr);
  CHECK(f.P_T.slope > 5 * f.P_T.slope_stderr);
}

TEST_CASE("repulsive expansion: T rises, P falls, P and T anti-correlated (Fig. 3)") {
  Run run(paper_swarm(1000, -1, 12), expansion_plan(1.03, 8, 30));
  run.finish();
  const StageFits f = run.fits();
  REQUIRE(f.P_V.valid);
  CHECK(f.T_V.slope > 5 * f.T_V.slope_stderr);
  CHECK(f.P_V.slope < -5 * f.P_V.slope_stderr);
  CHECK(f.P_T.slope < -5 * f.P_T.slope_stderr);
  // Pressure falls with volume, but more slowly than 1/V: the swarm heats as it expands.
  CHECK(f.P_V.slope > -1);
}

TEST_CASE("energy is conserved through every expansion step, attractive and repulsive") {
  for (double sign : {+1.0, -1.0}) {
    const System start = paper_swarm(500, sign, 13);
    const double E0 = total_energy(start);
    Run run(start, expansion_plan(1.1, 6, 20));
    run.finish();
    REQUIRE(run.stages().size() == 6);
    for (const Stage& st : run.stages()) CHECK(std::abs(st.E - E0) < 1e-10 * std::abs(E0));
  }
}

TEST_CASE("attractive: P and T vanish once the wall is beyond every orbit, and not before") {
  // Stage by stage, from the state just after the wall moved: while nothing touches the wall
  // the system is isolated, so particle i stays within its ellipse's semi-major axis a_i of a
  // CM that moves uniformly. Its farthest reach from the container's centre during the stage
  // is then at most max_i a_i + max |R_cm(t)|, and |R_cm(t)| is largest at an end of the stage.
  // A wall beyond that reach receives nothing: P = T = 0. A wall well inside the reach of the
  // widest orbit, max_i a_i - max |R_cm(t)|, is hit: P, T > 0.
  const RunPlan plan = expansion_plan(1.08, 10, 30);
  Run run(mirrored_swarm(1000, 14), plan);
  const long per_stage = steps_per_stage(*plan.expansion, plan.dt);
  int beyond = 0, inside = 0;
  for (long k = 0; k < plan.expansion->stages; ++k) {
    const System& s = run.engine().system();
    const AnalyticSolution free_flight(s);
    double widest = 0;
    for (std::size_t i = 0; i < s.particles.size(); ++i)
      widest = std::max(widest, free_flight.ellipse(i).semi_major.norm());
    const double cm_excursion =
        std::max(free_flight.cm_position_at(s.t).norm(),
                 free_flight.cm_position_at(s.t + plan.expansion->tau).norm());
    const double R = *run.engine().container_radius();
    run.advance(per_stage);
    const Stage& st = run.stages().back();
    CAPTURE(k);
    CAPTURE(R);
    if (R > widest + cm_excursion) {
      ++beyond;
      CHECK(st.hits == 0);
      CHECK(st.P == 0);
      CHECK(st.T == 0);
    } else if (R < 0.9 * (widest - cm_excursion)) {
      ++inside;
      CHECK(st.P > 0);
      CHECK(st.T > 0);
    }
  }
  // The run must cross the critical size for the test to mean anything.
  CHECK(beyond >= 2);
  CHECK(inside >= 2);
}
