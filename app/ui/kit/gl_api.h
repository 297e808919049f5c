#pragma once
// The OpenGL entry points the app uses: OpenGL 3.3 core on the desktop, OpenGL ES 3.0 (WebGL2)
// in the browser. The code restricts itself to the common subset of the two.

#ifdef __EMSCRIPTEN__
#include <GLES3/gl3.h>
#else
// Mesa's libGL exports every core entry point, so no loader is needed on Linux.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#endif

namespace swarmlab {

/// Prepended to every shader: the sources themselves are written in the GLSL subset shared by
/// "#version 330 core" and "#version 300 es". kGlslVersion is the version line alone, which
/// ImGui's OpenGL3 backend is started with (sdl_window.cpp, and again after a lost context).
#ifdef __EMSCRIPTEN__
inline constexpr const char* kGlslVersion = "#version 300 es";
inline constexpr const char* kGlslPrefix = "#version 300 es\nprecision highp float;\n";
#else
inline constexpr const char* kGlslVersion = "#version 330 core";
inline constexpr const char* kGlslPrefix = "#version 330 core\n";
#endif

}  // namespace swarmlab
