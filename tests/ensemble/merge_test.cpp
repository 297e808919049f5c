#include "ensemble/merge.h"

#include <doctest/doctest.h>

#include <stdlib.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "ensemble/ensemble_member.h"
#include "files/atomic_file.h"
#include "files/text_file.h"
#include "swarm/physics/wall.h"
#include "swarm/preset/ensemble_seed.h"

using namespace swarmlab::ensemble;
namespace fs = std::filesystem;

namespace {

/// A new folder of its own under /tmp: two suites running at once (two engineers on one
/// machine) never share one.
std::string merge_scratch_dir(const std::string& stem) {
  std::string name = (fs::temp_directory_path() / (stem + ".XXXXXX")).string();
  REQUIRE(::mkdtemp(name.data()) != nullptr);
  return name;
}

/// An ideal gas (J = 0) of n particles at T = 1 in the unit ball, starting in equilibrium.
swarm::Preset ideal_gas(long n, double duration) {
  swarm::Preset p;
  p.J = 0;
  swarm::SwarmSpec spec;
  spec.count = n;
  spec.position_radius = 0.999;
  spec.velocities = swarm::SwarmSpec::Velocities::maxwell;
  spec.temperature = 1;
  spec.cm_at_rest = true;
  p.particles = spec;
  p.container_radius = 1.0;
  p.dt = 1e-3;
  p.duration = duration;
  return p;
}

/// Runs `runs` members of an ensemble of p with master seed `seed` into dir, as swarmlab
/// ensemble does, and merges them.
nlohmann::json ensemble_report(const swarm::Preset& p, long runs, std::uint64_t seed,
                               const std::string& dir) {
  fs::remove_all(dir);
  fs::create_directories(dir + "/runs");
  const EnsemblePlan plan{{{"{}", preset_hash(p)}}, runs, seed, 0.0, program_version()};
  REQUIRE(swarmlab::write_file_atomically(plan_path(dir), plan_json(plan)).empty());
  for (long k = 0; k < runs; ++k) {
    const std::uint64_t s = swarm::run_seed(seed, std::uint64_t(k));
    const swarm::SeededPreset seeded = swarm::with_seed(p, s, 0);
    REQUIRE(seeded.preset);
    REQUIRE(run_member(*seeded.preset, {k, s, plan.points[0].preset_hash, plan.version, 0.0},
                       run_path(dir, k), 1)
                .empty());
  }
  const MergeReport m = merge_ensemble(dir);
  REQUIRE(m.error.empty());
  return nlohmann::json::parse(m.json);
}

}  // namespace

TEST_CASE("ensemble coverage: 95 % intervals of an ideal gas's pressure hold P V = 2 KE / 3") {
  // For J = 0 the walls are elastic and the kinetic energy stays as drawn; in equilibrium the
  // time-averaged wall pressure is 2 KE / (3 V), and over seeds E[KE] = 3/2 (N - 1) T (the CM's
  // velocity taken away), so the true mean pressure is (N - 1) T / V. 200 ensembles of 6 runs:
  // the intervals should hold it in about 95 % of them (the binomial's sd: 1.5 %).
  const long n = 100;
  const swarm::Preset gas = ideal_gas(n, 1.0);
  const double truth = double(n - 1) * 1.0 / swarm::sphere_volume(1.0);
  const std::string dir = merge_scratch_dir("swarmlab-coverage-test");
  int held = 0;
  const int ensembles = 200;
  double ratio_sum = 0, mean_sum = 0, sd_sum = 0;
  for (int e = 0; e < ensembles; ++e) {
    const nlohmann::json r = ensemble_report(gas, 6, std::uint64_t(1000 + e), dir);
    const auto& P = r["quantities"]["P"];
    held += P["ci95"][0].get<double>() <= truth && truth <= P["ci95"][1].get<double>();
    ratio_sum += P["spread_ratio"].get<double>();
    mean_sum += P["mean"].get<double>();
    sd_sum += P["sd"].get<double>();
  }
  CAPTURE(mean_sum / ensembles);
  CAPTURE(sd_sum / ensembles);
  CAPTURE(truth);
  fs::remove_all(dir);
  const double coverage = double(held) / ensembles;
  CAPTURE(coverage);
  CAPTURE(ratio_sum / ensembles);
  CHECK(coverage >= 0.90);
  CHECK(coverage <= 0.99);
}

TEST_CASE("merge: the report's numbers are the runs' numbers, summarised") {
  const swarm::Preset gas = ideal_gas(60, 0.3);
  const std::string dir = merge_scratch_dir("swarmlab-merge-test");
  const nlohmann::json r = ensemble_report(gas, 5, 7, dir);
  CHECK(r["runs"] == 5);
  CHECK(r["planned"] == 5);
  const auto& P = r["quantities"]["P"];
  std::vector<double> v = P["values"].get<std::vector<double>>();
  REQUIRE(v.size() == 5);
  double mean = 0;
  for (double x : v) mean += x / 5;
  double ss = 0;
  for (double x : v) ss += (x - mean) * (x - mean);
  const double sd = std::sqrt(ss / 4);
  CHECK(P["mean"].get<double>() == doctest::Approx(mean).epsilon(1e-12));
  CHECK(P["sd"].get<double>() == doctest::Approx(sd).epsilon(1e-12));
  // t(0.975, 4) = 2.776445 (printed tables).
  CHECK(P["ci95"][1].get<double>() - mean == doctest::Approx(2.776445 * sd / std::sqrt(5.0)).epsilon(1e-6));
  // T kinetic beside the wall's T: a quantity, and a band whose mean is the runs' mean.
  double last_T_kinetic = 0;
  for (long k = 0; k < 5; ++k) {
    std::string error;
    const RecordRead rec = parse_record(swarmlab::read_text_file(run_path(dir, k), error));
    REQUIRE(rec.record);
    last_T_kinetic += rec.record->T_kinetic.back() / 5;
  }
  const auto& band = r["bands"]["time"]["T_kinetic"]["mean"];
  CHECK(band.back().get<double>() == doctest::Approx(last_T_kinetic).epsilon(1e-12));
  CHECK(r["quantities"].contains("T_kinetic"));
  // A run deleted: listed as missing, the others still merged.
  fs::remove(run_path(dir, 2));
  const nlohmann::json partial = nlohmann::json::parse(merge_ensemble(dir).json);
  CHECK(partial["runs"] == 4);
  CHECK(partial["missing"] == nlohmann::json::array({2}));
  fs::remove_all(dir);
}
