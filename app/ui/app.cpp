#include "ui/app.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <limits>
#include <utility>

#include "i18n/translator.h"
#include "swarm/physics/system.h"
#include "ui/classroom/presentation.h"
#include "ui/input/shortcuts.h"
#include "ui/kit/touch_target.h"
#include "ui/lesson_player/lesson_panel.h"
#include "ui/lesson_player/lesson_scene.h"
#include "ui/panels/panels.h"
#include "ui/panels/windows.h"
#include "ui/platform/save_dialog.h"
#include "ui/plots/plot_export.h"
#include "ui/time/time_controls.h"
#include "ui/time/timeline_strip.h"
#include "ui/view/scene_overlay.h"

namespace swarmlab {
namespace {

using Clock = std::chrono::steady_clock;

/// The windows over the rest (top-level, not the panels or strips: those are NoMove) as drawn
/// this frame, with the close button where ImGui puts it (RenderWindowTitleBarContents), in
/// this frame's style: for swarmlab.state().
void record_floating_windows(AppState& s) {
  s.layout.windows.clear();
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  const ImGuiStyle& style = g.Style;
  for (const ImGuiWindow* w : g.Windows) {
    if (!w->Active || w->Hidden || w->IsFallbackWindow) continue;
    if (w->Flags & ImGuiWindowFlags_ChildWindow) continue;
    if ((w->Flags & ImGuiWindowFlags_NoMove) && !(w->Flags & ImGuiWindowFlags_Popup)) continue;
    if (w->Flags & ImGuiWindowFlags_Tooltip) continue;
    Layout::FloatingWindow f{std::string(translator().english_label(w->Name)),
                             {w->Pos.x, w->Pos.y, w->Size.x, w->Size.y}, {}, w->Scroll.y};
    if (w->HasCloseButton && !(w->Flags & ImGuiWindowFlags_NoTitleBar)) {
      const float side = g.FontSize + 2 * style.FramePadding.x;
      f.close = {w->Pos.x + w->Size.x - 2 * style.FramePadding.x - g.FontSize, w->Pos.y, side,
                 g.FontSize + 2 * style.FramePadding.y};
    }
    s.layout.windows.push_back(std::move(f));
  }
}

/// A finger dragging on a window that floats over the view (the welcome, the help, a menu)
/// scrolls it; the panels scroll themselves (panel_windows.cpp). ImGui's hovered window is the
/// frontmost under the finger (the main loop put the mouse there).
void scroll_floating_window(const TouchFrame& t) {
  if (!t.pointer || t.scroll_y == 0) return;
  ImGuiWindow* w = ImGui::GetCurrentContext()->HoveredWindow;
  if (!w ||
      ((w->RootWindow->Flags & ImGuiWindowFlags_NoMove) && !(w->Flags & ImGuiWindowFlags_Popup)))
    return;
  ImGui::SetScrollY(w, std::clamp(w->Scroll.y + t.scroll_y, 0.0f, w->ScrollMax.y));
}

constexpr const char* kFirstPreset = "fig1-four-masses.json";
/// Stepping may take this much of a frame, and at low frame rates (a school Chromebook, a
/// loaded machine) up to this share of the frame's time, so that the run keeps its speed by
/// drawing less often rather than stepping less; beyond the budget it runs slower than asked,
/// says so, and the window still answers.
constexpr double kStepBudgetMs = 20;
constexpr double kStepBudgetShare = 0.5;
constexpr double kMaxStepBudgetMs = 50;
/// A frame longer than this (a dragged window, a very slow device) is made up in steps only up
/// to this long, and counts as running slower than asked.
constexpr double kStallSeconds = 1.0;
constexpr double kSpeedRatioSeconds = 1.0;  ///< the speed reached is averaged over this long
constexpr double kFixedFrameSeconds = 1.0 / 60;
/// A fast-forward or seek steps for this long in a frame: as fast as the machine allows while
/// the window still answers (about 20 frames a second).
constexpr double kTravelBudgetMs = 40;

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

bool App::run_moving() const {
  const AppState& s = state_;
  return (s.playing && !s.run->finished()) || s.travel.active() || s.step_once;
}

bool App::moving() const {
  const AppState& s = state_;
  return run_moving() || touch_.active() || !s.language.pending.empty() ||
         s.layout.pending_ui_scale != s.layout.ui_scale || !s.layout.settled ||
         s.layout.resize_panels;
}

void App::update(double real_seconds) {
  FrameStats& stats = state_.stats;
  // By the run alone: a frame-rate row that changed with the layout's settling would unsettle
  // the layout it is drawn in (a new width, a new wrap), and the window would never idle.
  stats.idle = !run_moving();
  if (!stats.idle) smooth(stats.frame_ms, real_seconds * 1000);
  ++stats.frames;
  // An open lesson's own translations into the language in use come before the tables.
  const Lesson* lesson = state_.lessons.open_lesson();
  const std::map<std::string, std::string>* own = nullptr;
  if (lesson)
    if (const auto it = lesson->translations.find(translator().language().code);
        it != lesson->translations.end())
      own = &it->second;
  // Named by the lesson and where its texts live, so a lesson opened again is read again.
  translator().use_lesson_texts(
      own ? lesson->id + "@" + std::to_string(reinterpret_cast<std::uintptr_t>(own)) : "", own);
  handle_shortcuts(state_);
  advance_simulation(state_.fixed_frame_time ? kFixedFrameSeconds : real_seconds);
  state_.instruments.update(*state_.run, state_.selected, state_.plots.average_window,
                            state_.preset.container_radius.has_value());
  layout_windows();
  scroll_floating_window(touch_frame_);
  handle_view_input();
  update_camera();
  const Clock::time_point start = Clock::now();
  build_particles();
  smooth(stats.scene_ms, milliseconds_since(start));
  draw_scene_overlay(state_);
  handle_plot_export(state_);
  draw_save_dialogs(state_);
}

void App::advance_simulation(double seconds) {
  AppState& s = state_;
  if (s.travel.active()) {  // a seek or fast-forward, a frame's budget at a time
    continue_travel(s, kTravelBudgetMs);
    return;
  }
  long steps = 0;
  double wanted = 0, asked = 0;
  if (s.step_once) {
    steps = 1;
    s.step_once = false;
  } else if (s.playing && !s.run->finished()) {
    s.step_debt += s.speed * std::min(seconds, kStallSeconds) / s.preset.dt;
    wanted = std::floor(s.step_debt);
    asked = wanted * std::max(1.0, seconds / kStallSeconds);
    s.step_debt -= wanted;
    steps = long(std::min(wanted, 1e9));
    if (!s.fixed_frame_time) {
      const double budget_ms =
          std::clamp(kStepBudgetShare * 1000 * seconds, kStepBudgetMs, kMaxStepBudgetMs);
      steps = std::min(steps, std::max(1L, long(budget_ms / std::max(s.stats.step_ms, 1e-6))));
    }
  }
  const Clock::time_point start = Clock::now();
  const long taken = steps > 0 ? s.run->advance(steps) : 0;
  if (s.playing) keep_lesson_run_going(s);  // a lesson step's run never ends while it is read
  const double ms = milliseconds_since(start);
  if (taken > 0) smooth(s.stats.step_ms, ms / double(taken));
  smooth(s.stats.simulation_ms, ms);
  // Averaged over about a second of the run, however few frames that is.
  if (asked >= 1)
    s.stats.speed_ratio += (1 - std::exp(-seconds / kSpeedRatioSeconds)) *
                           (double(steps) / asked - s.stats.speed_ratio);
  else if (!s.playing)
    s.stats.speed_ratio = 1;
  if (s.run->finished()) {
    s.playing = false;
    // Validation keeps a preset's numbers finite; should one still overflow, say so.
    if (const std::string& failure = s.run->primary().failure(); !failure.empty()) {
      char text[800];
      std::snprintf(text, sizeof text, tr("The run stopped: %s"), failure.c_str());
      s.status = text;
      s.status_is_error = true;
    }
  }
}

void App::layout_windows() {
  AppState& s = state_;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float font = ImGui::GetFontSize();
  float top = viewport->Pos.y;
  s.layout.panels.clear();
  s.layout.drag_at_once = {0, 0, 0, 0};  // until the timeline draws its bar

  // Fingers need larger targets than a mouse: in a touch or compact layout (as last laid
  // out) every frame (button, field, slider, a window's close button, the menu bar) is at least
  // kTouchTargetPx tall, the size WCAG asks of touch targets, and so is every menu's row.
  const bool roomy = s.layout.touch || s.layout.screen.kind != LayoutKind::wide;
  const float pad_y = std::max(0.45f * font, 0.5f * (kTouchTargetPx - font));
  if (roomy) {
    // Taller, not wider: the particle table's cells need their width for digits.
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(0.3f * font, pad_y));
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(0.5f * font, kTouchTargetPx - font));
    ImGui::PushStyleVar(ImGuiStyleVar_ScrollbarSize, 1.1f * font);
  }
  if (!s.embedded) top += draw_menu_bar(s);  // a course page wants no menu bar (embedding.h)
  if (roomy) ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(0.5f * font, 0.45f * font));

  ScreenLayoutInput in;
  in.width = viewport->Size.x, in.height = viewport->Size.y;
  in.font = font;
  in.menu_height = top - viewport->Pos.y;
  in.mode = s.layout.mode;
  // An open lesson keeps its column when the controls are closed (presentation mode).
  in.controls = s.layout.controls || s.lessons.open_lesson(), in.plots = s.layout.plots;
  in.transport_height = s.layout.transport_height;
  in.readouts_height = s.layout.readouts_height;
  in.bottom_strip_height = s.layout.bottom_strip_height = timeline_strip_height();
  const ScreenLayout l = screen_layout(in);
  s.layout.screen = l;
  s.layout.resize_panels = false;
  s.layout.view = {l.view.x, l.view.y, std::max(l.view.width, 1.0f), std::max(l.view.height, 1.0f)};
  // The timeline strip (timeline_strip.cpp) under the view.
  draw_timeline_strip(s, l.bottom_strip.x, l.bottom_strip.y, l.bottom_strip.width,
                      l.bottom_strip.height);
  draw_panel_windows(s, l, touch_frame_, &lesson_tab_step_);
  // Rows of 44 px targets over the view need little space between them: the view keeps room.
  if (roomy) ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(0.5f * font, 0.2f * font));
  draw_view_strips(s, l);
  s.layout.settled = in.transport_height == s.layout.transport_height &&
                     in.readouts_height == s.layout.readouts_height &&
                     s.layout.pending_ui_scale == s.layout.ui_scale;
  if (roomy) ImGui::PopStyleVar();
  // The windows over the view get a square close button a finger can hit.
  if (roomy) ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(pad_y, pad_y));
  draw_help_window(s);
  draw_welcome_window(s);
  draw_progress_notice(s);
  record_floating_windows(s);
  if (roomy) ImGui::PopStyleVar();
  if (roomy) ImGui::PopStyleVar(4);
}

void App::handle_view_input() {
  const ImGuiIO& io = ImGui::GetIO();
  const ViewRect& view = state_.layout.view;
  if (state_.layout.touch) {
    // Fingers (touch_gestures.h): ImGui's mouse only ever sees them on the panels.
    const TouchFrame& t = touch_frame_;
    state_.camera.orbit(t.orbit_dx, t.orbit_dy);
    state_.camera.zoom_by(t.zoom);
    state_.camera.pan(t.pan_dx, t.pan_dy, view.height);
    if (t.tap) pick_particle(t.tap_x, t.tap_y);
    dragging_ = false;
    return;
  }
  const bool over_view = !io.WantCaptureMouse && view.contains(io.MousePos.x, io.MousePos.y);
  // The drag turns the camera by the motion of this press (pointer_press.h), never ImGui's
  // MouseDelta, which spans a jump to where a whiteboard presses with no motion before.
  if (over_view && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    dragging_ = true;
    press_.start(io.MousePos.x, io.MousePos.y);
  }
  if (dragging_ && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    const PointerPress::Motion m = press_.move_to(io.MousePos.x, io.MousePos.y);
    state_.camera.orbit(m.dx, m.dy);
  }
  if (dragging_ && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    dragging_ = false;
    // A click that hardly moved selects rather than turns.
    if (press_.is_click()) pick_particle(io.MousePos.x, io.MousePos.y);
  }
  if (over_view && io.MouseWheel != 0) state_.camera.zoom(io.MouseWheel);
  // The right button slides the view, as two fingers do.
  if (over_view && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) panning_ = true;
  if (panning_ && ImGui::IsMouseDown(ImGuiMouseButton_Right))
    state_.camera.pan(io.MouseDelta.x, io.MouseDelta.y, view.height);
  else
    panning_ = false;
}

void App::pick_particle(float x, float y) {
  const swarm::System& s = state_.run->system();
  // A fingertip covers more than a mouse pointer.
  const float reach = (state_.layout.touch ? 1.6f : 0.9f) * ImGui::GetFontSize();
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
    s.camera.reset_pan();
    // An isolated swarm is framed about its centre of mass; a container about itself.
    if (!s.view.follow_cm && !s.preset.container_radius)
      s.camera.set_target(swarm::cm_position(system).cast<float>());
    s.camera.frame(s.scene_radius, s.layout.view.aspect());
    // Small isolated systems (the paper's orbits, mostly in the x-y plane) are seen from high
    // above so that the ellipses show their shape; a swarm in a sphere from lower down.
    s.camera.set_elevation(s.preset.container_radius ? 0.45f : 1.1f);
    s.framed_radius = s.scene_radius;
    s.reframe = false;
    framed_aspect_ = s.layout.view.aspect();
  }
  // A new shape of the view (a phone turned, another layout, a resized window) frames the
  // scene again in what is left of the window.
  if (const float aspect = s.layout.view.aspect(); std::abs(aspect / framed_aspect_ - 1) > 0.2f) {
    s.camera.frame(s.framed_radius, aspect);
    framed_aspect_ = aspect;
  }
  // An isolated run that flies apart (Euler, J < 0) is followed out rather than lost.
  if (s.view.auto_reframe && !s.preset.container_radius) {
    const swarm::Vec3 cm = swarm::cm_position(system);
    double extent = 0;
    for (const swarm::Particle& p : system.particles) extent = std::max(extent, (p.r - cm).norm());
    const float wanted = float(1.15 * extent);
    if (std::isfinite(wanted) && wanted > 1.5f * s.framed_radius) {
      s.camera.reset_pan();
      s.camera.set_target(cm.cast<float>());
      s.camera.scale_distance(wanted / s.framed_radius);
      s.framed_radius = wanted;
    }
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
    // Hard spheres are drawn at their true radius, so contacts look like contacts.
    const float radius = s.preset.sphere_radius ? float(*s.preset.sphere_radius)
                                                : base * float(std::cbrt(p.m * inverse_heaviest));
    particles_[i] = {float(p.r.x()), float(p.r.y()), float(p.r.z()), radius,
                     particle_colour(s.colour_scale.position(q), s.presentation.theme).packed()};
  }
  // Paused, the scale stays put (a colour means the same value while one looks at it).
  if (s.playing || s.step_once || !s.colour_scale.initialised) s.colour_scale.follow(lo, hi);

  ghosts_.clear();
  if (swarm::Run* exact = s.run->analytic_reference(); exact && s.view.ghosts) {
    const swarm::System& e = exact->engine().system();
    ghosts_.reserve(e.particles.size());
    for (const swarm::Particle& p : e.particles)
      ghosts_.push_back({float(p.r.x()), float(p.r.y()), float(p.r.z()),
                         1.35f * base * float(std::cbrt(p.m * inverse_heaviest)),
                         palette(s.presentation.theme).ghost.packed()});
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
