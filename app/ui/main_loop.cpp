#include "ui/main_loop.h"

#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>

#include "i18n/language.h"
#include "i18n/speak.h"
#include "i18n/translator.h"
#include "ui/input/keyboard_regions.h"
#include "ui/kit/gl_api.h"
#include "ui/parallel_dom/parallel_dom.h"
#include "ui/platform/cjk_font.h"
#include "ui/platform/fonts.h"
#include "ui/platform/language_memory.h"
#include "ui/plots/plot_export.h"

namespace swarmlab {
namespace {

constexpr float kMaxUiFrameSeconds = 0.1f;  // s

/// The frontmost of last frame's ImGui windows (a panel, a strip, the welcome, a menu, a popup)
/// at x, y, or none: a finger there acts on it, never on the 3D view behind.
const ImGuiWindow* window_at(float x, float y) {
  const ImVector<ImGuiWindow*>& windows = ImGui::GetCurrentContext()->Windows;  // back to front
  for (int i = windows.Size - 1; i >= 0; --i) {
    const ImGuiWindow* w = windows[i];
    if (w->Active && !w->Hidden && !(w->Flags & ImGuiWindowFlags_NoMouseInputs) &&
        w->OuterRectClipped.Contains(ImVec2(x, y)))
      return w;
  }
  return nullptr;
}

/// The language the UI is drawn in: the one chosen, or English while the chosen one's glyphs
/// are missing (cjk_font.h).
std::string drawn_language(const std::string& chosen) {
  const Language* language = find_language(chosen);
  return language && language->needs_cjk_font && cjk_font_missing() ? source_language().code : chosen;
}

/// What a finger landing at x, y acts on. While a menu or popup is open, a tap anywhere goes to
/// ImGui (outside the popup it closes it, as a click does), never to the view behind; a window
/// floating over the timeline's bar takes the finger before the bar does.
TouchSurface surface_at(const Layout& layout, float x, float y) {
  if (ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) return TouchSurface::panel;
  const ImGuiWindow* w = window_at(x, y);
  const bool floating = w && !(w->RootWindow->Flags & ImGuiWindowFlags_NoMove);
  if (!floating && layout.drag_at_once.contains(x, y)) return TouchSurface::control;
  if (w || !layout.view.contains(x, y) || ImGui::IsAnyItemActive()) return TouchSurface::panel;
  return TouchSurface::view;
}

/// A finger event to the app's gestures, in ImGui's window pixels, at the event's own time
/// (in the browser, the page's time of the touch event: web/finger_times.cpp).
void feed_finger(App& app, const SDL_TouchFingerEvent& e) {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  const float x = e.x * size.x, y = e.y * size.y;
  Layout& layout = app.state().layout;
  layout.touch = true;
  const long id = long(e.fingerId);
  const double ms = double(e.timestamp);
  if (e.type == SDL_FINGERDOWN)
    app.touch().down(id, x, y, surface_at(layout, x, y), ms);
  else if (e.type == SDL_FINGERMOTION)
    app.touch().move(id, x, y, ms);
  else
    app.touch().up(id, x, y, ms);
}

/// With fingers, ImGui's mouse is where a finger presses, clicks or scrolls a panel, and
/// nowhere otherwise (no hover left behind, no tooltip stuck on the screen).
void apply_touch(App& app) {
  const TouchFrame t = app.touch().frame();
  app.set_touch_frame(t);
  if (!app.state().layout.touch) return;
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = t.pointer ? ImVec2(t.x, t.y) : ImVec2(-FLT_MAX, -FLT_MAX);
  io.MouseDown[0] = t.pointer && t.down;  // the App scrolls the panel under a dragging finger
}

/// ImGui's SDL backend, with the modifiers a key event carries: the backend reads them from
/// SDL's state when the event is handled, by which time a quick Ctrl+A (both keys down and up
/// between two frames) has let Ctrl go, and the A would be typed as text.
bool is_modifier(SDL_Scancode key) {
  return key == SDL_SCANCODE_LCTRL || key == SDL_SCANCODE_RCTRL || key == SDL_SCANCODE_LSHIFT ||
         key == SDL_SCANCODE_RSHIFT || key == SDL_SCANCODE_LALT || key == SDL_SCANCODE_RALT ||
         key == SDL_SCANCODE_LGUI || key == SDL_SCANCODE_RGUI;
}

void process_event(SDL_Event& event) {
  ImGui_ImplSDL2_ProcessEvent(&event);
  if (event.type != SDL_KEYDOWN && event.type != SDL_KEYUP) return;
  ImGuiIO& io = ImGui::GetIO();
  const Uint16 mod = event.key.keysym.mod;
  io.KeyShift = (mod & KMOD_SHIFT) != 0;
  io.KeyCtrl = (mod & KMOD_CTRL) != 0;
  io.KeyAlt = (mod & KMOD_ALT) != 0;
  io.KeySuper = (mod & KMOD_GUI) != 0;
}

}  // namespace

bool frame_wanted(Frontend& f) {
  SDL_PumpEvents();
  if (!f.waiting_keys.empty() || SDL_HasEvents(SDL_FIRSTEVENT, SDL_LASTEVENT)) f.demand.wake();
  if (f.demand.wanted(steady_seconds())) return true;
  f.last_frame = std::chrono::steady_clock::now();
  return false;
}

bool run_frame(Frontend& f, void (*before_present)(Frontend&)) {
  bool typed = false;
  const auto keyboard_event = [](const SDL_Event& e) {
    return e.type == SDL_KEYDOWN || e.type == SDL_KEYUP || e.type == SDL_TEXTINPUT;
  };
  const auto take_key = [&](SDL_Event& e) {
    process_event(e);
    if (e.type == SDL_TEXTINPUT ||
        (e.type == SDL_KEYDOWN && !is_modifier(e.key.keysym.scancode)))
      typed = true;
  };
  // ImGui 1.86 sees a key as held or not once a frame, and within a frame a text field takes
  // typed characters before shortcuts: a key pressed and released between two frames would
  // never be seen pressed (Enter in a lesson's answer field did nothing), and "Ctrl+A, 4.4,
  // Enter" arriving in one frame of a busy machine typed 4.4 before selecting all. So the
  // keyboard trickles, as ImGui's later input queue does: once a key other than a modifier has
  // gone down (or a character arrived) in a frame, every later keyboard event waits, in order,
  // for the frames after, in Frontend::waiting_keys. A modifier's release waits too, so Ctrl+A
  // stays Ctrl+A.
  while (!f.waiting_keys.empty() && !typed) {
    take_key(f.waiting_keys.front());
    f.waiting_keys.pop_front();
  }
  SDL_Event event;
  while (SDL_PollEvent(&event)) {
    if (keyboard_event(event)) {
      if (typed || !f.waiting_keys.empty())
        f.waiting_keys.push_back(event);
      else
        take_key(event);
      continue;
    }
    if (event.type == SDL_FINGERDOWN || event.type == SDL_FINGERMOTION ||
        event.type == SDL_FINGERUP) {
      feed_finger(*f.app, event.tfinger);
      continue;
    }
    // A real mouse (not one SDL made of a finger) brings the mouse back.
    if ((event.type == SDL_MOUSEMOTION && event.motion.which != SDL_TOUCH_MOUSEID) ||
        (event.type == SDL_MOUSEBUTTONDOWN && event.button.which != SDL_TOUCH_MOUSEID))
      f.app->state().layout.touch = false;
    process_event(event);
    // Closing asks first when there are unsaved edits (save_dialog.h).
    if (event.type == SDL_QUIT) f.app->request_close();
    if (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_CLOSE &&
        event.window.windowID == SDL_GetWindowID(f.window.window))
      f.app->request_close();
  }

  // A new UI scale or language rebuilds the font atlas, which only may happen between frames,
  // and not while a slider is being dragged; so does the Chinese font arriving or given up on.
  Layout& layout = f.app->state().layout;
  LanguageChoice& language = f.app->state().language;
  bool new_fonts = cjk_font_news() != CjkFontNews::none;
  if (!language.pending.empty() && !ImGui::IsAnyItemActive()) {
    std::string error;
    // Chinese chosen anew tries its font again, if it had been given up on.
    if (const Language* chosen = find_language(language.pending); chosen && chosen->needs_cjk_font)
      retry_cjk_font();
    if (speak(language.pending, error)) {
      language.code = language.pending;
      // The pseudo-language is for layout tests: never the next visit's.
      if (language.remember && language.code != pseudo_language().code) remember_language(language.code);
      new_fonts = true;
    } else {
      std::fprintf(stderr, "swarmlab: %s\n", error.c_str());
    }
    language.pending.clear();
  }
  // Chinese without its font would show a '?' for every character: English is drawn instead
  // until the font is here (the page says so, in Chinese, with a retry: cjk_font_web.cpp).
  if (const std::string drawn = drawn_language(language.code);
      translator().language().code != drawn) {
    std::string error;
    if (speak(drawn, error)) new_fonts = true;
  }
  if (layout.pending_ui_scale != layout.ui_scale && !ImGui::IsAnyItemActive()) {
    layout.ui_scale = layout.pending_ui_scale;
    new_fonts = true;
  }
  if (new_fonts) {
    // Numbers in fields and on sliders as the language writes them (third_party/imgui/patches/05-decimal-separator.patch).
    ImGui::GetCurrentContext()->PlatformLocaleDecimalPoint = translator().language().decimal_separator;
    layout.resize_panels = true;
    apply_ui_scale(layout.ui_scale, f.app->state().presentation.theme);
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
  }

  f.outputs.apply_theme(f.app->state());

  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - f.last_frame).count();
  f.last_frame = now;

  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplSDL2_NewFrame();
  // ImGui repeats a key held longer than 0.275 s of its frame time. On a slow machine (a
  // school Chromebook, a busy projector laptop) one quick press spanning two slow frames
  // would toggle Play twice; the UI's clock is capped so a press repeats only when held.
  ImGui::GetIO().DeltaTime = std::min(ImGui::GetIO().DeltaTime, kMaxUiFrameSeconds);
  apply_touch(*f.app);
  keep_ctrl_tab_from_imgui();  // the browser's key: regions are F6 (keyboard_regions.h)
  ParallelDom& dom = parallel_dom();
  dom.apply_requests();  // what the page's mirrored elements asked since the last frame
  dom.begin_frame();
  ImGui::NewFrame();
  f.app->update(seconds);
  f.outputs.update(f.app->state(), f.window.window, seconds);
  ImGui::Render();
  dom.end_frame();

  const ImGuiIO& io = ImGui::GetIO();
  glViewport(0, 0, int(io.DisplaySize.x * io.DisplayFramebufferScale.x),
             int(io.DisplaySize.y * io.DisplayFramebufferScale.y));
  const Colour background = palette(f.app->state().presentation.theme).view_background;
  glClearColor(background.r / 255.0f, background.g / 255.0f, background.b / 255.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  f.app->render_scene(io.DisplayFramebufferScale.y, io.DisplaySize.y);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  capture_plot_png(f.app->state());  // a plot saved as PNG: its pixels, before they are shown
  if (before_present) before_present(f);
  SDL_GL_SwapWindow(f.window.window);
  f.demand.drawn(steady_seconds(), f.app->moving(), ImGui::GetIO().WantTextInput);
  if (f.app->quit_requested()) f.running = false;
  return f.running;
}

}  // namespace swarmlab
