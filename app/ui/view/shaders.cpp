#include "ui/view/shaders.h"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace swarmlab {
namespace {

/// The info log of a shader or a program, read with its pair of GL getters.
template <class GetLength, class GetLog>
std::vector<char> info_log(GLuint object, GetLength get_length, GetLog get_log) {
  GLint length = 0;
  get_length(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(std::size_t(std::max(length, 0)) + 1);
  get_log(object, length, nullptr, log.data());
  return log;
}

GLuint compile(const char* name, GLenum kind, const char* source) {
  const GLuint shader = glCreateShader(kind);
  const char* parts[] = {kGlslPrefix, source};
  glShaderSource(shader, 2, parts, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::vector<char> log = info_log(
        shader, [](GLuint o, GLenum q, GLint* v) { glGetShaderiv(o, q, v); },
        [](GLuint o, GLsizei n, GLsizei* l, char* t) { glGetShaderInfoLog(o, n, l, t); });
    std::fprintf(stderr, "swarmlab: %s %s shader: %s\n", name,
                 kind == GL_VERTEX_SHADER ? "vertex" : "fragment", log.data());
    glDeleteShader(shader);
    return 0;
  }
  return shader;
}

}  // namespace

GLuint link_program(const char* name, const char* vertex_source, const char* fragment_source) {
  const GLuint vertex = compile(name, GL_VERTEX_SHADER, vertex_source);
  const GLuint fragment = compile(name, GL_FRAGMENT_SHADER, fragment_source);
  if (!vertex || !fragment) return 0;
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::vector<char> log = info_log(
        program, [](GLuint o, GLenum q, GLint* v) { glGetProgramiv(o, q, v); },
        [](GLuint o, GLsizei n, GLsizei* l, char* t) { glGetProgramInfoLog(o, n, l, t); });
    std::fprintf(stderr, "swarmlab: %s program: %s\n", name, log.data());
    glDeleteProgram(program);
    return 0;
  }
  return program;
}

}  // namespace swarmlab
