#pragma once
// One frame of Swarm Lab: advance the simulation, lay out the panels, draw the 3D view. The
// same App runs on the desktop (main_loop.cpp from a loop) and in the browser (from
// emscripten_set_main_loop); it knows nothing of windows or files.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ui/input/pointer_press.h"
#include "ui/input/touch_gestures.h"
#include "ui/panels/windows.h"
#include "ui/platform/save_dialog.h"
#include "ui/state/app_state.h"
#include "ui/view/particle_renderer.h"

namespace swarmlab {

class App {
 public:
  /// Opens preset_location through the store, or a shipped preset when it is empty. Needs a
  /// current OpenGL context. On a bad preset, error() says why.
  App(std::unique_ptr<PresetStore> store, const std::string& preset_location,
      bool fixed_frame_time);

  const std::string& error() const { return error_; }
  AppState& state() { return state_; }
  bool quit_requested() const { return quit_ || state_.save_dialog.quit_confirmed; }
  /// The fingers (fed by the main loop) and what they did this frame.
  TouchGestures& touch() { return touch_; }
  void set_touch_frame(const TouchFrame& frame) { touch_frame_ = frame; }
  /// The window's close button: quits, or first asks when there are unsaved edits.
  void request_close() { request_quit(state_); }
  /// Whether the picture moves by itself: a run playing, a seek or a step under way, a finger
  /// down, a new language or size being applied, a layout still settling. Paused and still, the window draws only when
  /// something changes (frame_demand.h).
  bool moving() const;
  /// The run itself moves: playing (not at its end), a seek or a single step under way.
  bool run_moving() const;

  /// Between ImGui::NewFrame() and ImGui::Render(): runs the simulation for one frame that
  /// took real_seconds and builds the whole UI.
  void update(double real_seconds);
  /// After ImGui::Render() and before ImGui's draw data: draws the particles into the 3D view.
  void render_scene(float framebuffer_scale, float window_height);
  /// The GL objects of the 3D view, which a lost context takes away (ui/gl_context_life.h).
  ParticleRenderer& renderer() { return renderer_; }

 private:
  void advance_simulation(double real_seconds);
  void layout_windows();
  void handle_view_input();
  void update_camera();
  void build_particles();
  void pick_particle(float x, float y);

  AppState state_;
  ParticleRenderer renderer_;
  std::vector<ParticleInstance> particles_, ghosts_;
  std::string error_;
  bool quit_ = false;
  TouchGestures touch_;
  TouchFrame touch_frame_;
  /// The lesson step the drawer last showed: a new one brings the Lesson tab to the front.
  LessonTabStep lesson_tab_step_{nullptr, 0};
  float framed_aspect_ = 1;  ///< the view's width / height when the camera distance was set
  bool dragging_ = false;
  PointerPress press_;    ///< the left button's press on the view, while dragging_
  bool panning_ = false;  ///< the right button went down on the view and is held
};

}  // namespace swarmlab
