#pragma once
// What the window shows and edits: the preset being run, the edited draft of it, the live run,
// the camera and the display options. Panels read and change this; app.cpp draws it.

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "access/theme_palette.h"
#include "i18n/language.h"
#include "ui/state/camera.h"
#include "ui/state/colour_map.h"
#include "ui/state/instruments.h"
#include "ui/state/lesson_session.h"
#include "ui/state/live_run.h"
#include "ui/state/plot_exports.h"
#include "ui/state/plot_series.h"
#include "ui/state/plot_tab.h"
#include "ui/state/preset_store.h"
#include "ui/state/save_request.h"
#include "ui/state/screen_layout.h"
#include "ui/state/time_travel.h"

namespace swarmlab {

enum class SpringOverlay { off, pairs, to_cm };

struct ViewOptions {
  ColourBy colour_by = ColourBy::speed;
  float particle_size = 1.0f;  ///< multiplies the automatic size
  bool container = true;
  bool centre_of_mass = true;
  bool trails = true;
  bool orbit = true;   ///< the analytic orbit ahead of the selected particle
  bool ghosts = true;  ///< analytic positions beside a numerical run
  bool axes = true;
  bool follow_cm = false;
  bool auto_reframe = true;  ///< back away when an isolated run flies apart (App::update_camera)
  SpringOverlay springs = SpringOverlay::off;
};

struct PlotOptions {
  double average_window = 0;  ///< running average of P and T over this time; 0: none
  double scroll_window = 0;   ///< show the last stretch of this length; 0: the whole run
  bool log_log = true;        ///< P-V, T-V, P-T on log-log axes
  std::optional<PlotTab> tab;        ///< tab to select on the next frame; none: leave as is
  std::optional<PlotTab> shown_tab;  ///< the tab open in the last frame
  unsigned tab_window = 0;    ///< an ImGui id of the window that drew the tabs last frame
  bool tabs_wrapped = false;  ///< the last frame drew the tabs wrapped (wrapping_tabs.h)
};

struct Layout {
  static constexpr float kMinUiScale = 0.75f, kMaxUiScale = 2.5f, kUiScaleStep = 0.25f;

  bool controls = true, plots = true, help = false;
  float ui_scale = 1.0f;
  float pending_ui_scale = 1.0f;  ///< applied between frames by the main loop
  bool resize_panels = false;     ///< fit the panels to the window again (after a new scale)
  ViewRect view;                  ///< the 3D view: the window minus the panels

  // Screen layouts (screen_layout.h) and touch.
  LayoutMode mode = LayoutMode::automatic;  ///< View > Layout, or swarmlab.set({layout})
  ScreenLayout screen;                      ///< this frame's rectangles
  /// Measured on the last frame: the transport bar's and the read-outs strip's height.
  float transport_height = 0, readouts_height = 0;
  float bottom_strip_height = 0;  ///< reserved under the view for strips of other features
  /// This frame was laid out with the heights it measured, at the scale asked for: the next
  /// lays out the same (state().layout_settled, what a test waits for after a resize).
  bool settled = false;
  bool touch = false;             ///< the last pointer was a finger: larger targets
  /// The timeline's bar as last drawn: a finger drags it as it lands (touch_gestures.h).
  ViewRect drag_at_once{0, 0, 0, 0};
  struct Panel {
    std::string name;
    ScreenRect rect;
    float scroll = 0;  ///< pixels scrolled down
    float scroll_max = 0;  ///< pixels it can scroll down at most
  };
  std::vector<Panel> panels;  ///< every window drawn this frame, for swarmlab.state()
  /// For swarmlab.state() too: the menus' titles in the menu bar, and the windows floating over
  /// the rest (the welcome, the help, an open menu or popup) with their close button if any.
  std::vector<Panel> menus;
  struct FloatingWindow {
    std::string name;
    ScreenRect rect, close;  ///< close: empty without a close button
    float scroll = 0;        ///< pixels scrolled down
  };
  std::vector<FloatingWindow> windows;
  /// The compact layouts' drawer of tabs: the part open (its English name), kept across the two
  /// ways of drawing the tabs, and whether the last frame drew them wrapped (wrapping_tabs.h).
  std::string drawer_open;
  bool drawer_tabs_wrapped = false;

  /// One step larger (+1) or smaller (-1), within the limits (menu and Ctrl +/-).
  void step_ui_scale(int direction) {
    pending_ui_scale = std::clamp(ui_scale + float(direction) * kUiScaleStep, kMinUiScale,
                                  kMaxUiScale);
  }
};

/// Frame timing, smoothed, in milliseconds.
struct FrameStats {
  double frame_ms = 16, simulation_ms = 0, scene_ms = 0;
  double step_ms = 0.05;   ///< one step of every method run side by side
  double speed_ratio = 1;  ///< simulated speed achieved / requested (< 1: the budget ran out)
  long frames = 0;
  bool idle = false;  ///< nothing moves: frames come only on a change, so no frame rate
};

/// The projector and the classroom: theme, presentation mode, fullscreen, sound
/// (presentation.h switches them; classroom_outputs.h carries them out on the window).
struct Presentation {
  Theme theme = Theme::dark;
  bool on = false;                 ///< presentation mode: light, large, the view and one plot
  bool fullscreen = false;         ///< as the window or page last reported it
  bool fullscreen_wanted = false;  ///< what the user asked for; the adapter tries it
  bool sound = false;              ///< clicks at the wall hits; off until turned on
  std::string sound_status;        ///< why sound could not start, "" when fine
  // A page in a hidden tab (the browser): its run pauses unless the teacher keeps it running.
  bool can_be_hidden = false;        ///< the window is a page, which another tab can hide
  bool run_while_hidden = false;     ///< the teacher's choice: a hidden page's run goes on
  bool paused_while_hidden = false;  ///< the run was paused when the page was hidden
  // What presentation mode replaced, given back when it ends.
  bool saved_controls = true, saved_plots = true;
  float saved_ui_scale = 1;
  Theme saved_theme = Theme::dark;
};

/// The language the UI speaks (app/i18n/), and the one asked for: a new language may need another
/// font atlas, so the main loop switches between frames.
struct LanguageChoice {
  std::string code = source_language().code;
  std::string pending;  ///< "" when none is asked for
  /// Remember the choice for the next visit (View > Language, a link's #lang=); a scripted or
  /// tested run does not.
  bool remember = true;
};

/// What the controls remember between frames beside the draft they edit.
struct ControlsMemory {
  double coupling_magnitude = 1.0;   ///< |J|, kept through a trip to J = 0 ("zero" and back)
  std::string drag_particles;        ///< the drag's particle list as typed
  std::string drag_particles_shown;  ///< the draft's list the field was last filled from
};

/// Which part of the controls an edit came from, to show a refusal next to it.
enum class Section { none, scenario, system, container, simulation, forces, walls };

struct AppState {
  std::unique_ptr<PresetStore> store;
  std::vector<ShippedPreset> shipped;

  swarm::Preset origin;  ///< as opened: "Reset to preset" returns here
  swarm::Preset preset;  ///< running, always valid
  swarm::Preset draft;   ///< edited in the panels; applied only when valid
  std::string draft_error;
  Section draft_error_section = Section::none;
  ControlsMemory controls_memory;
  bool modified = false;   ///< preset differs from origin
  std::string location;    ///< the path field of open and save
  std::string shipped_id;  ///< the shipped preset opened last, empty after opening a file
  std::string status;      ///< last open or save result
  bool status_is_error = false;
  /// Draws the scenario panel's storage controls in place of the path field with Open and
  /// Save, when set: the browser build's Open preset, Download preset and Copy link.
  std::function<void(AppState&)> storage_controls;

  std::unique_ptr<LiveRun> run;
  int engine_threads = 0;  ///< threads of the runs' engines (desktop --threads); 0: the default
  bool playing = true;
  double speed = 1;        ///< simulated time per second of wall time
  double step_debt = 0;    ///< fractional steps carried to the next frame
  bool step_once = false;  ///< single step requested while paused
  TimeTravel travel;       ///< a seek or fast-forward under way (time_travel.h)
  long travels_started = 0;             ///< the last travel's id
  std::vector<TravelEnd> travel_ends;   ///< the page's seeks that ended, until it reads them
  FastForwardRecord last_fast_forward;  ///< kept after it ends (time_travel.h)
  /// Frames run with a fixed wall-clock step and no time budget (--frames, screenshots), so
  /// that the picture does not depend on the machine's speed.
  bool fixed_frame_time = false;

  OrbitCamera camera;
  bool reframe = true;  ///< fit the camera to the scene on the next frame
  float scene_radius = 1;
  float framed_radius = 1;        ///< the container radius the camera distance was set for
  float particle_radius = 0.05f;  ///< world radius of the heaviest particle at size 1
  double heaviest_mass = 1;
  std::optional<std::size_t> selected;
  ColourScale colour_scale;
  ViewOptions view;
  PlotOptions plots;
  PlotExports plot_exports;  ///< a plot's export on its way to the save dialog (plot_exports.h)
  /// The plots' series computed from the live run, kept between frames (plot_series.h).
  SampleSeries sample_series;
  ProjectCache project_cache;
  SaveDialog save_dialog;  ///< save, export and quit dialogs (save_request.h)
  Layout layout;
  Presentation presentation;
  LanguageChoice language;
  /// Inside a course page (?embed, ui/classroom/embedding.h): no menu bar, no welcome.
  bool embedded = false;
  FrameStats stats;
  /// Stopwatch, period meter, P and T (Instruments::update feeds them every frame).
  Instruments instruments;
  /// The shipped lessons, the open one and the student's progress (lesson_session.h).
  LessonSession lessons;
  /// Times a lesson step's run started again at its end ("loop"), kept for lessonState().
  int lesson_loops = 0;

  /// Opens a valid preset: it becomes origin, preset and draft; the run restarts.
  void open(const swarm::Preset& p, std::string location);
  /// Opens a preset given as JSON text (a share link, a file picked in the browser). A preset
  /// that fails validation leaves the running one alone; the message (as in the CLI) is
  /// returned and shown in the scenario panel.
  std::string open_json(const std::string& json, std::string location);
  /// Validates the draft; applies it and restarts the run, or keeps the running preset and
  /// records the reason next to `section`. Returns whether it was applied.
  bool apply_draft(Section section);
  /// Drops a refused draft: the panels show the running preset again.
  void revert_draft();
  /// Restarts the run from the running preset's initial state.
  void restart();
  /// The trails to keep: the selected particle, and every particle of a small system.
  void update_followed();
  /// Selects particle `index` of the running system (none: no selection), as a click on it
  /// does. Returns false, changing nothing, when there is no such particle.
  bool select_particle(std::optional<std::size_t> index);
};

}  // namespace swarmlab
