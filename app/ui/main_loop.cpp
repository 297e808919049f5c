#include "main_loop.h"

#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>
#include <imgui.h>

#include "fonts.h"
#include "gl_api.h"

namespace swarmlab {

bool run_frame(Frontend& f, void (*before_present)(Frontend&)) {
  SDL_Event event;
  while (SDL_PollEvent(&event)) {
    ImGui_ImplSDL2_ProcessEvent(&event);
    if (event.type == SDL_QUIT) f.running = false;
    if (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_CLOSE &&
        event.window.windowID == SDL_GetWindowID(f.window.window))
      f.running = false;
  }

  // A new UI scale rebuilds the font atlas, which only may happen between frames, and not
  // while a slider is being dragged.
  Layout& layout = f.app->state().layout;
  if (layout.pending_ui_scale != layout.ui_scale && !ImGui::IsAnyItemActive()) {
    layout.ui_scale = layout.pending_ui_scale;
    layout.resize_panels = true;
    apply_ui_scale(layout.ui_scale);
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
  }

  f.outputs.apply_theme(f.app->state());

  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - f.last_frame).count();
  f.last_frame = now;

  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplSDL2_NewFrame();
  ImGui::NewFrame();
  f.app->update(seconds);
  f.outputs.update(f.app->state(), f.window.window, seconds);
  ImGui::Render();

  const ImGuiIO& io = ImGui::GetIO();
  glViewport(0, 0, int(io.DisplaySize.x * io.DisplayFramebufferScale.x),
             int(io.DisplaySize.y * io.DisplayFramebufferScale.y));
  const Colour background = palette(f.app->state().presentation.theme).view_background;
  glClearColor(background.r / 255.0f, background.g / 255.0f, background.b / 255.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  f.app->render_scene(io.DisplayFramebufferScale.y, io.DisplaySize.y);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (before_present) before_present(f);
  SDL_GL_SwapWindow(f.window.window);
  if (f.app->quit_requested()) f.running = false;
  return f.running;
}

}  // namespace swarmlab
