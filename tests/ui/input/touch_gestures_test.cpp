#include "ui/input/touch_gestures.h"

#include <doctest/doctest.h>

using namespace swarmlab;

TEST_CASE("touch_gestures: a tap on the view selects, it does not orbit") {
  TouchGestures g;
  g.down(1, 100, 100, true, 0.0);
  g.move(1, 103, 101);  // a fingertip wobbles by a few pixels
  g.up(1, 103, 101);
  const TouchFrame f = g.frame(0.1);
  CHECK(f.tap);
  CHECK(f.tap_x == 103);
  CHECK(f.orbit_dx == 0);
  CHECK(f.orbit_dy == 0);
  CHECK_FALSE(f.pointer);  // ImGui's mouse is not pressed on the view
  CHECK_FALSE(g.frame(0.2).tap);
}

TEST_CASE("touch_gestures: one finger dragged on the view orbits by its motion past the slop") {
  TouchGestures g;
  g.down(1, 100, 100, true, 0.0);
  g.move(1, 120, 100);  // leaves the slop: the orbit starts here
  g.move(1, 150, 90);
  TouchFrame f = g.frame(0.1);
  CHECK(f.orbit_dx == doctest::Approx(30));
  CHECK(f.orbit_dy == doctest::Approx(-10));
  g.up(1, 150, 90);
  f = g.frame(0.2);
  CHECK_FALSE(f.tap);
  CHECK(f.orbit_dx == 0);
}

TEST_CASE("touch_gestures: two fingers pinch to zoom and drag to pan") {
  TouchGestures g;
  g.down(1, 100, 100, true, 0.0);
  g.down(2, 200, 100, true, 0.0);
  g.move(1, 50, 100);
  g.move(2, 250, 100);  // 100 px apart -> 200 px apart
  TouchFrame f = g.frame(0.1);
  CHECK(f.zoom == doctest::Approx(2.0));
  CHECK(f.orbit_dx == 0);
  CHECK(f.pan_dx == doctest::Approx(0).epsilon(1e-6));
  g.move(1, 50, 140);
  g.move(2, 250, 140);  // both down by 40: the midpoint moves 40
  f = g.frame(0.2);
  CHECK(f.zoom == doctest::Approx(1.0));
  CHECK(f.pan_dy == doctest::Approx(40));
  // Lifting one finger neither taps nor turns the remaining one into an orbit.
  g.up(2, 250, 140);
  g.move(1, 90, 180);
  g.up(1, 90, 180);
  f = g.frame(0.3);
  CHECK_FALSE(f.tap);
  CHECK(f.orbit_dx == 0);
}

TEST_CASE("touch_gestures: on a panel a drag scrolls without pressing, a tap clicks") {
  TouchGestures g;
  g.down(1, 300, 400, false, 0.0);
  TouchFrame f = g.frame(0.02);
  CHECK_FALSE(f.pointer);  // undecided: nothing hovered, nothing pressed
  g.move(1, 300, 350);     // 50 px up: the content moves up, the panel scrolls down
  f = g.frame(0.04);
  CHECK(f.scroll_y == doctest::Approx(50));
  CHECK(f.pointer);
  CHECK_FALSE(f.down);
  g.move(1, 300, 330);
  g.up(1, 300, 330);
  f = g.frame(0.5);  // past the hold time, but the finger was scrolling: no press
  CHECK(f.scroll_y == doctest::Approx(20));
  CHECK_FALSE(f.down);
  CHECK_FALSE(g.active());

  g.down(2, 40, 60, false, 1.0);
  g.up(2, 41, 60);
  f = g.frame(1.05);
  CHECK(f.pointer);
  CHECK(f.down);  // pressed on this frame...
  CHECK(f.x == 41);
  f = g.frame(1.07);
  CHECK(f.pointer);
  CHECK_FALSE(f.down);  // ...released on the next
  f = g.frame(1.09);
  CHECK_FALSE(f.pointer);  // then the mouse is nowhere
}

TEST_CASE("touch_gestures: a finger held still on a panel presses (to drag a slider)") {
  TouchGestures g;
  g.down(1, 100, 100, false, 0.0);
  CHECK_FALSE(g.frame(0.1).down);
  TouchFrame f = g.frame(TouchGestures::kHoldSeconds + 0.01);
  CHECK(f.down);
  g.move(1, 180, 100);  // now the slider follows; no scrolling
  f = g.frame(0.5);
  CHECK(f.down);
  CHECK(f.x == 180);
  CHECK(f.scroll_y == 0);
  g.up(1, 180, 100);
  f = g.frame(0.6);
  CHECK(f.pointer);
  CHECK_FALSE(f.down);
}
