#pragma once
// Draws every particle as a shaded sphere impostor: one camera-facing quad per particle, all
// of them in one instanced draw call fed by one buffer upload per frame.

#include <cstdint>
#include <vector>

#include "camera.h"
#include "colour_map.h"
#include "gl_api.h"

namespace swarmlab {

/// One particle as the GPU sees it: 20 bytes.
struct ParticleInstance {
  float x, y, z;
  float radius;  ///< world units
  Rgba8 colour;
};

enum class ParticleStyle {
  solid,  ///< lit spheres
  ghost,  ///< hollow rings: the analytic positions beside a numerical run
};

class ParticleRenderer {
 public:
  ParticleRenderer();
  ~ParticleRenderer();
  ParticleRenderer(const ParticleRenderer&) = delete;
  ParticleRenderer& operator=(const ParticleRenderer&) = delete;

  /// Draws into the view rectangle. framebuffer_scale converts ImGui pixels to framebuffer
  /// pixels (HiDPI screens); window_height is in ImGui pixels.
  void draw(const std::vector<ParticleInstance>& particles, ParticleStyle style,
            const OrbitCamera& camera, const ViewRect& rect, float framebuffer_scale,
            float window_height);

 private:
  GLuint program_ = 0, vao_ = 0, corner_buffer_ = 0, instance_buffer_ = 0;
  GLint view_location_ = -1, projection_location_ = -1, ghost_location_ = -1,
        min_radius_location_ = -1;
  std::size_t capacity_ = 0;
};

}  // namespace swarmlab
