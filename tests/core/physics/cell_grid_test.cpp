// The cell grid finds every close pair, each once, whatever the extent of the particles.

#include <doctest/doctest.h>

#include <set>
#include <utility>

#include "physics/cell_grid.h"
#include "swarm/preset/initial_conditions.h"

using namespace swarm;

TEST_CASE("CellGrid: every pair closer than the cell side is visited exactly once") {
  for (double radius : {1.0, 50.0}) {  // 50: the cap on cells makes cells wider than the side
    CAPTURE(radius);
    SwarmSpec spec;
    spec.count = 700;
    spec.position_radius = radius;
    spec.seed = 8;
    const System s = generate_swarm(spec);
    const double side = radius == 1.0 ? 0.15 : 3.0;
    std::set<std::pair<std::uint32_t, std::uint32_t>> close, visited;
    for (std::uint32_t i = 0; i < s.particles.size(); ++i)
      for (std::uint32_t j = i + 1; j < s.particles.size(); ++j)
        if ((s.particles[i].r - s.particles[j].r).norm() < side) close.insert({i, j});
    CellGrid grid;
    grid.build(s.particles, side);
    long visits = 0;
    grid.for_each_neighbour_pair([&](std::uint32_t i, std::uint32_t j) {
      ++visits;
      visited.insert({std::min(i, j), std::max(i, j)});
    });
    CHECK(long(visited.size()) == visits);  // no pair twice
    for (const auto& pair : close) CHECK(visited.count(pair) == 1);
    CHECK(!close.empty());
    CHECK(grid.cells_per_side() <= 12);  // the smallest c with c^3 >= 2 N = 1,400
  }
}
