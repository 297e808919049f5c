#include "ui/state/camera.h"

#include <doctest/doctest.h>

using swarmlab::OrbitCamera;
using swarmlab::ScreenPoint;
using swarmlab::ViewRect;

namespace {

ScreenPoint seen(OrbitCamera& camera, const ViewRect& view, const Eigen::Vector3f& p) {
  camera.update(view);
  return camera.project(p, view);
}

}  // namespace

TEST_CASE("camera: the point looked at sits in the middle of the view") {
  const ViewRect view{100, 50, 800, 600};
  OrbitCamera camera;
  camera.set_target({1, -2, 3});
  camera.frame(2, view.aspect());
  const ScreenPoint p = seen(camera, view, {1, -2, 3});
  CHECK(p.visible);
  CHECK(p.x == doctest::Approx(500).epsilon(1e-4));
  CHECK(p.y == doctest::Approx(350).epsilon(1e-4));
}

TEST_CASE("camera: a pan moves the scene with the fingers, and survives a moving target") {
  const ViewRect view{0, 0, 1000, 700};
  OrbitCamera camera;
  camera.orbit(150, -40);
  camera.frame(3, view.aspect());
  const Eigen::Vector3f cm(0.5f, 0.25f, -1);
  camera.set_target(cm);
  const ScreenPoint before = seen(camera, view, cm);
  camera.pan(120, -45, view.height);
  // The point at the target's depth follows the drag to the pixel.
  const ScreenPoint after = seen(camera, view, cm);
  CHECK(after.x - before.x == doctest::Approx(120).epsilon(1e-3));
  CHECK(after.y - before.y == doctest::Approx(-45).epsilon(1e-3));
  // Following the centre of mass moves the target every frame: the slide stays.
  const Eigen::Vector3f moved = cm + Eigen::Vector3f(0.3f, -0.2f, 0.1f);
  camera.set_target(moved);
  const ScreenPoint followed = seen(camera, view, moved);
  CHECK(followed.x == doctest::Approx(after.x).epsilon(1e-3));
  CHECK(followed.y == doctest::Approx(after.y).epsilon(1e-3));
  // Forgetting the slide (as a reframe does) brings the target back to the middle.
  camera.reset_pan();
  const ScreenPoint reset = seen(camera, view, moved);
  CHECK(reset.x == doctest::Approx(500).epsilon(1e-4));
  CHECK(reset.y == doctest::Approx(350).epsilon(1e-4));
}
