#include "ui/input/region_cycle.h"

#include <doctest/doctest.h>

using namespace swarmlab;

TEST_CASE("region_cycle: F6 walks the regions shown in order and wraps around") {
  // Controls, drawer (hidden: the wide layout), transport, view, read-outs, timeline, plots.
  const std::vector<bool> shown = {true, false, true, true, true, true, true};
  CHECK(next_region(0, shown, +1) == 2u);  // the hidden drawer is passed over
  CHECK(next_region(2, shown, +1) == 3u);
  CHECK(next_region(6, shown, +1) == 0u);  // from the plots back to the controls
  CHECK(next_region(0, shown, -1) == 6u);  // Shift+F6 goes back
  CHECK(next_region(2, shown, -1) == 0u);
}

TEST_CASE("region_cycle: from a dialog F6 starts at the first region, Shift+F6 at the last") {
  const std::vector<bool> shown = {false, true, true, true};
  CHECK(next_region(std::nullopt, shown, +1) == 1u);
  CHECK(next_region(std::nullopt, shown, -1) == 3u);
}

TEST_CASE("region_cycle: one region stays, none gives none") {
  CHECK(next_region(1, {false, true, false}, +1) == 1u);
  CHECK_FALSE(next_region(0, {false, false}, +1).has_value());
  CHECK_FALSE(next_region(std::nullopt, {}, -1).has_value());
}
