#include "ensemble/run_record.h"

#include <doctest/doctest.h>

#include "swarm/preset/initial_conditions.h"

using namespace swarmlab::ensemble;

namespace {

swarm::Run gas_run(long steps) {
  swarm::SwarmSpec spec;
  spec.count = 100;
  spec.position_radius = 0.99;
  spec.velocities = swarm::SwarmSpec::Velocities::maxwell;
  spec.cm_at_rest = true;
  swarm::System s = swarm::generate_swarm(spec);
  s.J = 0;
  swarm::RunPlan plan;
  plan.engine.container_radius = 1.0;
  plan.steps = steps;
  plan.sample_every = 2;
  swarm::Run run(s, plan);
  run.finish();
  return run;
}

}  // namespace

TEST_CASE("run record: written and read back whole, the series an exact thinning of the samples") {
  swarm::Run run = gas_run(2000);  // 1,000 samples into 200 points of 5 intervals each
  const RunRecord r = record_of({3, 99, "00ff", "abc", 0.0}, run);
  REQUIRE(r.values.count("P"));
  REQUIRE(r.values.at("P").se);
  CHECK(r.values.count("energy_drift"));
  REQUIRE(r.t.size() == kSeriesPoints);
  // Point 0 is the wall average of intervals 0-4: the impulse over 5 intervals of 2 steps.
  const auto intervals = swarm::wall_intervals(run.samples());
  double P = 0;
  for (int i = 0; i < 5; ++i) P += intervals[std::size_t(i)].reading.P / 5;
  CHECK(r.P[0] == doctest::Approx(P).epsilon(1e-12));
  CHECK(r.t[0] == doctest::Approx(0.01));
  CHECK(r.t.back() == doctest::Approx(2.0));

  const RecordRead back = parse_record(record_json(r));
  REQUIRE(back.record);
  CHECK(back.record->id.seed == 99);
  CHECK(back.record->id.index == 3);
  CHECK(back.record->values.at("P").value == r.values.at("P").value);  // to the bit
  CHECK(*back.record->values.at("P").se == *r.values.at("P").se);
  CHECK(back.record->P == r.P);
}

TEST_CASE("run record: a cut or altered file is refused, naming what is wrong") {
  swarm::Run run = gas_run(200);
  const std::string text = record_json(record_of({0, 1, "00ff", "abc", 0.0}, run));
  CHECK(parse_record(text.substr(0, text.size() / 2)).error.find("not a complete JSON object") == 0);
  CHECK(parse_record("{\"format\": \"something else\"}").error.find("format:") == 0);
  std::string other = text;
  other.replace(other.find("\"format_version\":1"), 18, "\"format_version\":7");
  CHECK(parse_record(other).error.find("format_version: 7") == 0);
  std::string bad_seed = text;
  bad_seed.replace(bad_seed.find("\"seed\":1"), 8, "\"seed\":-1");
  CHECK(parse_record(bad_seed).error.find("seed:") == 0);
}
