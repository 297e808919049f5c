#pragma once
// What the window does beyond drawing, each frame, for the classroom: applies the theme, goes
// fullscreen or back (SDL on the desktop, the Fullscreen API in the browser), keeps the title
// and the browser's ARIA live region saying what runs, and clicks at the wall hits.

#include <SDL.h>

#include <cstdint>
#include <string>

#include "access/announcement.h"
#include "access/wall_clicks.h"
#include "ui/platform/wall_sound.h"
#include "ui/state/app_state.h"

namespace swarmlab {

class ClassroomOutputs {
 public:
  /// Between frames (a new theme rebuilds ImGui's style).
  void apply_theme(AppState& state);
  /// After the frame's update: fullscreen, title and live region, sound. seconds: the frame's
  /// wall time.
  void update(AppState& state, SDL_Window* window, double seconds);

  /// What the wall clicks did since sound was last turned on: the desktop's --frames summary
  /// reports it, so a test can match the audio output against the wall hits.
  struct SoundTally {
    std::int64_t hits = 0;            ///< wall hits while sound was on
    double seconds = 0;               ///< wall time of those frames
    std::int64_t clicks_played = 0;   ///< clicks handed to the audio output
    std::int64_t clicks_dropped = 0;  ///< clicks left out because the output was behind
  };
  const SoundTally& sound_tally() const { return tally_; }

 private:
  void update_fullscreen(AppState& state, SDL_Window* window);
  void update_sound(AppState& state, double seconds);

  Theme theme_ = Theme::dark;
  bool fullscreen_requested_ = false;
  bool fullscreen_seen_ = false;
  Announcer announcer_;
  double wall_seconds_ = 0;
  std::string title_;
  WallSound sound_;
  WallClicks clicks_;
  long run_id_ = -1;
  std::int64_t hits_ = 0;  // the run's wall hits at the last frame
  SoundTally tally_;
};

/// The state as a listener needs it.
Situation situation_of(AppState& state);

}  // namespace swarmlab
