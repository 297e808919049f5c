#include "report/run_csv.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

using namespace swarmlab;

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

/// The numbers of a row of quoted numeric fields ("0.5","-1.25"); NAN for a field that is not
/// one quoted number.
std::vector<double> numbers_of(const std::string& line) {
  std::vector<double> out;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, ',');) {
    const bool quoted = field.size() >= 2 && field.front() == '"' && field.back() == '"';
    out.push_back(quoted ? std::strtod(field.substr(1, field.size() - 2).c_str(), nullptr) : NAN);
  }
  return out;
}

}  // namespace

TEST_CASE("the samples CSV has the CLI's columns and re-reads every value exactly") {
  std::vector<swarm::Sample> samples(2);
  samples[0] = {0.1, 1.0 / 3, 2.0 / 7, 0.5, -1.25, -0.75, 3, 1.5, {0.25, -1.0 / 7, 0.125}, 0.3, 0.7};
  samples[1] = {0.2, 1e-300, 6.02e23, 1.0 / 9, -2.0 / 3, -5.0 / 9, 12, 1.5, {}, -2.5, 1.0 / 3};
  samples[0].T_kinetic = 1.0 / 3;
  samples[1].T_kinetic = 2.0 / 11;
  const std::vector<std::string> lines = lines_of(report::samples_csv(samples));
  REQUIRE(lines.size() == 3);
  // The header tests/cli/cli_test.sh pins for `swarmlab run --csv`.
  CHECK(lines[0] ==
        R"("t","P","T","KE","PE","E","hits","R","work","heat","drag_loss","cm_height","size","T_kinetic")");
  for (int i = 0; i < 2; ++i) {
    const swarm::Sample& s = samples[std::size_t(i)];
    const std::vector<double> v = numbers_of(lines[std::size_t(i) + 1]);
    REQUIRE(v.size() == 14);
    CHECK(v[0] == s.t);
    CHECK(v[1] == s.P);
    CHECK(v[2] == s.T);
    CHECK(v[3] == s.KE);
    CHECK(v[4] == s.PE);
    CHECK(v[5] == s.E);
    CHECK(v[6] == double(s.hits));
    CHECK(v[7] == s.R);
    CHECK(v[8] == s.books.wall_work);
    CHECK(v[9] == s.books.wall_heat);
    CHECK(v[10] == s.books.drag_loss);
    CHECK(v[11] == s.cm_height);
    CHECK(v[12] == s.size);
    CHECK(v[13] == s.T_kinetic);
  }
}

TEST_CASE("the stages CSV has RESULT.json's stage keys in order") {
  std::vector<swarm::Stage> stages(1);
  stages[0] = {2.0, 33.510321638291124, 0.1 / 3, 1.0 / 7, -0.5, 41};
  stages[0].T_kinetic = 3.0 / 7;
  const std::vector<std::string> lines = lines_of(report::stages_csv(stages));
  REQUIRE(lines.size() == 2);
  CHECK(lines[0] == R"("R","V","P","T","E","hits","T_kinetic")");
  const std::vector<double> v = numbers_of(lines[1]);
  REQUIRE(v.size() == 7);
  CHECK(v[0] == 2.0);
  CHECK(v[1] == 33.510321638291124);
  CHECK(v[2] == 0.1 / 3);
  CHECK(v[3] == 1.0 / 7);
  CHECK(v[4] == -0.5);
  CHECK(v[5] == 41.0);
  CHECK(v[6] == 3.0 / 7);
  CHECK(lines_of(report::stages_csv({})).size() == 1);  // the header alone
}
