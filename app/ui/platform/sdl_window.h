#pragma once
// The window, its OpenGL context and Dear ImGui's SDL2 and OpenGL3 backends. SDL2 exists on
// the desktop and in Emscripten, so this file serves both; only the context version differs.

#include <SDL.h>

#include <string>

namespace swarmlab {

struct SdlWindow {
  SDL_Window* window = nullptr;
  SDL_GLContext context = nullptr;
};

/// Opens a resizable window with an OpenGL 3.3 core (desktop) or OpenGL ES 3.0 (WebGL2)
/// context and a depth buffer, and starts ImGui on it. On failure returns a window with
/// null members and sets error.
SdlWindow open_window(const char* title, int width, int height, std::string& error);
void close_window(SdlWindow& w);

}  // namespace swarmlab
