// Every measurable statement of the shipped lessons (assets/lessons/*.json), checked against the
// physics: each case runs the core (not the UI) on the preset the lesson's step opens and
// compares with the equations or with a calculation made here by hand, never with the code's
// earlier output. Each case names the lesson and step it guards (steps counted from 1, as the
// student sees them). Statements that are definitions (P = sum |dp| / (4 pi R^2 t)) or the
// paper's reading of its own data (the arch in lesson 6's residuals) are not measured here.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "lessons/lesson_file.h"
#include "swarm/measure/thermometry.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/preset/preset.h"

namespace swarmlab {
namespace {

using swarm::Vec3;

const std::vector<Lesson>& shipped_lessons() {
  static const std::vector<Lesson> lessons = [] {
    std::string problems;
    std::vector<Lesson> l =
        load_shipped_lessons(SWARM_LESSON_DIR, shipped_preset_lookup(SWARM_PRESET_DIR), problems);
    REQUIRE_MESSAGE(problems.empty(), problems);
    return l;
  }();
  return lessons;
}

const LessonStep& step_of(const std::string& id, std::size_t step_from_1) {
  for (const Lesson& l : shipped_lessons())
    if (l.id == id) {
      REQUIRE(step_from_1 - 1 < l.steps.size());
      return l.steps[step_from_1 - 1];
    }
  FAIL("no shipped lesson " << id);
  throw;
}

/// The preset of the scene shown at that step (its own, else the last one before it).
swarm::Preset scene_of(const std::string& id, std::size_t step_from_1) {
  for (std::size_t i = step_from_1; i >= 1; --i)
    if (const LessonStep& s = step_of(id, i); s.preset) return *s.preset;
  FAIL("lesson " << id << " has no preset up to step " << step_from_1);
  throw;
}

/// The preset a step opens, checked to be the one the statement is about.
swarm::Preset preset_of(const std::string& id, std::size_t step_from_1, const std::string& name) {
  const LessonStep& s = step_of(id, step_from_1);
  REQUIRE(s.preset);
  if (!name.empty()) REQUIRE(s.preset_name == name);
  return *s.preset;
}

swarm::Run run_of(const swarm::Preset& p) { return swarm::Run(swarm::initial_system(p), swarm::run_plan(p)); }

/// Advances to time t (to the nearest step).
void advance_to(swarm::Run& run, double t, double dt) {
  const long target = std::lround(t / dt);
  run.advance(target - run.steps_done());
}

std::vector<Vec3> about_cm(const swarm::System& s) {
  const Vec3 cm = swarm::cm_position(s);
  std::vector<Vec3> out;
  for (const auto& p : s.particles) out.push_back(p.r - cm);
  return out;
}

double total_mass_of(const swarm::System& s) {
  double M = 0;
  for (const auto& p : s.particles) M += p.m;
  return M;
}

/// The largest distance from the centre of mass a particle of a J > 0 swarm ever reaches: its
/// motion about the CM is x(t) = a cos wt + b sin wt with a = r0, b = v0 / w, whose largest
/// length is the root of the larger eigenvalue of the Gram matrix of a and b.
double apocentre(const Vec3& a, const Vec3& b) {
  const double aa = a.dot(a), bb = b.dot(b), ab = a.dot(b);
  return std::sqrt(0.5 * (aa + bb) + std::sqrt(0.25 * (aa - bb) * (aa - bb) + ab * ab));
}

double mean(const std::vector<double>& x) {
  return std::accumulate(x.begin(), x.end(), 0.0) / double(x.size());
}

double coefficient_of_variation(const std::vector<double>& x) {
  const double m = mean(x);
  double ss = 0;
  for (double v : x) ss += (v - m) * (v - m);
  return std::sqrt(ss / double(x.size() - 1)) / m;
}

}  // namespace

// Lesson 1 (one-period), steps 1 and 2: the pair goes round in 2 pi / sqrt(J M); the student's
// timing (a return of ball 1 to where it started) is what this measures.
TEST_CASE("lesson one-period, steps 1-2: the pair's period is 2 pi / sqrt(J M)") {
  const swarm::Preset p = preset_of("one-period", 1, "two-body-circular.json");
  swarm::Run run = run_of(p);
  const swarm::System start = run.engine().system();
  const double M = total_mass_of(start), w = std::sqrt(p.J * M), period = 2 * M_PI / w;
  const Vec3 r0 = about_cm(start)[0], v0 = start.particles[0].v - swarm::cm_velocity(start);
  // Ball 1 about the CM follows r0 cos wt + (v0 / w) sin wt: round once in 2 pi / w.
  for (const double t : {0.25 * period, 0.5 * period, period}) {
    advance_to(run, t, p.dt);
    const double at = double(run.steps_done()) * p.dt;
    const Vec3 expected = r0 * std::cos(w * at) + v0 / w * std::sin(w * at);
    CHECK((about_cm(run.engine().system())[0] - expected).norm() < 1e-9 * r0.norm());
  }
  // Back where it started, to within one step of its motion.
  CHECK((about_cm(run.engine().system())[0] - r0).norm() < 1.01 * v0.norm() * p.dt);
}

// Lesson 1, steps 3-5 and lesson 2, step 4: four different masses all close their orbits about
// the CM at the same moment, 2 pi / sqrt(J M), and none of them before.
TEST_CASE("lesson one-period, steps 3-5: every ball of Fig. 1 shares the one period") {
  const swarm::Preset p = preset_of("one-period", 3, "fig1-four-masses.json");
  swarm::Run run = run_of(p);
  const std::vector<Vec3> start = about_cm(run.engine().system());
  const double M = total_mass_of(run.engine().system());
  CHECK(M == doctest::Approx(3.25));  // lesson 2, step 2: "M = 3.25 is the total mass"
  const double period = 2 * M_PI / std::sqrt(p.J * M);
  advance_to(run, 0.37 * period, p.dt);
  for (std::size_t i = 0; i < start.size(); ++i)
    CHECK((about_cm(run.engine().system())[i] - start[i]).norm() > 0.1 * start[i].norm());
  advance_to(run, period, p.dt);
  const std::vector<Vec3> after = about_cm(run.engine().system());
  for (std::size_t i = 0; i < start.size(); ++i) {
    INFO("ball " << i + 1);
    CHECK((after[i] - start[i]).norm() < 0.01 * start[i].norm());
  }
}

// Lesson 1, step 5: the pulls of all partners add up to one pull J M m towards the CM, so the
// acceleration of every ball about the CM is -J M (r - R) whatever its mass. Summed here pair by
// pair from F = J m1 m2 r.
TEST_CASE("lesson one-period, step 5: the pair forces sum to J M m towards the CM") {
  const swarm::Preset p = scene_of("one-period", 5);
  const swarm::System s = swarm::initial_system(p);
  const double M = total_mass_of(s);
  const std::vector<Vec3> rel = about_cm(s);
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    Vec3 force = Vec3::Zero();
    for (std::size_t j = 0; j < s.particles.size(); ++j)
      force += s.J * s.particles[i].m * s.particles[j].m * (s.particles[j].r - s.particles[i].r);
    const Vec3 acceleration = force / s.particles[i].m;
    CHECK((acceleration + s.J * M * rel[i]).norm() < 1e-12 * (1 + (s.J * M * rel[i]).norm()));
  }
}

// Lesson 1, step 7: "Four times the total mass halves the period."
TEST_CASE("lesson one-period, step 7: four times the mass halves the period") {
  swarm::Preset p = preset_of("one-period", 3, "fig1-four-masses.json");
  auto& particles = std::get<std::vector<swarm::Particle>>(p.particles);
  const double M = 3.25, period = 2 * M_PI / std::sqrt(p.J * M);
  for (auto& q : particles) q.m *= 4;
  swarm::Run run = run_of(p);
  const std::vector<Vec3> start = about_cm(run.engine().system());
  advance_to(run, 0.5 * period, p.dt);  // the new period: all back at the start
  const std::vector<Vec3> after = about_cm(run.engine().system());
  for (std::size_t i = 0; i < start.size(); ++i)
    CHECK((after[i] - start[i]).norm() < 0.01 * start[i].norm());
}

// Lesson 2, step 1: the stiffest spring k = J m1 m2 is between the two heaviest balls (1 and
// 1.5), k = 1.5; the weakest between the two lightest, 0.125.
TEST_CASE("lesson springs-to-cm, step 1: the stiffest and weakest springs") {
  const swarm::System s = swarm::initial_system(preset_of("springs-to-cm", 1, "fig1-four-masses.json"));
  double stiffest = 0, weakest = 1e300;
  for (std::size_t i = 0; i < s.particles.size(); ++i)
    for (std::size_t j = i + 1; j < s.particles.size(); ++j) {
      const double k = s.J * s.particles[i].m * s.particles[j].m;
      stiffest = std::max(stiffest, k);
      weakest = std::min(weakest, k);
    }
  CHECK(stiffest == doctest::Approx(1.5));
  CHECK(weakest == doctest::Approx(0.125));
  // Step 3: "Ball 3 has mass 1" (balls are numbered from 1, as in the particle table); its one
  // spring to the CM has k = J M m = 3.25.
  REQUIRE(s.particles.size() == 4);
  CHECK(s.particles[2].m == 1.0);
  CHECK(s.J * total_mass_of(s) * s.particles[2].m == doctest::Approx(3.25));
  // Lesson 1, step 4: "The period of ball 4 (mass 1.5)", the task's particle 3 counted from 0.
  CHECK(s.particles[3].m == 1.5);
  CHECK(*step_of("one-period", 4).task->particle == 3);
}

// Lesson 2, step 5: the centre of mass moves at a steady velocity (no net force), and lesson 8,
// step 4, says the same of hard spheres, whose collisions share momentum between pairs.
TEST_CASE("lesson springs-to-cm, step 5; walls-that-work, step 4: the CM moves uniformly") {
  // Named variables, not a structured binding: clang (emcc) cannot capture one in INFO's lambda.
  for (const auto& scene : {std::pair<const char*, std::size_t>{"springs-to-cm", 1},
                            {"walls-that-work", 4}}) {
    const char* id = scene.first;
    const std::size_t step = scene.second;
    INFO(id << " step " << step);
    const swarm::Preset p = scene_of(id, step);
    swarm::Run run = run_of(p);
    const swarm::System& s0 = run.engine().system();
    const Vec3 R0 = swarm::cm_position(s0), V0 = swarm::cm_velocity(s0);
    const double t = std::min(2.0, 0.5 * p.duration);
    advance_to(run, t, p.dt);
    const swarm::System& s = run.engine().system();
    const double scale = 1 + R0.norm() + V0.norm() * t;
    // Inside a fixed container the wall pushes back; lesson 8's gas starts at rest in the
    // middle, so its CM stays put to the wall's share of the kicks, which cancel on average.
    const double tolerance = p.container_radius ? 0.02 : 1e-9;
    CHECK((swarm::cm_position(s) - (R0 + V0 * t)).norm() < tolerance * scale);
  }
}

// Lesson 3, steps 1-2: with J < 0 every distance from the CM grows like e^(Omega t),
// Omega = sqrt(-J M); step 4: the total energy stays constant while the kinetic energy grows.
TEST_CASE("lesson repulsive-runaway, steps 1-4: growth at Omega = sqrt(-J M), E constant") {
  const swarm::Preset p = scene_of("repulsive-runaway", 1);
  REQUIRE(p.J < 0);
  swarm::Run run = run_of(p);
  const double M = total_mass_of(run.engine().system());
  const double Omega = std::sqrt(-p.J * M);
  const double E0 = swarm::kinetic_energy(run.engine().system()) +
                    swarm::potential_energy_cm(run.engine().system());
  const double KE0 = swarm::kinetic_energy(run.engine().system());
  auto size = [&] {
    double sum = 0;
    for (const Vec3& r : about_cm(run.engine().system())) sum += r.norm();
    return sum;
  };
  advance_to(run, 1.0, p.dt);
  const double at1 = size();
  advance_to(run, 2.0, p.dt);
  const double at2 = size();
  // Late on the growing mode dominates: one time unit multiplies sizes by about e^Omega.
  CHECK(std::log(at2 / at1) == doctest::Approx(Omega).epsilon(0.05));
  const swarm::System& s = run.engine().system();
  const double E = swarm::kinetic_energy(s) + swarm::potential_energy_cm(s);
  CHECK(swarm::kinetic_energy(s) > 10 * KE0);
  CHECK(std::abs(E - E0) < 1e-9 * std::abs(swarm::kinetic_energy(s)));
}

// Lesson 4, steps 1-2: Euler's energy grows step after step. For a swarm of springs to the CM
// each Euler step multiplies the energy of the motion about the CM by exactly 1 + (w dt)^2.
// Step 5: halving dt halves the rate at which that energy error grows (a first-order method).
TEST_CASE("lesson euler-cromer-exact, steps 1, 2 and 5: Euler's energy grows as (1 + w^2 dt^2)^n") {
  swarm::Preset p = preset_of("euler-cromer-exact", 1, "euler-vs-euler-cromer.json");
  REQUIRE(p.method == swarm::Method::euler);
  p.compare.clear();
  auto internal_energy = [](const swarm::System& s) {
    const double M = total_mass_of(s);
    return swarm::kinetic_energy(s) + swarm::potential_energy_cm(s) -
           0.5 * M * swarm::cm_velocity(s).squaredNorm();
  };
  auto growth_rate = [&](double dt) {  // d ln(E_internal) / dt over 5 time units
    p.dt = dt;
    swarm::Run run = run_of(p);
    const double e0 = internal_energy(run.engine().system());
    const double w2 = p.J * total_mass_of(run.engine().system());
    const long n = std::lround(5.0 / dt);
    double previous = e0;
    bool grows = true;
    for (long k = 0; k < n; k += 50) {
      run.advance(50);
      const double e = internal_energy(run.engine().system());
      grows = grows && e > previous;
      previous = e;
    }
    CHECK(grows);
    const double expected = std::pow(1 + w2 * dt * dt, double(run.steps_done()));
    CHECK(previous / e0 == doctest::Approx(expected).epsilon(1e-9));
    return std::log(previous / e0) / (double(run.steps_done()) * dt);
  };
  const double rate = growth_rate(p.dt), half = growth_rate(0.5 * p.dt);
  CHECK(half / rate == doctest::Approx(0.5).epsilon(0.02));
}

// Lesson 4, step 3: Euler-Cromer's energy only wobbles about the right value and never runs
// away; the exact solution's stays put.
TEST_CASE("lesson euler-cromer-exact, steps 3-4: Euler-Cromer's energy stays bounded") {
  swarm::Preset p = preset_of("euler-cromer-exact", 3, "methods-vs-analytic.json");
  p.compare.clear();
  for (const swarm::Method method : {swarm::Method::euler_cromer, swarm::Method::analytic}) {
    p.method = method;
    swarm::Run run = run_of(p);
    const swarm::System& s0 = run.engine().system();
    const double E0 = swarm::kinetic_energy(s0) + swarm::potential_energy_cm(s0);
    const double w = std::sqrt(p.J * total_mass_of(s0));
    double worst_early = 0, worst_late = 0;
    const long n = swarm::step_count(p);
    for (long k = 0; k < n; ++k) {
      run.advance(1);
      const swarm::System& s = run.engine().system();
      const double off = std::abs(swarm::kinetic_energy(s) + swarm::potential_energy_cm(s) - E0);
      (k < n / 2 ? worst_early : worst_late) = std::max(k < n / 2 ? worst_early : worst_late, off);
    }
    if (method == swarm::Method::analytic) {
      CHECK(worst_late < 1e-10 * std::abs(E0));
    } else {
      // Bounded by a term of order w dt, and no larger in the second half than in the first.
      CHECK(worst_late < 2 * w * p.dt * std::abs(E0));
      CHECK(worst_late < 1.5 * worst_early);
    }
  }
}

// Lesson 5, step 5 (finding 11): the pressure is the noisier of the two: sample by sample (as
// the Wall P, T plot draws them: P in every sample, T where something hit) P scatters several
// times as much as T about its trend (the gas is still equilibrating; about 1 hit a sample, so
// most samples of P are 0 or one kick, while T averages the energies of whoever hit). Over four
// seeds, the spread between them taken as the uncertainty.
TEST_CASE("lesson gas-at-the-wall, step 5: P scatters several times as much as T") {
  swarm::Preset p = preset_of("gas-at-the-wall", 1, "fig4-equilibration.json");
  // The scatter of x about its centred moving average over `half` neighbours each side, relative
  // to that average: the noise without the trend of the equilibration.
  auto relative_scatter = [](const std::vector<double>& x, std::size_t half) {
    std::vector<double> residual;
    for (std::size_t i = half; i + half < x.size(); ++i) {
      double sum = 0;
      for (std::size_t j = i - half; j <= i + half; ++j) sum += x[j];
      const double trend = sum / double(2 * half + 1);
      if (trend > 0) residual.push_back(x[i] / trend - 1);  // before the first hits: no P yet
    }
    double ss = 0;
    for (double r : residual) ss += r * r;
    return std::sqrt(ss / double(residual.size()));
  };
  std::vector<double> ratios;
  for (const std::uint64_t seed : {2025u, 7u, 11u, 99u}) {
    std::get<swarm::SwarmSpec>(p.particles).seed = seed;
    swarm::Run run = run_of(p);
    run.finish();
    std::vector<double> P, T;
    for (const swarm::Sample& s : run.samples()) {
      P.push_back(s.P);
      if (s.hits > 0) T.push_back(s.T);
    }
    REQUIRE(T.size() > 500);
    // About 0.1 time units each side, in samples of P (every step) and of T (about every other).
    const std::size_t half_P = std::size_t(0.05 / p.dt);
    const std::size_t half_T = half_P * T.size() / P.size();
    ratios.push_back(relative_scatter(P, half_P) / relative_scatter(T, half_T));

  }
  const double ratio = mean(ratios);
  double spread = 0;
  for (double r : ratios) spread = std::max(spread, std::abs(r - ratio));
  MESSAGE("per-sample scatter of P / scatter of T = " << ratio << " +- " << spread << " over 4 seeds");
  CHECK(ratio - spread > 3);
}

// Lesson 5, steps 1 and 5: "every particle is pulled towards the middle": the gas crowds
// towards the centre, more than a uniform gas would (1/8 of it within half the radius).
TEST_CASE("lesson gas-at-the-wall, steps 1 and 5: the attracting gas crowds to the middle") {
  const swarm::Preset p = preset_of("gas-at-the-wall", 1, "fig4-equilibration.json");
  swarm::Run run = run_of(p);
  run.finish();
  const swarm::System& s = run.engine().system();
  const double R = *p.container_radius;
  std::size_t inner = 0;
  for (const Vec3& r : about_cm(s)) inner += r.norm() < 0.5 * R;
  // Uniform: 1/8 of the particles, give or take sqrt(N / 8 * 7 / 8) of them (about 0.005).
  const double uniform = 1.0 / 8, sd = std::sqrt(uniform * (1 - uniform) / double(s.particles.size()));
  CHECK(double(inner) / double(s.particles.size()) > uniform + 10 * sd);
}

// Lesson 6, step 2: a bound swarm has a largest size: a wall beyond every particle's furthest
// point (its apocentre about the CM, computed here from r0 and v0 / w) is never hit.
TEST_CASE("lesson expansion-log-log, step 2: a wall beyond every orbit is never hit") {
  swarm::Preset p = preset_of("expansion-log-log", 1, "fig2-attractive-expansion.json");
  auto& spec = std::get<swarm::SwarmSpec>(p.particles);
  spec.count = 300;
  spec.cm_at_rest = true;  // so that the CM stays where the wall is centred
  p.J *= 4000.0 / 300.0;  // the same J M, so the same orbits' frequency
  const swarm::System s = swarm::initial_system(p);
  const double w = std::sqrt(p.J * total_mass_of(s));
  const Vec3 V = swarm::cm_velocity(s);
  const std::vector<Vec3> rel = about_cm(s);
  double reach = 0;
  for (std::size_t i = 0; i < rel.size(); ++i)
    reach = std::max(reach, apocentre(rel[i], (s.particles[i].v - V) / w));
  // The wall is centred on the origin, the orbits on the CM (at rest, near the origin).
  const double furthest = swarm::cm_position(s).norm() + reach;
  REQUIRE(V.norm() < 1e-9);
  p.expansion.reset();
  p.container_radius = 1.001 * furthest;
  p.duration = 4 * 2 * M_PI / w;
  p.sample_every.reset();
  swarm::Run run = run_of(p);
  run.finish();
  CHECK(run.summary().wall_hits == 0);
  p.container_radius = 0.9 * reach;  // and one inside that reach is hit
  swarm::Run closer = run_of(p);
  closer.finish();
  CHECK(closer.summary().wall_hits > 0);
}

// Lesson 6, steps 2 and 5: as the attracting gas's container grows, P and T both fall, so
// they are positively correlated. A smaller swarm with the same J M and the same protocol.
TEST_CASE("lesson expansion-log-log, steps 2 and 5: P and T fall together as V grows") {
  swarm::Preset p = preset_of("expansion-log-log", 1, "fig2-attractive-expansion.json");
  std::get<swarm::SwarmSpec>(p.particles).count = 1000;
  p.J *= 4.0;
  p.expansion->stages = 12;
  p.expansion->factor = 1.05;
  p.duration = p.expansion->stages * p.expansion->tau;
  REQUIRE(swarm::preset_error(p).empty());
  swarm::Run run = run_of(p);
  run.finish();
  const std::vector<swarm::Stage>& stages = run.stages();
  REQUIRE(stages.size() >= 10);
  CHECK(stages.back().P < stages.front().P);
  CHECK(stages.back().T < stages.front().T);
  const swarm::StageFits fits = run.fits();
  CHECK(fits.P_V.slope < 0);
  CHECK(fits.T_V.slope < 0);
  CHECK(fits.P_T.slope > 0);  // positively correlated
}

// Lesson 7, step 2: while the swarm falls freely its CM follows R0 + V0 t + g t^2 / 2, and the
// motion about the CM is that of the same swarm without gravity.
TEST_CASE("lesson outside-forces, step 2: free fall moves the CM only") {
  const swarm::Preset p = preset_of("outside-forces", 1, "gravity-floor-bounce.json");
  REQUIRE(p.gravity);
  REQUIRE(p.floor);
  swarm::Preset weightless = p;
  weightless.gravity.reset();
  weightless.floor.reset();
  swarm::Run falling = run_of(p), floating = run_of(weightless);
  const swarm::System& s0 = falling.engine().system();
  const Vec3 R0 = swarm::cm_position(s0), V0 = swarm::cm_velocity(s0), g = *p.gravity;
  // Before any particle reaches the floor: the lowest particle at t = 0 falls at most
  // (its height - floor) in the time free fall takes, from rest or moving down.
  double lowest = 1e300;
  for (const auto& q : s0.particles) lowest = std::min(lowest, q.r.z());
  const double drop = lowest - p.floor->z;
  REQUIRE(drop > 0);
  const double t = 0.5 * std::sqrt(2 * drop / std::abs(g.z()));  // well before a hit
  advance_to(falling, t, p.dt);
  advance_to(floating, t, p.dt);
  const double tt = double(falling.steps_done()) * p.dt;
  const Vec3 expected = R0 + V0 * tt + 0.5 * g * tt * tt;
  CHECK((swarm::cm_position(falling.engine().system()) - expected).norm() < 1e-9 * (1 + expected.norm()));
  const std::vector<Vec3> a = about_cm(falling.engine().system()), b = about_cm(floating.engine().system());
  for (std::size_t i = 0; i < a.size(); ++i) CHECK((a[i] - b[i]).norm() < 1e-8);
}

// Lesson 7, step 3: drag -gamma m v slows every particle alike: the CM's velocity decays as
// e^(-gamma t) and the energy only falls.
TEST_CASE("lesson outside-forces, step 3: drag takes energy out; the CM coasts to a stop") {
  const swarm::Preset p = preset_of("outside-forces", 3, "drag-damped-swarm.json");
  REQUIRE(p.drag);
  REQUIRE(p.drag->mass_proportional());
  swarm::Run run = run_of(p);
  const swarm::System& s0 = run.engine().system();
  const Vec3 V0 = swarm::cm_velocity(s0);
  double E = swarm::kinetic_energy(s0) + swarm::potential_energy_cm(s0);
  bool falls = true;
  for (int k = 1; k <= 20; ++k) {
    advance_to(run, 0.1 * k, p.dt);
    const swarm::System& s = run.engine().system();
    const double e = swarm::kinetic_energy(s) + swarm::potential_energy_cm(s);
    falls = falls && e < E;
    E = e;
  }
  CHECK(falls);
  const double t = double(run.steps_done()) * p.dt;
  const Vec3 expected = V0 * std::exp(-p.drag->gamma * t);
  CHECK((swarm::cm_velocity(run.engine().system()) - expected).norm() < 1e-6 * (1 + V0.norm()));
}

// Lesson 8, steps 1-2: a wall moved in and back out at a finite speed leaves the gas hotter:
// the net work done on it over the cycle is positive, and it is all the energy the gas gained.
TEST_CASE("lesson walls-that-work, steps 1-2: a moving wall's cycle leaves work in the gas") {
  const swarm::Preset p = preset_of("walls-that-work", 1, "moving-wall-cycle.json");
  REQUIRE_FALSE(p.wall_moves.empty());
  swarm::Run run = run_of(p);
  run.finish();
  const swarm::RunSummary s = run.summary();
  CHECK(s.books.wall_work > 0);
  CHECK(s.E_end > s.E0);
  CHECK(s.E_end - s.E0 == doctest::Approx(s.books.net()).epsilon(1e-6));
}

// Lesson 8, step 3: a hot wall brings the gas's temperature towards its own.
TEST_CASE("lesson walls-that-work, step 3: the gas heats towards the wall's temperature") {
  const swarm::Preset p = preset_of("walls-that-work", 3, "hot-wall.json");
  REQUIRE(p.wall_temperature);
  swarm::Run run = run_of(p);
  run.finish();
  const std::vector<swarm::WallInterval> intervals = swarm::wall_intervals(run.samples());
  REQUIRE(intervals.size() > 20);
  const std::size_t tenth = intervals.size() / 10;
  const double early = swarm::wall_average(intervals, 0, tenth).T;
  const double late = swarm::wall_average(intervals, intervals.size() - tenth, intervals.size()).T;
  const double Tw = *p.wall_temperature;
  CHECK(std::abs(late - Tw) < std::abs(early - Tw));
  CHECK(std::abs(late - Tw) < 0.25 * Tw);
}

}  // namespace swarmlab
