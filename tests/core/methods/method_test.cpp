#include "swarm/methods/method.h"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "swarm/physics/system.h"
#include "test_systems.h"

using namespace swarm;
using doctest::Approx;
using swarm::testing::two_body_circle;

namespace {

constexpr Method kEveryMethod[] = {Method::analytic, Method::euler, Method::euler_cromer,
                                   Method::verlet, Method::rk4};

/// Distance of particle 0 from its exact position after `steps` steps of the method to t_end.
double error_after(const MethodInfo& method, double t_end, int steps) {
  System s = two_body_circle();
  for (int i = 0; i < steps; ++i) method.step(s, t_end / steps, 1);
  const double w = std::sqrt(2.0);
  const Vec3 exact(0.5 * std::cos(w * t_end), 0.5 * std::sin(w * t_end), 0);
  return (s.particles[0].r - exact).norm();
}

/// docs/physics.md's method table: the lines after its header row, up to the first non-table line.
std::vector<std::string> documented_method_rows() {
  // The presets live in assets/presets/ of the repository, docs/physics.md beside them.
  std::ifstream in(SWARM_PRESET_DIR "/../../docs/physics.md");
  REQUIRE(in);
  std::vector<std::string> rows;
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.rfind("| method | order | cost per step |", 0) == 0) {
      inside = true;
      std::getline(in, line);  // the |---| separator
      continue;
    }
    if (!inside) continue;
    if (line.empty() || line[0] != '|') break;
    rows.push_back(line);
  }
  return rows;
}

}  // namespace

TEST_CASE("every method has exactly one row, in the enum's order") {
  const auto& table = method_table();
  REQUIRE(table.size() == std::size(kEveryMethod));
  for (std::size_t i = 0; i < table.size(); ++i) {
    CHECK(table[i].id == kEveryMethod[i]);
    CHECK(&info_of(kEveryMethod[i]) == &table[i]);
    CHECK(bool(table[i].step));
    CHECK(!table[i].description.empty());
    CHECK(!table[i].display_name.empty());
  }
}

TEST_CASE("method names are unique and round-trip through the parser") {
  std::set<std::string_view> names, shown;
  for (const MethodInfo& m : method_table()) {
    CHECK(names.insert(m.name).second);
    CHECK(shown.insert(m.display_name).second);
    CHECK(method_named(m.name) == m.id);
    CHECK(name_of(m.id) == m.name);
  }
  CHECK(!method_named("leapfrog"));
  CHECK(method_names_listed() == "analytic, euler, euler-cromer, verlet or rk4");
}

TEST_CASE("only the analytic map avoids the pairwise sum") {
  for (const MethodInfo& m : method_table()) CHECK(m.pairwise == (m.id != Method::analytic));
}

TEST_CASE("each step function has its stated order on a two-body circular orbit") {
  // Not a whole period: there Euler-Cromer's first-order phase error happens to cancel.
  const double t_end = 0.37 * 2 * M_PI / std::sqrt(2.0);
  for (const MethodInfo& m : method_table()) {
    CAPTURE(m.name);
    if (m.order == 0) {
      // The exact map: any dt, rounding only.
      CHECK(error_after(m, t_end, 7) < 1e-13);
      continue;
    }
    // Enough steps that the error is in its asymptotic regime, few enough that rounding
    // stays far below it (rk4 at 40 steps: error about 1e-7).
    const int steps = m.order >= 4 ? 40 : m.order == 2 ? 400 : 4000;
    const double coarse = error_after(m, t_end, steps), fine = error_after(m, t_end, 2 * steps);
    CHECK(std::log2(coarse / fine) == Approx(m.order).epsilon(0.05));
  }
}

TEST_CASE("docs/physics.md's method table lists exactly the descriptors, in their order") {
  const std::vector<std::string> rows = documented_method_rows();
  const auto& table = method_table();
  REQUIRE(rows.size() == table.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    const MethodInfo& m = table[i];
    std::ostringstream expected;
    expected << "| `" << m.name << "` | "
             << (m.order == 0 ? std::string("exact") : std::to_string(m.order)) << " | "
             << (m.pairwise ? "O(N^2)" : "O(N)") << " | " << m.description << " |";
    CHECK(rows[i] == expected.str());
  }
}
