#include "ensemble/run_record.h"

#include <doctest/doctest.h>

#include <cmath>
#include <nlohmann/json.hpp>

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
  // T kinetic: each point the mean of the (2/3) KE / N of the samples ending its intervals;
  // the window's value, for an ideal gas whose speeds the walls keep, (2/3) KE / N less the
  // CM's share (|p|^2 / 2M, of order KE / N: 1 % with 100 particles).
  double T_kinetic = 0;
  for (int i = 1; i <= 5; ++i) T_kinetic += run.samples()[std::size_t(i)].T_kinetic / 5;
  CHECK(r.T_kinetic[0] == doctest::Approx(T_kinetic).epsilon(1e-12));
  REQUIRE(r.T_kinetic.size() == kSeriesPoints);
  REQUIRE(r.values.count("T_kinetic"));
  const double KE = run.samples().front().KE;  // J = 0 and specular walls: constant
  CHECK(r.values.at("T_kinetic").value == doctest::Approx(2.0 / 3 * KE / 100).epsilon(0.03));
  CHECK(r.values.at("T_kinetic").value < 2.0 / 3 * KE / 100);

  const RecordRead back = parse_record(record_json(r));
  REQUIRE(back.record);
  CHECK(back.record->id.seed == 99);
  CHECK(back.record->id.index == 3);
  CHECK(back.record->values.at("P").value == r.values.at("P").value);  // to the bit
  CHECK(*back.record->values.at("P").se == *r.values.at("P").se);
  CHECK(back.record->P == r.P);
  CHECK(back.record->T_kinetic == r.T_kinetic);
}

TEST_CASE("run record: a cut or altered file is refused, naming what is wrong") {
  swarm::Run run = gas_run(200);
  const std::string text = record_json(record_of({0, 1, "00ff", "abc", 0.0}, run));
  CHECK(parse_record(text.substr(0, text.size() / 2)).error.find("not a complete JSON object") == 0);
  CHECK(parse_record("{\"format\": \"something else\"}").error.find("format:") == 0);
  std::string other = text;
  other.replace(other.find("\"format_version\":4"), 18, "\"format_version\":7");
  CHECK(parse_record(other).error.find("format_version: 7") == 0);
  std::string bad_seed = text;
  // The record's own seed (keys in byte order: "series" follows), not provenance.seeds'.
  bad_seed.replace(bad_seed.find("\"seed\":1,\"series\""), 8, "\"seed\":-1");
  CHECK(parse_record(bad_seed).error.find("seed:") == 0);
}

TEST_CASE("run record: the digest is over the documented canonical text") {
  RunRecord r;
  r.id = {4, 18446744073709551615ULL, "00ff", "v1", 0.25};
  r.failure = "a:b";
  r.equilibration_start = 0.5;
  r.values["P"] = {-1.5, 0.125};
  r.values["T"] = {1.0 / 3, std::nullopt};
  r.t = {1, 2};
  r.P = {0.5, 1e300};
  r.T = {NAN, 2};
  r.R = {1, 1};
  r.T_kinetic = {0.25, NAN};
  r.made_by = {"v1", "c0ffee", false, "GCC 1", "Linux 6", "x86_64", "2026-12-07T18:00:00Z",
               {18446744073709551615ULL, std::nullopt, 0}};
  // The text run_record.h describes, written out by hand.
  CHECK(canonical_text(r) ==
        "swarmlab ensemble run 4\n"
        "swarmlab 2:v1\n"
        "preset_hash 4:00ff\n"
        "index 4\n"
        "seed 18446744073709551615\n"
        "perturbation 0.25\n"
        "failure 3:a:b\n"
        "equilibration_start 0.5\n"
        "provenance 2:v1 6:c0ffee false 5:GCC 1 7:Linux 6 6:x86_64 20:2026-12-07T18:00:00Z\n"
        "provenance.seeds 18446744073709551615 - 0\n"
        "value 1:P -1.5 0.125\n"
        "value 1:T 0.33333333333333331 -\n"
        "series.t 2 1 2\n"
        "series.P 2 0.5 1.0000000000000001e+300\n"
        "series.T 2 null 2\n"
        "series.R 2 1 1\n"
        "series.T_kinetic 2 0.25 null\n"
        "stages.V 0\n"
        "stages.P 0\n"
        "stages.T 0\n"
        "stages.T_kinetic 0\n");
  // sha256 of that text, from Python's hashlib.
  CHECK(record_digest(r) == "sha256:7611cd72b3024786e98b38a2fbcb2b69aa16164f22cddea51841c5ddac20732e");
}

TEST_CASE("run record: an edited value is refused by its digest, a re-laid-out file is not") {
  swarm::Run run = gas_run(200);
  const RunRecord r = record_of({0, 1, "00ff", "abc", 0.0}, run);
  nlohmann::json j = nlohmann::json::parse(record_json(r));
  // Pretty-printed: the same values, so the same digest.
  CHECK(parse_record(j.dump(2)).record.has_value());
  // P times 10, in valid JSON: what a hand edit does.
  j["values"]["P"]["value"] = j["values"]["P"]["value"].get<double>() * 10;
  CHECK(parse_record(j.dump()).error ==
        "digest: does not match the record's contents (edited by hand or damaged)");
  j.erase("digest");
  CHECK(parse_record(j.dump()).error == "digest: missing or not text");
}

TEST_CASE("run record: what made it is read back, and an edited provenance is refused") {
  swarm::Run run = gas_run(200);
  const RunRecord r = record_of({0, 7, "00ff", "abc", 0.0}, run);
  CHECK(r.made_by.seeds.seed == std::optional<std::uint64_t>(7));  // the run's seed
  CHECK(!r.made_by.compiler.empty());
  const RecordRead back = parse_record(record_json(r));
  REQUIRE(back.record);
  CHECK(back.record->made_by.date == r.made_by.date);
  CHECK(back.record->made_by.os == r.made_by.os);
  nlohmann::json j = nlohmann::json::parse(record_json(r));
  // Another date or host, in valid JSON: the digest covers them.
  for (const char* key : {"date", "compiler"}) {
    nlohmann::json edited = j;
    edited["provenance"][key] = std::string(key) == "date" ? "2020-01-01T00:00:00Z" : "GCC 0";
    CHECK(parse_record(edited.dump()).error ==
          "digest: does not match the record's contents (edited by hand or damaged)");
  }
  nlohmann::json edited = j;
  edited["provenance"]["host"]["os"] = "Plan 9";
  CHECK(parse_record(edited.dump()).error.find("digest:") == 0);
  edited.erase("provenance");
  CHECK(parse_record(edited.dump()).error == "provenance: missing or not an object");
}
