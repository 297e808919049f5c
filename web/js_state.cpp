// swarmlab.state(): what the app shows and runs, as one JSON object, for course pages and
// tests. Each feature adds its own fields here (web/README.md lists them).

#include <emscripten.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <nlohmann/json.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "i18n/translator.h"
#include "ui/parallel_dom/parallel_dom.h"
#include "web_app.h"

namespace {

std::string state_text, position_text;  // valid until the next call

nlohmann::json rect_json(float x, float y, float width, float height) {
  return {{"x", x}, {"y", y}, {"width", width}, {"height", height}};
}

nlohmann::json app_state_json(swarmlab::App& app) {
  const swarmlab::AppState& s = app.state();
  nlohmann::json j;
  j["name"] = s.preset.name;
  j["edited"] = s.modified;
  j["playing"] = s.playing;
  j["t"] = s.run->time();
  j["speed"] = s.speed;
  // The simulated speed reached over the set one (< 1: the steps do not fit the frames; the
  // clock's line says so), and the frames drawn (none while paused and still).
  j["speed_ratio"] = s.stats.speed_ratio;
  j["frames_drawn"] = s.stats.frames;
  j["idle"] = s.stats.idle;
  j["run_while_hidden"] = s.presentation.run_while_hidden;
  j["selected"] = s.selected ? nlohmann::json(*s.selected) : nlohmann::json(nullptr);
  // The camera, the layout and where everything is (CSS pixels of the canvas = ImGui's).
  j["camera"] = {{"distance", s.camera.distance()}, {"yaw", s.camera.yaw()},
                 {"pitch", s.camera.pitch()}};
  j["layout"] = swarmlab::layout_name(s.layout.screen.kind);
  j["layout_mode"] = swarmlab::layout_mode_name(s.layout.mode);
  j["touch"] = s.layout.touch;
  j["fingers"] = app.touch().fingers();
  j["ui_scale"] = s.layout.ui_scale;
  // The canvas size the last frame was laid out for, and whether the next lays out the same.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  j["display"] = {{"width", display.x}, {"height", display.y}};
  j["layout_settled"] = s.layout.settled;
  const swarmlab::ViewRect& v = s.layout.view;
  j["view"] = rect_json(v.x, v.y, v.width, v.height);
  j["panels"] = nlohmann::json::array();
  for (const swarmlab::Layout::Panel& p : s.layout.panels) {
    nlohmann::json panel = rect_json(p.rect.x, p.rect.y, p.rect.width, p.rect.height);
    panel["name"] = p.name;
    panel["scroll"] = p.scroll;
    panel["scroll_max"] = p.scroll_max;
    j["panels"].push_back(panel);
  }
  // The menus' titles in the bar and the windows floating over the rest, with their close
  // button (app.cpp records them): where a finger taps them.
  j["menus"] = nlohmann::json::array();
  for (const swarmlab::Layout::Panel& m : s.layout.menus) {
    nlohmann::json menu = rect_json(m.rect.x, m.rect.y, m.rect.width, m.rect.height);
    menu["name"] = m.name;
    j["menus"].push_back(menu);
  }
  j["windows"] = nlohmann::json::array();
  for (const swarmlab::Layout::FloatingWindow& w : s.layout.windows) {
    nlohmann::json window = rect_json(w.rect.x, w.rect.y, w.rect.width, w.rect.height);
    window["name"] = w.name;
    window["scroll"] = w.scroll;
    window["close"] = w.close.shown()
                          ? rect_json(w.close.x, w.close.y, w.close.width, w.close.height)
                          : nlohmann::json(nullptr);
    j["windows"].push_back(window);
  }
  // Time (web/js_time.cpp): the furthest time computed, and a fast-forward under way.
  // The timeline's bar: its rectangle and the time at its right end (the left end is t = 0).
  const swarmlab::ViewRect& bar = s.layout.drag_at_once;
  j["timeline"] = rect_json(bar.x, bar.y, bar.width, bar.height);
  j["timeline"]["t_end"] = double(std::max(1L, s.run->timeline().end_step())) * s.preset.dt;
  j["t_reached"] = double(s.run->timeline().reached()) * s.preset.dt;
  j["fast_forward"] = s.travel.active() && s.travel.kind != swarmlab::TimeTravel::Kind::seek
                          ? nlohmann::json{{"progress", s.travel.progress(s.run->step())}}
                          : nlohmann::json(nullptr);
  // A swarmlab.seek under way: its target time and how much of the way is done (0 to 1).
  j["seek"] = s.travel.kind == swarmlab::TimeTravel::Kind::to_time
                  ? nlohmann::json{{"t", double(s.travel.target) * s.preset.dt},
                                   {"progress", s.travel.progress(s.run->step())}}
                  : nlohmann::json(nullptr);
  // The last fast-forward as its bar showed it, kept after it ends (time_travel.h).
  // A seek the page asked for (swarmlab.seek) shows its progress the same way, kind "time".
  const swarmlab::FastForwardRecord& ff = s.last_fast_forward;
  const char* kind = ff.kind == swarmlab::TimeTravel::Kind::to_run_end  ? "run_end"
                     : ff.kind == swarmlab::TimeTravel::Kind::to_time ? "time"
                                                                       : "stage_end";
  j["last_fast_forward"] = nullptr;
  if (ff.kind != swarmlab::TimeTravel::Kind::none)
    j["last_fast_forward"] = {{"kind", kind},
                              {"frames", ff.frames},
                              {"progress", ff.progress},
                              {"reached", ff.reached},
                              {"longest_ms", ff.longest_ms}};
  // The instruments: P and T as the read-outs show them (null without a container or before
  // the first sample; T also before the first wall hit), the stopwatch, the measured period.
  const swarmlab::Instruments& in = s.instruments;
  const bool wall = s.preset.container_radius && in.wall.intervals > 0;
  j["P"] = wall ? nlohmann::json(in.wall.mean.P) : nlohmann::json(nullptr);
  j["T"] = wall && in.wall.mean.hits > 0 ? nlohmann::json(in.wall.mean.T) : nlohmann::json(nullptr);
  j["stopwatch"] = {{"running", in.stopwatch.running()}, {"elapsed", in.stopwatch.elapsed()}};
  const auto period = in.track ? in.track->meter.period() : std::nullopt;
  j["measured_period"] = period ? nlohmann::json(*period) : nlohmann::json(nullptr);
  // The projector and the classroom (app/ui/classroom/presentation.h).
  j["theme"] = swarmlab::theme_name(s.presentation.theme);
  j["language"] = s.language.code;
  j["presentation"] = s.presentation.on;
  j["sound"] = s.presentation.sound;
  j["fullscreen"] = s.presentation.fullscreen;
  j["embed"] = s.embedded;  // inside a course page: no menu bar (embedding.h)
  // The region keyboard navigation is in, by its window's title ("Controls", "Plots",
  // "Transport", "Read-outs", "Timeline", "Panels", "menu"), or null (the 3D view).
  const ImGuiContext* imgui = ImGui::GetCurrentContext();
  const ImGuiWindow* nav = imgui ? imgui->NavWindow : nullptr;
  if (nav && imgui->NavLayer == ImGuiNavLayer_Menu) j["keyboard_focus"] = "menu";
  else if (nav) {
    // The English name in every language (the API's), without its "##" ID.
    const std::string name(swarmlab::translator().english_label(nav->RootWindow->Name));
    j["keyboard_focus"] = name.substr(0, name.find("##"));
  }
  else j["keyboard_focus"] = nullptr;
  // The item the keyboard is on (its name as the parallel DOM gives it), or null.
  j["keyboard_item"] = nullptr;
  if (const unsigned nav_id = swarmlab::parallel_dom().nav_id())
    for (const swarmlab::MirroredItem& item : swarmlab::parallel_dom().items())
      if (item.id == nav_id) {
        j["keyboard_item"] = item.name;
        break;
      }
  return j;
}

}  // namespace

extern "C" {

/// The app's state as compact JSON ("{}" before main() has made the app).
EMSCRIPTEN_KEEPALIVE const char* swarmlab_state() {
  swarmlab::App* app = swarmlab::web_app();
  state_text = app ? app_state_json(*app).dump() : "{}";
  return state_text.c_str();
}

/// Where particle i was drawn this frame: "x y" in CSS pixels of the canvas, "" when it is
/// behind the camera or outside the 3D view, "bad N" when there is no particle i (N particles).
/// i comes as a double and is checked before it becomes an index: an int parameter would take
/// JavaScript's 2^32 + 1 as 1.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_screen_position(double i) {
  swarmlab::App* app = swarmlab::web_app();
  if (!app) return "bad 0";
  const swarmlab::AppState& s = app->state();
  const auto& particles = s.run->system().particles;
  if (!(i >= 0 && i < double(particles.size()) && i == std::floor(i))) {
    position_text = "bad " + std::to_string(particles.size());
    return position_text.c_str();
  }
  const swarmlab::ScreenPoint p = s.camera.project(particles[std::size_t(i)].r.cast<float>(), s.layout.view);
  if (!p.visible || !s.layout.view.contains(p.x, p.y)) return "";
  char text[64];
  std::snprintf(text, sizeof text, "%.2f %.2f", p.x, p.y);
  position_text = text;
  return position_text.c_str();
}

}  // extern "C"
