#pragma once
// Draws every particle as a shaded sphere impostor in one draw call fed by one buffer upload
// per frame: instanced camera-facing quads for small systems, point sprites for large ones.

#include <cstdint>
#include <vector>

#include "ui/kit/gl_api.h"
#include "ui/state/camera.h"
#include "ui/state/colour_map.h"

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

  /// The browser took the GL context away (ui/gl_context_life.h): deletes the programs,
  /// buffers and vertex arrays, which a lost context ignores, so that no name of the old
  /// context is used on the new one; draw() draws nothing until create_gl_objects().
  void release_gl_objects();
  /// Makes the programs, buffers and vertex arrays on the current context: at construction,
  /// and again on a restored one.
  void create_gl_objects();

 private:
  struct Program {
    GLuint id = 0;
    GLint view = -1, projection = -1, ghost = -1, min_radius = -1, pixels_per_unit = -1,
          max_point_size = -1;
  };
  static Program link(const char* name, const char* vertex_source, const char* corner_source);

  Program quads_, sprites_;
  GLuint quad_vao_ = 0, sprite_vao_ = 0, corner_buffer_ = 0, instance_buffer_ = 0;
  float max_point_size_ = 64;
  std::size_t capacity_ = 0;  ///< particles the instance buffer holds (0: no storage yet)
};

}  // namespace swarmlab
