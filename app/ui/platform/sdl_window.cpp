#include "ui/platform/sdl_window.h"

#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>
#include <imgui.h>

#include "ui/kit/gl_api.h"
#include "ui/platform/fonts.h"

namespace swarmlab {

SdlWindow open_window(const char* title, int width, int height, std::string& error) {
  SdlWindow w;
  // Fingers reach the app as finger events only (touch_gestures.h), not also as a mouse: a
  // tap must select, not spin the camera.
  SDL_SetHint(SDL_HINT_TOUCH_MOUSE_EVENTS, "0");
  if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_TIMER) != 0) {
    error = std::string("cannot start SDL: ") + SDL_GetError();
    return w;
  }
#ifdef __EMSCRIPTEN__
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_ES);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 0);
#else
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
#endif
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 24);
  SDL_GL_SetAttribute(SDL_GL_STENCIL_SIZE, 0);
  const auto flags =
      SDL_WindowFlags(SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
  w.window =
      SDL_CreateWindow(title, SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height, flags);
  if (!w.window) {
    error = std::string("cannot open a window: ") + SDL_GetError();
    SDL_Quit();
    return w;
  }
  w.context = SDL_GL_CreateContext(w.window);
  if (!w.context) {
    error = std::string("cannot create an OpenGL 3.3 context: ") + SDL_GetError();
    SDL_DestroyWindow(w.window);
    w.window = nullptr;
    SDL_Quit();
    return w;
  }
  SDL_GL_MakeCurrent(w.window, w.context);
  SDL_GL_SetSwapInterval(1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  // Panel sizes follow the window; nothing is worth keeping in an imgui.ini.
  ImGui::GetIO().IniFilename = nullptr;
  // Every control reachable from the keyboard: arrows move, Space activates, Enter types into
  // a field, Escape backs out; F6 goes to the next region (input/keyboard_regions.h).
  ImGui::GetIO().ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard;
  apply_ui_scale(1.0f, Theme::dark);  // the app's first theme; ClassroomOutputs applies another
  ImGui_ImplSDL2_InitForOpenGL(w.window, w.context);
  ImGui_ImplOpenGL3_Init(kGlslVersion);
  return w;
}

void close_window(SdlWindow& w) {
  if (!w.window) return;
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplSDL2_Shutdown();
  ImGui::DestroyContext();
  SDL_GL_DeleteContext(w.context);
  SDL_DestroyWindow(w.window);
  SDL_Quit();
  w = {};
}

}  // namespace swarmlab
