// swarmlab.state(): what the app shows and runs, as one JSON object, for course pages and
// tests. Each feature adds its own fields here (web/README.md lists them).

#include <emscripten.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <nlohmann/json.hpp>
#include <string>

#include "web_app.h"

namespace {

std::string state_text;  // valid until the next call

nlohmann::json app_state_json(swarmlab::App& app) {
  const swarmlab::AppState& s = app.state();
  nlohmann::json j;
  j["name"] = s.preset.name;
  j["edited"] = s.modified;
  j["playing"] = s.playing;
  j["t"] = s.run->time();
  j["speed"] = s.speed;
  j["selected"] = s.selected ? nlohmann::json(*s.selected) : nlohmann::json(nullptr);
  // The projector and the classroom (app/ui/presentation.h).
  j["theme"] = swarmlab::theme_name(s.presentation.theme);
  j["presentation"] = s.presentation.on;
  j["sound"] = s.presentation.sound;
  j["fullscreen"] = s.presentation.fullscreen;
  // The panel keyboard navigation is in ("Controls", "Plots", "transport", "menu"), or null.
  const ImGuiContext* imgui = ImGui::GetCurrentContext();
  const ImGuiWindow* nav = imgui ? imgui->NavWindow : nullptr;
  if (nav && imgui->NavLayer == ImGuiNavLayer_Menu) j["keyboard_focus"] = "menu";
  else if (nav) j["keyboard_focus"] = std::string(nav->Name).substr(nav->Name[0] == '#' ? 2 : 0);
  else j["keyboard_focus"] = nullptr;
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

}  // extern "C"
