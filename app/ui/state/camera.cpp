#include "ui/state/camera.h"

#include <algorithm>
#include <cmath>

namespace swarmlab {

void OrbitCamera::frame(float radius, float aspect) {
  // The narrower of the two fields of view decides: a tall view is limited by its width.
  const float half_fov = std::min(0.5f * fov_y_, std::atan(std::tan(0.5f * fov_y_) * aspect));
  distance_ = std::max(radius, 1e-6f) / std::sin(half_fov) * 1.08f;
}

void OrbitCamera::orbit(float dx, float dy) {
  azimuth_ -= dx * 0.008f;
  // Stopping short of the poles keeps "up" well defined.
  elevation_ = std::clamp(elevation_ + dy * 0.008f, -1.55f, 1.55f);
}

void OrbitCamera::zoom(float steps) {
  distance_ = std::clamp(distance_ * std::pow(0.88f, steps), 1e-4f, 1e7f);
}

void OrbitCamera::zoom_by(float factor) {
  if (factor > 0) distance_ = std::clamp(distance_ / factor, 1e-4f, 1e7f);
}

void OrbitCamera::pan(float dx, float dy, float view_height) {
  const Eigen::Matrix4f m = view();
  const Eigen::Vector3f right = m.block<1, 3>(0, 0).transpose();
  const Eigen::Vector3f up = m.block<1, 3>(1, 0).transpose();
  // World length of one pixel at the target's depth.
  const float per_pixel = 2 * distance_ * std::tan(0.5f * fov_y_) / std::max(view_height, 1.0f);
  pan_offset_ -= per_pixel * (dx * right - dy * up);
}

void OrbitCamera::set_elevation(float radians) { elevation_ = std::clamp(radians, -1.55f, 1.55f); }

Eigen::Vector3f OrbitCamera::eye() const {
  const float c = std::cos(elevation_);
  return look_at() + distance_ * Eigen::Vector3f(c * std::cos(azimuth_),
                                                 c * std::sin(azimuth_), std::sin(elevation_));
}

Eigen::Matrix4f OrbitCamera::view() const {
  const Eigen::Vector3f e = eye();
  const Eigen::Vector3f forward = (look_at() - e).normalized();
  const Eigen::Vector3f right = forward.cross(Eigen::Vector3f::UnitZ()).normalized();
  const Eigen::Vector3f up = right.cross(forward);
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.block<1, 3>(0, 0) = right.transpose();
  m.block<1, 3>(1, 0) = up.transpose();
  m.block<1, 3>(2, 0) = -forward.transpose();
  m(0, 3) = -right.dot(e);
  m(1, 3) = -up.dot(e);
  m(2, 3) = forward.dot(e);
  return m;
}

Eigen::Matrix4f OrbitCamera::projection(float aspect) const {
  // Near and far planes follow the distance so that zooming never clips the scene.
  const float near_plane = distance_ * 0.01f, far_plane = distance_ * 100.0f;
  const float f = 1.0f / std::tan(0.5f * fov_y_);
  Eigen::Matrix4f m = Eigen::Matrix4f::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (far_plane + near_plane) / (near_plane - far_plane);
  m(2, 3) = 2 * far_plane * near_plane / (near_plane - far_plane);
  m(3, 2) = -1;
  return m;
}

void OrbitCamera::update(const ViewRect& rect) {
  view_ = view();
  view_projection_ = projection(rect.aspect()) * view_;
}

ScreenPoint OrbitCamera::project(const Eigen::Vector3f& p, const ViewRect& rect) const {
  const Eigen::Vector4f clip = view_projection_ * Eigen::Vector4f(p.x(), p.y(), p.z(), 1.0f);
  ScreenPoint out;
  out.visible = clip.w() > 1e-6f;
  if (!out.visible) return out;
  out.x = rect.x + (0.5f + 0.5f * clip.x() / clip.w()) * rect.width;
  out.y = rect.y + (0.5f - 0.5f * clip.y() / clip.w()) * rect.height;
  return out;
}

}  // namespace swarmlab
