#pragma once
// The orbit camera of the 3D view: it circles a target point, z is up.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace swarmlab {

/// A rectangle of the window in ImGui's coordinates (pixels, origin at the top left).
struct ViewRect {
  float x = 0, y = 0, width = 1, height = 1;
  float aspect() const { return width / height; }
  bool contains(float px, float py) const {
    return px >= x && py >= y && px < x + width && py < y + height;
  }
};

/// A point of the scene on the screen.
struct ScreenPoint {
  float x = 0, y = 0;
  bool visible = false;  ///< in front of the camera
};

class OrbitCamera {
 public:
  /// Sets the distance so that a ball of this radius about the target fills a view of this
  /// width / height.
  void frame(float radius, float aspect);
  /// Turns the camera by a mouse drag of dx, dy pixels.
  void orbit(float dx, float dy);
  /// Moves away by this factor (a growing container stays in view).
  void scale_distance(float factor) { distance_ *= factor; }
  /// Moves closer (steps > 0) or farther, one wheel notch at a time.
  void zoom(float steps);
  /// Moves closer by this factor (a pinch that spread the fingers by it).
  void zoom_by(float factor);
  /// Slides the view so the scene follows a two-finger drag of dx, dy pixels across a view
  /// view_height pixels tall. The slide is kept apart from the target, so a view that follows
  /// the centre of mass keeps following it, shifted, until reset_pan().
  void pan(float dx, float dy, float view_height);
  /// Forgets the slide: the target is in the middle of the view again.
  void reset_pan() { pan_offset_ = Eigen::Vector3f::Zero(); }
  float distance() const { return distance_; }
  float yaw() const { return azimuth_; }      ///< radians about z
  float pitch() const { return elevation_; }  ///< radians above the x-y plane
  void set_target(const Eigen::Vector3f& target) { target_ = target; }
  /// Height of the eye above the x-y plane, radians (0: level, pi/2: looking straight down).
  void set_elevation(float radians);

  Eigen::Vector3f eye() const;
  Eigen::Matrix4f view() const;
  Eigen::Matrix4f projection(float aspect) const;
  float fov_y() const { return fov_y_; }

  /// Projects a point with the matrices of this frame into the view rectangle.
  ScreenPoint project(const Eigen::Vector3f& p, const ViewRect& rect) const;
  /// Call once per frame before project(): caches view * projection for the rectangle.
  void update(const ViewRect& rect);

 private:
  Eigen::Vector3f look_at() const { return target_ + pan_offset_; }

  Eigen::Vector3f target_ = Eigen::Vector3f::Zero();
  Eigen::Vector3f pan_offset_ = Eigen::Vector3f::Zero();  ///< world units
  float distance_ = 5;
  float azimuth_ = -1.1f;   ///< radians about z
  float elevation_ = 0.6f;  ///< radians above the x-y plane
  float fov_y_ = 0.7f;      ///< radians
  Eigen::Matrix4f view_projection_ = Eigen::Matrix4f::Identity();
  Eigen::Matrix4f view_ = Eigen::Matrix4f::Identity();
};

}  // namespace swarmlab
