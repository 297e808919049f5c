#include "particle_renderer.h"

#include "shaders.h"

namespace swarmlab {
namespace {

const char* kVertexShader = R"(
layout(location = 0) in vec2 corner;
layout(location = 1) in vec4 centre_radius;
layout(location = 2) in vec4 colour;
uniform mat4 view;
uniform mat4 projection;
// The smallest radius drawn, as a fraction of the view height at unit distance: far or tiny
// particles stay visible as dots instead of vanishing between pixels.
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

const char* kFragmentShader = R"(
in vec2 v_corner;
in vec4 v_colour;
uniform int ghost;
out vec4 fragment;
void main() {
  float d2 = dot(v_corner, v_corner);
  if (d2 > 1.0) discard;
  if (ghost == 1) {
    if (d2 < 0.45) discard;
    fragment = vec4(v_colour.rgb, 0.85);
    return;
  }
  // Lambert and a little Phong on the sphere the quad stands for, light from the upper left.
  vec3 normal = vec3(v_corner, sqrt(1.0 - d2));
  vec3 light = normalize(vec3(-0.45, 0.55, 0.7));
  float diffuse = max(dot(normal, light), 0.0);
  float specular = pow(max(dot(reflect(-light, normal), vec3(0.0, 0.0, 1.0)), 0.0), 24.0);
  vec3 rgb = v_colour.rgb * (0.32 + 0.75 * diffuse) + vec3(0.35 * specular);
  fragment = vec4(rgb, 1.0);
}
)";

}  // namespace

ParticleRenderer::ParticleRenderer() {
  program_ = link_program("particles", kVertexShader, kFragmentShader);
  view_location_ = glGetUniformLocation(program_, "view");
  projection_location_ = glGetUniformLocation(program_, "projection");
  ghost_location_ = glGetUniformLocation(program_, "ghost");
  min_radius_location_ = glGetUniformLocation(program_, "min_radius");

  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  const float corners[] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
  glGenBuffers(1, &corner_buffer_);
  glBindBuffer(GL_ARRAY_BUFFER, corner_buffer_);
  glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);

  glGenBuffers(1, &instance_buffer_);
  glBindBuffer(GL_ARRAY_BUFFER, instance_buffer_);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(ParticleInstance), nullptr);
  glVertexAttribDivisor(1, 1);
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(ParticleInstance),
                        reinterpret_cast<const void*>(offsetof(ParticleInstance, colour)));
  glVertexAttribDivisor(2, 1);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

ParticleRenderer::~ParticleRenderer() {
  glDeleteBuffers(1, &instance_buffer_);
  glDeleteBuffers(1, &corner_buffer_);
  glDeleteVertexArrays(1, &vao_);
  glDeleteProgram(program_);
}

void ParticleRenderer::draw(const std::vector<ParticleInstance>& particles, ParticleStyle style,
                            const OrbitCamera& camera, const ViewRect& rect,
                            float framebuffer_scale, float window_height) {
  if (particles.empty() || !program_) return;
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

  glBindBuffer(GL_ARRAY_BUFFER, instance_buffer_);
  const std::size_t bytes = particles.size() * sizeof(ParticleInstance);
  if (particles.size() > capacity_) {
    capacity_ = particles.size() + particles.size() / 2;
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(capacity_ * sizeof(ParticleInstance)), nullptr,
                 GL_STREAM_DRAW);
  }
  glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(bytes), particles.data());

  glUseProgram(program_);
  const Eigen::Matrix4f view = camera.view();
  const Eigen::Matrix4f projection = camera.projection(rect.aspect());
  glUniformMatrix4fv(view_location_, 1, GL_FALSE, view.data());
  glUniformMatrix4fv(projection_location_, 1, GL_FALSE, projection.data());
  glUniform1i(ghost_location_, style == ParticleStyle::ghost ? 1 : 0);
  // 1.3 pixels at any distance: tan(fov/2) / (half the view height in pixels).
  glUniform1f(min_radius_location_,
              1.3f * std::tan(0.5f * camera.fov_y()) / (0.5f * rect.height * framebuffer_scale));
  glBindVertexArray(vao_);
  glDrawArraysInstanced(GL_TRIANGLES, 0, 6, GLsizei(particles.size()));
  glBindVertexArray(0);
  glUseProgram(0);

  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
}

}  // namespace swarmlab
