#include "swarm/run/timeline.h"

#include <doctest/doctest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "swarm/measure/state_hash.h"
#include "swarm/physics/analytic.h"
#include "swarm/preset/preset.h"
#include "test_systems.h"

using namespace swarm;
using testing::crowded_swarm;
using testing::shipped_preset;

namespace {

/// The hash of every run's state (the primary's first), for "the same to the last bit".
std::vector<std::uint64_t> hashes(SideBySide& runs) {
  std::vector<std::uint64_t> out{state_hash(runs.primary().engine().system())};
  for (const SideBySide::Track& track : runs.tracks())
    out.push_back(state_hash(track.run->engine().system()));
  return out;
}

bool same_samples(const std::vector<Sample>& a, const std::vector<Sample>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].t != b[i].t || a[i].P != b[i].P || a[i].T != b[i].T || a[i].KE != b[i].KE ||
        a[i].PE != b[i].PE || a[i].E != b[i].E || a[i].hits != b[i].hits || a[i].R != b[i].R)
      return false;
  return true;
}

bool same_stages(const std::vector<Stage>& a, const std::vector<Stage>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].R != b[i].R || a[i].V != b[i].V || a[i].P != b[i].P || a[i].T != b[i].T ||
        a[i].E != b[i].E || a[i].hits != b[i].hits)
      return false;
  return true;
}

/// Runs the timeline to its end once, noting the hashes every `every` steps, then seeks to
/// those steps in a scrambled order (back and forth) and plays the whole run again from the
/// start: every state, sample and stage must be the first pass's to the last bit, and the
/// first pass must be what a plain run without snapshots computes.
void check_seeks_land_on_first_pass(const System& initial, const RunPlan& plan,
                                    const std::vector<Method>& compared, long every) {
  TimelineLimits limits;
  limits.max_snapshots = 6;  // thin several times
  Timeline timeline(initial, plan, compared, limits);
  std::map<long, std::vector<std::uint64_t>> first_pass;
  first_pass[0] = hashes(timeline.present());
  while (!timeline.finished()) {
    timeline.advance(every);
    first_pass[timeline.step()] = hashes(timeline.present());
  }
  CHECK(timeline.reached() == plan.steps);
  CHECK(timeline.snapshot_count() <= 6);
  const std::vector<Sample> samples = timeline.present().primary().samples();
  const std::vector<Stage> stages = timeline.present().primary().stages();

  SideBySide plain(initial, plan, compared);
  plain.finish();
  CHECK(hashes(plain) == first_pass[plan.steps]);
  CHECK(same_samples(plain.primary().samples(), samples));

  std::vector<long> order;
  for (const auto& entry : first_pass) order.push_back(entry.first);
  for (std::size_t i = 0; i < order.size(); ++i)  // a fixed scramble
    std::swap(order[i], order[(i * 7 + 3) % order.size()]);
  for (long step : order) {
    CAPTURE(step);
    REQUIRE(timeline.seek(step) == step);
    CHECK(hashes(timeline.present()) == first_pass[step]);
    CHECK(timeline.reached() == plan.steps);
  }
  timeline.seek(0);
  CHECK(timeline.present().primary().samples().size() == 1);
  timeline.seek(plan.steps);
  CHECK(hashes(timeline.present()) == first_pass[plan.steps]);
  CHECK(same_samples(timeline.present().primary().samples(), samples));
  CHECK(same_stages(timeline.present().primary().stages(), stages));
}

RunPlan plan_for(Method method, std::optional<double> R, double dt, long steps) {
  RunPlan plan;
  plan.engine.method = method;
  plan.engine.container_radius = R;
  plan.dt = dt;
  plan.steps = steps;
  plan.sample_every = 50;
  plan.stages_by_hand = true;
  return plan;
}

}  // namespace

TEST_CASE("seeking back and forth lands on the first pass to the last bit") {
  SUBCASE("fast engine in a container, J > 0") {
    check_seeks_land_on_first_pass(crowded_swarm(1000, +1.0, 3),
                                   plan_for(Method::analytic, 1.0, 1e-3, 3000), {}, 97);
  }
  SUBCASE("fast engine in a container, J < 0 (anchors renewed every few steps)") {
    check_seeks_land_on_first_pass(crowded_swarm(1000, -1.0, 5),
                                   plan_for(Method::analytic, 1.0, 1e-3, 3000), {}, 97);
  }
  SUBCASE("reference engine: exact collisions") {
    RunPlan plan = plan_for(Method::analytic, 1.0, 1e-3, 2000);
    plan.engine.collisions = CollisionMode::exact;
    check_seeks_land_on_first_pass(crowded_swarm(200, +1.0, 7), plan, {}, 89);
  }
  SUBCASE("numerical methods side by side in a container") {
    check_seeks_land_on_first_pass(crowded_swarm(40, +1.0, 9),
                                   plan_for(Method::verlet, 1.0, 1e-3, 2000),
                                   {Method::analytic, Method::rk4}, 101);
  }
  SUBCASE("isolated, Euler against the exact solution") {
    check_seeks_land_on_first_pass(testing::four_masses(),
                                   plan_for(Method::euler, std::nullopt, 0.01, 3000),
                                   {Method::analytic}, 113);
  }
}

TEST_CASE("an isolated system sought to any time is the analytic solution there") {
  const System initial = testing::four_masses(0.5);
  const RunPlan plan = plan_for(Method::analytic, std::nullopt, 0.01, 6000);
  Timeline timeline(initial, plan, {});
  const AnalyticSolution exact(initial);
  for (long step : {4000L, 250L, 5999L, 0L, 3001L, 6000L, 17L}) {
    CAPTURE(step);
    timeline.seek(step);
    const System& s = timeline.present().primary().engine().system();
    const System expected = exact.at(s.t);
    CHECK(s.t == doctest::Approx(double(step) * plan.dt).epsilon(1e-12));
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      CHECK((s.particles[i].r - expected.particles[i].r).norm() < 1e-11);
      CHECK((s.particles[i].v - expected.particles[i].v).norm() < 1e-11);
    }
  }
  CHECK(timeline.step_of(12.34) == 1234);
  CHECK(timeline.step_of(-3) == 0);
  CHECK(timeline.step_of(1e30) == plan.steps);
}

TEST_CASE("fast-forward of the Fig. 2 expansion gives the stages of swarmlab run") {
  const Preset preset = shipped_preset("fig2-attractive-expansion.json");
  const System initial = initial_system(preset);
  RunPlan plan = run_plan(preset);
  Run cli(initial, plan);  // what `swarmlab run` does
  cli.finish();
  plan.stages_by_hand = true;  // as the window's runs are
  Timeline timeline(initial, plan, preset.compare);
  // Chunks of uneven length, as the frames' time budget gives them.
  for (long chunk = 1; !timeline.finished(); chunk = chunk * 3 % 20011 + 1) timeline.advance(chunk);
  CHECK(timeline.present().primary().stages().size() == std::size_t(preset.expansion->stages));
  CHECK(same_stages(timeline.present().primary().stages(), cli.stages()));
  CHECK(same_samples(timeline.present().primary().samples(), cli.samples()));
  CHECK(state_hash(timeline.present().primary().engine().system()) ==
        state_hash(cli.engine().system()));
  // To the end of the third stage from the middle of the second.
  timeline.seek(15000);
  CHECK(timeline.end_of_stage() == 20000);
  timeline.seek(timeline.end_of_stage());
  CHECK(same_stages(timeline.present().primary().stages(),
                    {cli.stages().begin(), cli.stages().begin() + 2}));
}

TEST_CASE("stages by hand are averaged like the protocol's stages") {
  const System initial = crowded_swarm(600, +1.0, 11);
  RunPlan protocol_plan = plan_for(Method::analytic, 1.0, 1e-3, 0);
  protocol_plan.expansion = ExpansionProtocol{1.05, 4, 0.5, 0.8};
  protocol_plan.steps = 4 * steps_per_stage(*protocol_plan.expansion, protocol_plan.dt);
  protocol_plan.stages_by_hand = false;
  Run protocol(initial, protocol_plan);
  protocol.finish();
  REQUIRE(protocol.stages().size() == 4);

  // A fixed container expanded by hand at the protocol's times.
  const RunPlan fixed = plan_for(Method::analytic, 1.0, 1e-3, protocol_plan.steps);
  SUBCASE("a run") {
    Run by_hand(initial, fixed);
    for (int k = 0; k < 4; ++k) {
      by_hand.advance(500);
      by_hand.expand_now(1.05);
    }
    REQUIRE(by_hand.stages().size() == 4);
    CHECK(same_stages(by_hand.stages(), protocol.stages()));
    for (const Stage& s : by_hand.stages()) CHECK(s.by_hand);
    CHECK(by_hand.stage_by_hand_start() == 2000);
  }
  SUBCASE("a timeline, scrubbed back and played again") {
    Timeline timeline(initial, fixed, {});
    for (int k = 0; k < 3; ++k) {
      timeline.advance(500);
      timeline.expand_now(1.05);
    }
    timeline.advance(10000);
    CHECK(timeline.stage_starts() == std::vector<long>{0, 500, 1000, 1500});
    CHECK(timeline.end_of_stage() == 2000);
    timeline.seek(700);
    CHECK(timeline.present().primary().stages().size() == 1);
    CHECK(timeline.end_of_stage() == 1000);
    timeline.seek(2000);
    timeline.present().scale_container(1.05);  // the last, as above
    CHECK(same_stages(timeline.present().primary().stages(), protocol.stages()));
  }
  SUBCASE("a new expansion after a seek back replaces the future") {
    Timeline timeline(initial, fixed, {});
    timeline.advance(1500);
    timeline.seek(600);
    timeline.expand_now(1.2);
    CHECK(timeline.reached() == 600);
    CHECK(timeline.present().primary().engine().container_radius() == doctest::Approx(1.2));
    timeline.seek(300);
    timeline.seek(1000);
    CHECK(timeline.present().primary().engine().container_radius() == doctest::Approx(1.2));
    CHECK(timeline.present().primary().stages().size() == 1);
  }
}

TEST_CASE("after the protocol's end a stage by hand covers the steps since, averaged") {
  RunPlan plan = plan_for(Method::analytic, 1.0, 1e-3, 0);
  plan.expansion = ExpansionProtocol{1.05, 2, 0.3, 0.8};
  plan.steps = 600;
  Run run(crowded_swarm(600, +1.0, 13), plan);
  run.finish();
  REQUIRE(run.stages().size() == 2);
  CHECK(run.stage_by_hand_start() == 600);
  run.extend(1000);
  CHECK_FALSE(run.finished());
  // The window by hand, independently: the last 200 of the 1,000 steps to come.
  Run copy(run);
  const double R = *run.engine().container_radius();
  WallMeter meter;
  for (int i = 0; i < 1000; ++i) {
    const WallTally tally = copy.engine().step(plan.dt);
    if (i >= 800) meter.add(tally, plan.dt, sphere_area(R));
  }
  run.finish();
  CHECK(run.steps_done() == 1600);
  run.expand_now(1.1);
  REQUIRE(run.stages().size() == 3);
  const Stage& s = run.stages().back();
  CHECK(s.by_hand);
  CHECK(s.R == R);
  CHECK(s.hits == meter.reading().hits);
  CHECK(s.hits > 0);
  CHECK(s.P == meter.reading().P);
  CHECK(s.T == meter.reading().T);
  CHECK(*run.engine().container_radius() == doctest::Approx(1.1 * R));
}

TEST_CASE("a finished run continued through the timeline replays its extension") {
  const RunPlan plan = plan_for(Method::analytic, 1.0, 1e-3, 500);
  Timeline timeline(crowded_swarm(300, +1.0, 17), plan, {});
  timeline.advance(10000);
  REQUIRE(timeline.finished());
  timeline.extend(500);
  CHECK(timeline.end_step() == 1000);
  timeline.advance(10000);
  CHECK(timeline.step() == 1000);
  const auto end = hashes(timeline.present());
  const auto samples = timeline.present().primary().samples();
  timeline.seek(200);
  CHECK(timeline.end_step() == 1000);
  timeline.seek(1000);
  CHECK(hashes(timeline.present()) == end);
  CHECK(same_samples(timeline.present().primary().samples(), samples));
}
