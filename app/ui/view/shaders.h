#pragma once
// Compiling the app's GLSL programs, with the version line chosen by the platform.

#include <string>

#include "ui/kit/gl_api.h"

namespace swarmlab {

/// Compiles and links a program from shared-subset GLSL sources (without a #version line).
/// On failure prints the driver's log to stderr and returns 0.
GLuint link_program(const char* name, const char* vertex_source, const char* fragment_source);

}  // namespace swarmlab
