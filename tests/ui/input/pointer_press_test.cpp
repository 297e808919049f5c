#include "ui/input/pointer_press.h"

#include <doctest/doctest.h>

using namespace swarmlab;

TEST_CASE("pointer_press: a press at a new place with no motion before it is a click, not a turn") {
  // The pointer was last at (900, 100); a whiteboard presses at (300, 500) and lets go there.
  PointerPress p;
  p.start(300, 500);
  const PointerPress::Motion m = p.move_to(300, 500);  // the press's own frame
  CHECK(m.dx == 0);
  CHECK(m.dy == 0);
  CHECK(p.move_to(300, 500).dx == 0);  // held still
  CHECK(p.is_click());
}

TEST_CASE("pointer_press: a drag turns by each frame's motion of the same press") {
  PointerPress p;
  p.start(100, 100);
  PointerPress::Motion m = p.move_to(130, 90);
  CHECK(m.dx == 30);
  CHECK(m.dy == -10);
  m = p.move_to(150, 95);
  CHECK(m.dx == 20);
  CHECK(m.dy == 5);
  CHECK_FALSE(p.is_click());
  // The next press starts afresh where it goes down, whatever the last one did.
  p.start(600, 50);
  m = p.move_to(601, 51);
  CHECK(m.dx == 1);
  CHECK(m.dy == 1);
  CHECK(p.is_click());  // 2 px of wobble is still a click
}
