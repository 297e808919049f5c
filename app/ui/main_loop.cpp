#include "main_loop.h"

#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>
#include <imgui.h>

#include "fonts.h"
#include "gl_api.h"
#include "plot_export.h"

namespace swarmlab {

bool run_frame(Frontend& f, void (*before_present)(Frontend&)) {
  SDL_Event event;
  while (SDL_PollEvent(&event)) {
    ImGui_ImplSDL2_ProcessEvent(&event);
    // Closing asks first when there are unsaved edits (save_dialog.h).
    if (event.type == SDL_QUIT) f.app->request_close();
    if (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_CLOSE &&
        event.window.windowID == SDL_GetWindowID(f.window.window))
      f.app->request_close();
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

  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - f.last_frame).count();
  f.last_frame = now;

  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplSDL2_NewFrame();
  ImGui::NewFrame();
  f.app->update(seconds);
  ImGui::Render();

  const ImGuiIO& io = ImGui::GetIO();
  glViewport(0, 0, int(io.DisplaySize.x * io.DisplayFramebufferScale.x),
             int(io.DisplaySize.y * io.DisplayFramebufferScale.y));
  glClearColor(0.035f, 0.04f, 0.06f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  f.app->render_scene(io.DisplayFramebufferScale.y, io.DisplaySize.y);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  capture_plot_png(f.app->state());  // a plot saved as PNG: its pixels, before they are shown
  if (before_present) before_present(f);
  SDL_GL_SwapWindow(f.window.window);
  if (f.app->quit_requested()) f.running = false;
  return f.running;
}

}  // namespace swarmlab
