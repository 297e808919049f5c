#include "ui/view/particle_renderer.h"

#include <cmath>
#include <cstddef>
#include <string>

#include "ui/view/shaders.h"

namespace swarmlab {
namespace {

// Below this many particles each is a camera-facing quad of any size; above, a point sprite:
// one vertex instead of six per particle, which is what keeps 40,000 particles interactive on
// a software renderer. Sprites are capped at the largest point size of the GPU, which only
// matters for a large swarm seen from very close.
constexpr std::size_t kSpriteThreshold = 2000;

// Both vertex shaders compute the radius the same way: never less than min_radius times the
// distance, so far or tiny particles stay visible as dots instead of vanishing between pixels.
const char* kQuadVertexShader = R"(
layout(location = 0) in vec2 corner;
layout(location = 1) in vec4 centre_radius;
layout(location = 2) in vec4 colour;
uniform mat4 view;
uniform mat4 projection;
uniform float min_radius;
out vec2 v_corner;
out vec4 v_colour;
void main() {
  vec4 centre = view * vec4(centre_radius.xyz, 1.0);
  float radius = max(centre_radius.w, min_radius * -centre.z);
  v_corner = corner;
  v_colour = colour;
  gl_Position = projection * vec4(centre.xy + corner * radius, centre.z, 1.0);
}
)";

const char* kSpriteVertexShader = R"(
layout(location = 1) in vec4 centre_radius;
layout(location = 2) in vec4 colour;
uniform mat4 view;
uniform mat4 projection;
uniform float min_radius;
uniform float pixels_per_unit;  // at unit distance
uniform float max_point_size;
out vec4 v_colour;
void main() {
  vec4 centre = view * vec4(centre_radius.xyz, 1.0);
  float radius = max(centre_radius.w, min_radius * -centre.z);
  v_colour = colour;
  gl_Position = projection * centre;
  gl_PointSize = min(2.0 * radius * pixels_per_unit / -centre.z, max_point_size);
}
)";

// The fragment shaders differ only in where the position on the disc comes from.
const char* kQuadCorner = "in vec2 v_corner;\nvec2 corner() { return v_corner; }\n";
const char* kSpriteCorner =
    "vec2 corner() { return vec2(2.0 * gl_PointCoord.x - 1.0, 1.0 - 2.0 * gl_PointCoord.y); }\n";

const char* kFragmentShader = R"(
in vec4 v_colour;
uniform int ghost;
out vec4 fragment;
void main() {
  vec2 c = corner();
  float d2 = dot(c, c);
  if (d2 > 1.0) discard;
  if (ghost == 1) {
    if (d2 < 0.45) discard;
    fragment = vec4(v_colour.rgb, 0.85);
    return;
  }
  // Lambert and a little Blinn-Phong on the sphere the disc stands for, lit from the upper
  // left. The highlight is a 16th power by squaring: pow() is slow on software renderers.
  vec3 normal = vec3(c, sqrt(1.0 - d2));
  float diffuse = max(dot(normal, vec3(-0.43, 0.53, 0.73)), 0.0);
  float h = max(dot(normal, vec3(-0.23, 0.29, 0.93)), 0.0);
  h *= h;
  h *= h;
  h *= h;
  h *= h;
  fragment = vec4(v_colour.rgb * (0.32 + 0.75 * diffuse) + vec3(0.3 * h), 1.0);
}
)";

void instance_attributes(GLuint divisor) {
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(ParticleInstance), nullptr);
  glVertexAttribDivisor(1, divisor);
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(ParticleInstance),
                        reinterpret_cast<const void*>(offsetof(ParticleInstance, colour)));
  glVertexAttribDivisor(2, divisor);
}

}  // namespace

ParticleRenderer::Program ParticleRenderer::link(const char* name, const char* vertex,
                                                 const char* corner) {
  const std::string fragment = std::string(corner) + kFragmentShader;
  Program p;
  p.id = link_program(name, vertex, fragment.c_str());
  if (!p.id) return p;
  p.view = glGetUniformLocation(p.id, "view");
  p.projection = glGetUniformLocation(p.id, "projection");
  p.ghost = glGetUniformLocation(p.id, "ghost");
  p.min_radius = glGetUniformLocation(p.id, "min_radius");
  p.pixels_per_unit = glGetUniformLocation(p.id, "pixels_per_unit");
  p.max_point_size = glGetUniformLocation(p.id, "max_point_size");
  return p;
}

ParticleRenderer::ParticleRenderer() { create_gl_objects(); }

ParticleRenderer::~ParticleRenderer() { release_gl_objects(); }

void ParticleRenderer::create_gl_objects() {
  quads_ = link("particle quads", kQuadVertexShader, kQuadCorner);
  sprites_ = link("particle sprites", kSpriteVertexShader, kSpriteCorner);
  GLfloat point_sizes[2] = {1, 64};
  glGetFloatv(GL_ALIASED_POINT_SIZE_RANGE, point_sizes);
  max_point_size_ = point_sizes[1];

  // The instance buffer gets its storage at the first draw (capacity_ is 0).
  capacity_ = 0;
  glGenBuffers(1, &instance_buffer_);
  const float corners[] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
  glGenBuffers(1, &corner_buffer_);
  glGenVertexArrays(1, &quad_vao_);
  glBindVertexArray(quad_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, corner_buffer_);
  glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, instance_buffer_);
  instance_attributes(1);

  glGenVertexArrays(1, &sprite_vao_);
  glBindVertexArray(sprite_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, instance_buffer_);
  instance_attributes(0);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void ParticleRenderer::release_gl_objects() {
  glDeleteBuffers(1, &instance_buffer_);
  glDeleteBuffers(1, &corner_buffer_);
  glDeleteVertexArrays(1, &quad_vao_);
  glDeleteVertexArrays(1, &sprite_vao_);
  glDeleteProgram(quads_.id);
  glDeleteProgram(sprites_.id);
  quads_ = sprites_ = Program{};
  instance_buffer_ = corner_buffer_ = quad_vao_ = sprite_vao_ = 0;
  capacity_ = 0;
}

void ParticleRenderer::draw(const std::vector<ParticleInstance>& particles, ParticleStyle style,
                            const OrbitCamera& camera, const ViewRect& rect,
                            float framebuffer_scale, float window_height) {
  const bool sprites = particles.size() > kSpriteThreshold;
  const Program& program = sprites ? sprites_ : quads_;
  if (particles.empty() || !program.id) return;
  const GLint x = GLint(rect.x * framebuffer_scale);
  const GLint y = GLint((window_height - rect.y - rect.height) * framebuffer_scale);
  const GLsizei w = GLsizei(rect.width * framebuffer_scale);
  const GLsizei h = GLsizei(rect.height * framebuffer_scale);
  glViewport(x, y, w, h);
  glEnable(GL_SCISSOR_TEST);
  glScissor(x, y, w, h);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  if (style == ParticleStyle::ghost) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
  } else {
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
  }
#ifndef __EMSCRIPTEN__
  // Core profile needs this for gl_PointSize; OpenGL ES always honours it (and has no enum).
  if (sprites) glEnable(GL_PROGRAM_POINT_SIZE);
#endif

  glBindBuffer(GL_ARRAY_BUFFER, instance_buffer_);
  if (particles.size() > capacity_) {
    capacity_ = particles.size() + particles.size() / 2;
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(capacity_ * sizeof(ParticleInstance)), nullptr,
                 GL_STREAM_DRAW);
  }
  glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(particles.size() * sizeof(ParticleInstance)),
                  particles.data());

  glUseProgram(program.id);
  const Eigen::Matrix4f view = camera.view();
  const Eigen::Matrix4f projection = camera.projection(rect.aspect());
  glUniformMatrix4fv(program.view, 1, GL_FALSE, view.data());
  glUniformMatrix4fv(program.projection, 1, GL_FALSE, projection.data());
  glUniform1i(program.ghost, style == ParticleStyle::ghost ? 1 : 0);
  const float pixels_per_unit = 0.5f * float(h) / std::tan(0.5f * camera.fov_y());
  glUniform1f(program.min_radius, 1.3f / pixels_per_unit);  // 1.3 pixels at any distance
  if (sprites) {
    glUniform1f(program.pixels_per_unit, pixels_per_unit);
    glUniform1f(program.max_point_size, max_point_size_);
    glBindVertexArray(sprite_vao_);
    glDrawArrays(GL_POINTS, 0, GLsizei(particles.size()));
  } else {
    glBindVertexArray(quad_vao_);
    glDrawArraysInstanced(GL_TRIANGLES, 0, 6, GLsizei(particles.size()));
  }
  glBindVertexArray(0);
  glUseProgram(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);

#ifndef __EMSCRIPTEN__
  if (sprites) glDisable(GL_PROGRAM_POINT_SIZE);
#endif
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
}

}  // namespace swarmlab
