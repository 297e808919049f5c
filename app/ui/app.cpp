#include "app.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "lesson_panel.h"
#include "panels.h"
#include "scene_overlay.h"
#include "shortcuts.h"
#include "swarm/system.h"

namespace swarmlab {
namespace {

using Clock = std::chrono::steady_clock;

constexpr const char* kFirstPreset = "fig1-four-masses.json";
/// Stepping may take this much of a frame; beyond it the simulation runs slower than asked
/// rather than the window freezing.
constexpr double kStepBudgetMs = 20;
constexpr double kFixedFrameSeconds = 1.0 / 60;

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void smooth(double& average, double sample) { average += 0.1 * (sample - average); }

/// Used only when no shipped preset can be found (an installed binary without its assets).
swarm::Preset builtin_preset() {
  swarm::Preset p;
  p.name = "Attractive swarm in a sphere";
  p.description = "1,000 particles attracting each other inside a fixed sphere.";
  p.J = 1e-3;
  swarm::SwarmSpec g;
  g.count = 1000;
  g.seed = 2025;
  p.particles = g;
  p.container_radius = 1.0;
  p.dt = 0.01;
  p.duration = 100;
  return p;
}

}  // namespace

App::App(std::unique_ptr<PresetStore> store, const std::string& preset_location,
         bool fixed_frame_time) {
  state_.store = std::move(store);
  state_.fixed_frame_time = fixed_frame_time;
  state_.shipped = state_.store->shipped();
  if (!preset_location.empty()) {
    const swarm::PresetParse parsed = state_.store->open(preset_location);
    if (!parsed.preset) {
      error_ = parsed.error;
      state_.open(builtin_preset(), "");
      return;
    }
    state_.open(*parsed.preset, preset_location);
    return;
  }
  auto first = std::find_if(state_.shipped.begin(), state_.shipped.end(),
                            [](const ShippedPreset& s) { return s.id == kFirstPreset; });
  if (first == state_.shipped.end()) first = state_.shipped.begin();
  if (first != state_.shipped.end()) {
    state_.open(first->preset, "my-" + first->id);
    state_.shipped_id = first->id;
  } else {
    state_.open(builtin_preset(), "my-preset.json");
  }
}

void App::update(double real_seconds) {
  FrameStats& stats = state_.stats;
  smooth(stats.frame_ms, real_seconds * 1000);
  ++stats.frames;
  handle_shortcuts(state_);
  advance_simulation(state_.fixed_frame_time ? kFixedFrameSeconds : real_seconds);
  layout_windows();
  handle_view_input();
  update_camera();
  const Clock::time_point start = Clock::now();
  build_particles();
  smooth(stats.scene_ms, milliseconds_since(start));
  draw_scene_overlay(state_);
}

void App::advance_simulation(double seconds) {
  AppState& s = state_;
  long steps = 0;
  double wanted = 0;
  if (s.step_once) {
    steps = 1;
    s.step_once = false;
  } else if (s.playing && !s.run->finished()) {
    // A long stall (a dragged window) must not turn into a burst of catch-up steps.
    s.step_debt += s.speed * std::min(seconds, 0.1) / s.preset.dt;
    wanted = std::floor(s.step_debt);
    s.step_debt -= wanted;
    steps = long(std::min(wanted, 1e9));
    if (!s.fixed_frame_time)
      steps = std::min(steps, std::max(1L, long(kStepBudgetMs / std::max(s.stats.step_ms, 1e-6))));
  }
  const Clock::time_point start = Clock::now();
  const long taken = steps > 0 ? s.run->advance(steps) : 0;
  const double ms = milliseconds_since(start);
  if (taken > 0) smooth(s.stats.step_ms, ms / double(taken));
  smooth(s.stats.simulation_ms, ms);
  if (wanted >= 1)
    smooth(s.stats.speed_ratio, double(steps) / wanted);
  else if (!s.playing)
    s.stats.speed_ratio = 1;
  if (s.run->finished()) {
    s.playing = false;
    // Validation keeps a preset's numbers finite; should one still overflow, say so.
    if (const std::string& failure = s.run->primary().failure(); !failure.empty()) {
      s.status = "The run stopped: " + failure;
      s.status_is_error = true;
    }
  }
}

void App::layout_windows() {
  AppState& s = state_;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float font = ImGui::GetFontSize();
  float top = viewport->Pos.y;

  if (ImGui::BeginMainMenuBar()) {
    if (ImGui::BeginMenu("Scenario")) {
      for (const ShippedPreset& p : s.shipped)
        if (ImGui::MenuItem(p.preset.name.empty() ? p.id.c_str() : p.preset.name.c_str(), nullptr,
                            s.shipped_id == p.id)) {
          s.open(p.preset, "my-" + p.id);
          s.shipped_id = p.id;
        }
      ImGui::Separator();
      if (ImGui::MenuItem("Quit")) quit_ = true;
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
      ImGui::MenuItem("Controls", "1", &s.layout.controls);
      ImGui::MenuItem("Plots", "2", &s.layout.plots);
      if (ImGui::MenuItem("Larger UI", "Ctrl +")) s.layout.step_ui_scale(+1);
      if (ImGui::MenuItem("Smaller UI", "Ctrl -")) s.layout.step_ui_scale(-1);
      ImGui::EndMenu();
    }
    draw_lessons_menu(s);
    if (ImGui::MenuItem("Help")) s.layout.help = !s.layout.help;
    const std::string title = "Swarm Lab  \u2014  " + s.preset.name;
    const float w = ImGui::CalcTextSize(title.c_str()).x;
    ImGui::SameLine(std::max(ImGui::GetCursorPosX() + font, 0.5f * (viewport->Size.x - w)));
    ImGui::TextDisabled("%s", title.c_str());
    top += ImGui::GetWindowSize().y;
    ImGui::EndMainMenuBar();
  }
  const float height = viewport->Size.y - (top - viewport->Pos.y);
  const ImGuiWindowFlags panel =
      ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
  float left = viewport->Pos.x, right = viewport->Pos.x + viewport->Size.x;

  if (s.layout.controls) {
    ImGui::SetNextWindowPos(ImVec2(left, top));
    ImGui::SetNextWindowSize(ImVec2(std::min(22 * font, 0.3f * viewport->Size.x), height),
                             s.layout.resize_panels ? ImGuiCond_Always : ImGuiCond_Appearing);
    ImGui::SetNextWindowSizeConstraints(
        ImVec2(std::min(15 * font, 0.2f * viewport->Size.x), height), ImVec2(40 * font, height));
    if (ImGui::Begin("Controls", &s.layout.controls, panel)) {
      auto section = [&](const char* title, bool open_first, void (*body)(AppState&)) {
        ImGui::SetNextItemOpen(open_first, ImGuiCond_Once);
        if (ImGui::CollapsingHeader(title)) {
          ImGui::PushID(title);
          body(s);
          ImGui::PopID();
          ImGui::Spacing();
        }
      };
      section("Scenario", true, draw_scenario_panel);
      section("System", true, draw_system_panel);
      section("Container", bool(s.preset.container_radius), draw_container_panel);
      section("Simulation", true, draw_simulation_panel);
      section("View", false, draw_view_panel);
    }
    left += ImGui::GetWindowWidth();
    ImGui::End();
  }
  if (s.layout.plots) {
    ImGui::SetNextWindowPos(ImVec2(right, top), ImGuiCond_Always, ImVec2(1, 0));
    ImGui::SetNextWindowSize(ImVec2(std::min(25 * font, 0.34f * viewport->Size.x), height),
                             s.layout.resize_panels ? ImGuiCond_Always : ImGuiCond_Appearing);
    ImGui::SetNextWindowSizeConstraints(
        ImVec2(std::min(16 * font, 0.2f * viewport->Size.x), height), ImVec2(60 * font, height));
    if (ImGui::Begin("Plots", &s.layout.plots, panel)) draw_plots_panel(s);
    right -= ImGui::GetWindowWidth();
    ImGui::End();
  }
  s.layout.resize_panels = false;
  s.layout.view = {left, top, std::max(right - left, 1.0f), std::max(height, 1.0f)};

  // Over the 3D view: the transport bar along the top, the read-outs below it.
  const ImGuiWindowFlags overlay = ImGuiWindowFlags_NoDecoration |
                                   ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoFocusOnAppearing;
  ImGui::SetNextWindowPos(ImVec2(left + 0.5f * font, top + 0.5f * font));
  ImGui::SetNextWindowBgAlpha(0.75f);
  if (ImGui::Begin("##transport", nullptr, overlay)) draw_transport_bar(s);
  const float below = top + 0.5f * font + ImGui::GetWindowHeight() + 0.4f * font;
  ImGui::End();
  ImGui::SetNextWindowPos(ImVec2(left + 0.5f * font, below));
  ImGui::SetNextWindowBgAlpha(0.55f);
  if (ImGui::Begin("##readouts", nullptr, overlay)) draw_readouts(s);
  ImGui::End();
  draw_help_window(s);
  draw_lesson_window(s);
  draw_welcome_window(s);
}

void App::handle_view_input() {
  const ImGuiIO& io = ImGui::GetIO();
  const ViewRect& view = state_.layout.view;
  const bool over_view = !io.WantCaptureMouse && view.contains(io.MousePos.x, io.MousePos.y);
  if (over_view && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    dragging_ = true;
    drag_distance_ = 0;
  }
  if (dragging_ && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    state_.camera.orbit(io.MouseDelta.x, io.MouseDelta.y);
    drag_distance_ += std::abs(io.MouseDelta.x) + std::abs(io.MouseDelta.y);
  }
  if (dragging_ && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    dragging_ = false;
    // A click that hardly moved selects rather than turns.
    if (drag_distance_ < 4) pick_particle(io.MousePos.x, io.MousePos.y);
  }
  if (over_view && io.MouseWheel != 0) state_.camera.zoom(io.MouseWheel);
}

void App::pick_particle(float x, float y) {
  const swarm::System& s = state_.run->system();
  const float reach = 0.9f * ImGui::GetFontSize();
  float best = reach * reach;
  std::optional<std::size_t> picked;
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    const ScreenPoint p = state_.camera.project(s.particles[i].r.cast<float>(), state_.layout.view);
    if (!p.visible) continue;
    const float d = (p.x - x) * (p.x - x) + (p.y - y) * (p.y - y);
    if (d < best) best = d, picked = i;
  }
  state_.selected = picked;
  state_.update_followed();
}

void App::update_camera() {
  AppState& s = state_;
  const swarm::System& system = s.run->system();
  if (s.view.follow_cm)
    s.camera.set_target(swarm::cm_position(system).cast<float>());
  else if (s.reframe)
    s.camera.set_target(Eigen::Vector3f::Zero());
  if (s.reframe) {
    // An isolated swarm is framed about its centre of mass; a container about itself.
    if (!s.view.follow_cm && !s.preset.container_radius)
      s.camera.set_target(swarm::cm_position(system).cast<float>());
    s.camera.frame(s.scene_radius, s.layout.view.aspect());
    // Small isolated systems (the paper's orbits, mostly in the x-y plane) are seen from high
    // above so that the ellipses show their shape; a swarm in a sphere from lower down.
    s.camera.set_elevation(s.preset.container_radius ? 0.45f : 1.1f);
    s.framed_radius = s.scene_radius;
    s.reframe = false;
  }
  // The camera backs away as an expansion grows the container, keeping the whole wall in view.
  if (const auto R = s.run->primary().engine().container_radius(); R && *R > s.framed_radius) {
    s.camera.scale_distance(float(*R) / s.framed_radius);
    s.framed_radius = float(*R);
  }
  s.camera.update(s.layout.view);
}

void App::build_particles() {
  AppState& s = state_;
  const swarm::System& system = s.run->system();
  ParticleQuantity quantity{s.view.colour_by, swarm::cm_position(system), swarm::stiffness(system)};
  const float base = s.particle_radius * s.view.particle_size;
  const double inverse_heaviest = 1.0 / s.heaviest_mass;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  particles_.resize(system.particles.size());
  for (std::size_t i = 0; i < system.particles.size(); ++i) {
    const swarm::Particle& p = system.particles[i];
    const double q = quantity(p);
    lo = std::min(lo, q);
    hi = std::max(hi, q);
    // Spheres of one density: the radius goes as the cube root of the mass.
    particles_[i] = {float(p.r.x()), float(p.r.y()), float(p.r.z()),
                     base * float(std::cbrt(p.m * inverse_heaviest)), s.colour_scale.colour(q)};
  }
  s.colour_scale.follow(lo, hi);

  ghosts_.clear();
  if (swarm::Run* exact = s.run->analytic_reference(); exact && s.view.ghosts) {
    const swarm::System& e = exact->engine().system();
    ghosts_.reserve(e.particles.size());
    for (const swarm::Particle& p : e.particles)
      ghosts_.push_back({float(p.r.x()), float(p.r.y()), float(p.r.z()),
                         1.35f * base * float(std::cbrt(p.m * inverse_heaviest)),
                         IM_COL32(235, 240, 255, 255)});
  }
}

void App::render_scene(float framebuffer_scale, float window_height) {
  const ViewRect& view = state_.layout.view;
  renderer_.draw(particles_, ParticleStyle::solid, state_.camera, view, framebuffer_scale,
                 window_height);
  renderer_.draw(ghosts_, ParticleStyle::ghost, state_.camera, view, framebuffer_scale,
                 window_height);
}

}  // namespace swarmlab
