#include "ui/input/touch_gestures.h"

#include <doctest/doctest.h>

#include <utility>

using namespace swarmlab;

namespace {
constexpr TouchSurface view = TouchSurface::view, panel = TouchSurface::panel,
                       control = TouchSurface::control;
}  // namespace

TEST_CASE("touch_gestures: a tap on the view selects, it does not orbit") {
  TouchGestures g;
  g.down(1, 100, 100, view, 0);
  g.move(1, 103, 101, 40);  // a fingertip wobbles by a few pixels
  g.up(1, 103, 101, 90);
  const TouchFrame f = g.frame();
  CHECK(f.tap);
  CHECK(f.tap_x == 103);
  CHECK(f.orbit_dx == 0);
  CHECK(f.orbit_dy == 0);
  CHECK_FALSE(f.pointer);  // ImGui's mouse is not pressed on the view
  CHECK_FALSE(g.frame().tap);
}

TEST_CASE("touch_gestures: one finger dragged on the view orbits by its motion past the slop") {
  TouchGestures g;
  g.down(1, 100, 100, view, 0);
  g.move(1, 120, 100, 20);  // leaves the slop: the orbit starts here
  g.move(1, 150, 90, 40);
  TouchFrame f = g.frame();
  CHECK(f.orbit_dx == doctest::Approx(30));
  CHECK(f.orbit_dy == doctest::Approx(-10));
  CHECK_FALSE(f.pointer);
  g.up(1, 150, 90, 60);
  f = g.frame();
  CHECK_FALSE(f.tap);
  CHECK(f.orbit_dx == 0);
}

TEST_CASE("touch_gestures: two fingers pinch to zoom and drag to pan") {
  TouchGestures g;
  g.down(1, 100, 100, view, 0);
  g.down(2, 200, 100, view, 0);
  g.move(1, 50, 100, 20);
  g.move(2, 250, 100, 20);  // 100 px apart -> 200 px apart
  TouchFrame f = g.frame();
  CHECK(f.zoom == doctest::Approx(2.0));
  CHECK(f.orbit_dx == 0);
  CHECK(f.pan_dx == doctest::Approx(0).epsilon(1e-6));
  g.move(1, 50, 140, 40);
  g.move(2, 250, 140, 40);  // both down by 40: the midpoint moves 40
  f = g.frame();
  CHECK(f.zoom == doctest::Approx(1.0));
  CHECK(f.pan_dy == doctest::Approx(40));
  // Lifting one finger neither taps nor turns the remaining one into an orbit.
  g.up(2, 250, 140, 60);
  g.move(1, 90, 180, 80);
  g.up(1, 90, 180, 100);
  f = g.frame();
  CHECK_FALSE(f.tap);
  CHECK(f.orbit_dx == 0);
}

TEST_CASE("touch_gestures: on a panel a drag scrolls without pressing, a tap clicks") {
  TouchGestures g;
  g.down(1, 300, 400, panel, 0);
  TouchFrame f = g.frame();
  CHECK_FALSE(f.pointer);  // undecided: nothing hovered, nothing pressed
  g.move(1, 300, 350, 30);  // 50 px up: the content moves up, the panel scrolls down
  f = g.frame();
  CHECK(f.scroll_y == doctest::Approx(50));
  CHECK(f.pointer);
  CHECK_FALSE(f.down);
  g.move(1, 300, 330, 600);  // long past the hold time, but the finger was scrolling: no press
  g.up(1, 300, 330, 620);
  f = g.frame();
  CHECK(f.scroll_y == doctest::Approx(20));
  CHECK_FALSE(f.down);
  CHECK_FALSE(g.active());

  g.down(2, 40, 60, panel, 1000);
  g.up(2, 41, 60, 1050);
  f = g.frame();
  CHECK(f.pointer);
  CHECK(f.down);  // pressed on this frame...
  CHECK(f.x == 41);
  f = g.frame();
  CHECK(f.pointer);
  CHECK_FALSE(f.down);  // ...released on the next
  f = g.frame();
  CHECK_FALSE(f.pointer);  // then the mouse is nowhere
  CHECK_FALSE(g.active());
}

TEST_CASE(
    "touch_gestures: a finger held still on a panel, then moved, presses (to drag a slider)") {
  TouchGestures g;
  g.down(1, 100, 100, panel, 0);
  g.move(1, 102, 101, 200);  // a wobble inside the slop decides nothing
  CHECK_FALSE(g.frame().pointer);
  g.move(1, 180, 100, TouchGestures::kHoldMs + 10);  // still for the hold time, then moved
  TouchFrame f = g.frame();
  CHECK(f.down);
  CHECK(f.x == 100);  // pressed first where it landed: what the slider grabs
  CHECK(f.scroll_y == 0);
  f = g.frame();
  CHECK(f.down);
  CHECK(f.x == 180);  // then the slider follows
  g.move(1, 200, 100, 500);
  g.up(1, 210, 100, 520);  // moved and lifted between two frames
  f = g.frame();
  CHECK(f.down);
  CHECK(f.x == 210);  // the press reaches where the finger left...
  f = g.frame();
  CHECK(f.pointer);
  CHECK_FALSE(f.down);  // ...and is released there
  CHECK(f.x == 210);
}

TEST_CASE("touch_gestures: a stalled frame does not turn a drag into a press") {
  // A busy machine draws no frame for half a second while the finger lands and moves at
  // once: the events' own times say it was a drag.
  TouchGestures g;
  g.down(1, 300, 400, panel, 10'000);
  g.move(1, 300, 380, 10'040);
  g.move(1, 300, 340, 10'080);
  g.move(1, 300, 300, 10'120);
  TouchFrame f = g.frame();  // the first frame after the stall
  CHECK(f.scroll_y == doctest::Approx(100));
  CHECK_FALSE(f.down);
  g.up(1, 300, 300, 10'600);
  f = g.frame();
  CHECK_FALSE(f.down);
  CHECK_FALSE(g.active());
}

TEST_CASE("touch_gestures: a hold is judged on the events' times however often frames come") {
  // The same finger, frames every 10 ms or one frame in all: the same press.
  auto run = [](int frames_between) {
    TouchGestures g;
    int presses = 0, scrolls = 0;
    auto frames = [&] {
      for (int i = 0; i < frames_between; ++i) {
        const TouchFrame f = g.frame();
        presses += f.down, scrolls += f.scroll_y != 0;
      }
    };
    g.down(1, 50, 50, panel, 0);
    frames();
    g.move(1, 90, 50, 400);
    frames();
    g.up(1, 90, 50, 450);
    for (int i = 0; i < 4; ++i) {
      const TouchFrame f = g.frame();
      presses += f.down, scrolls += f.scroll_y != 0;
    }
    return std::make_pair(presses > 0, scrolls);
  };
  CHECK(run(40) == std::make_pair(true, 0));
  CHECK(run(0) == std::make_pair(true, 0));
}

TEST_CASE("touch_gestures: a control taken at once (the timeline) is pressed as the finger lands") {
  TouchGestures g;
  g.down(1, 200, 700, control, 0);
  TouchFrame f = g.frame();
  CHECK(f.pointer);
  CHECK(f.down);
  CHECK(f.x == 200);
  g.move(1, 205, 700, 16);  // inside the slop it already drags
  f = g.frame();
  CHECK(f.down);
  CHECK(f.x == 205);
  CHECK(f.scroll_y == 0);
  g.move(1, 80, 702, 32);
  g.up(1, 60, 702, 40);
  f = g.frame();
  CHECK(f.down);
  CHECK(f.x == 60);
  f = g.frame();
  CHECK_FALSE(f.down);
  CHECK(f.x == 60);
  CHECK_FALSE(g.active());

  // A quick tap on it presses on one frame and releases on the next.
  g.down(2, 300, 700, control, 100);
  g.up(2, 300, 700, 130);
  CHECK(g.frame().down);
  f = g.frame();
  CHECK(f.pointer);
  CHECK_FALSE(f.down);
}

TEST_CASE("touch_gestures: a flick that lifts before the next frame still scrolls where it was") {
  TouchGestures g;
  g.down(1, 200, 500, panel, 0);
  g.move(1, 200, 450, 16);
  g.move(1, 200, 380, 32);
  g.up(1, 200, 380, 40);
  const TouchFrame f = g.frame();
  CHECK(f.scroll_y == doctest::Approx(120));
  CHECK(f.pointer);  // ImGui's mouse over the window to scroll...
  CHECK(f.y == 380);
  CHECK_FALSE(f.down);  // ...pressing nothing
  CHECK_FALSE(g.frame().pointer);
}

TEST_CASE("touch_gestures: a window over the view is a panel: a drag on it never orbits") {
  TouchGestures g;
  g.down(1, 200, 300, panel, 0);
  g.move(1, 260, 330, 30);
  g.move(1, 320, 360, 60);
  const TouchFrame f = g.frame();
  CHECK(f.orbit_dx == 0);
  CHECK(f.orbit_dy == 0);
  CHECK_FALSE(f.tap);
  g.up(1, 320, 360, 90);
  CHECK_FALSE(g.frame().tap);
}
