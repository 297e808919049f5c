#pragma once
// The click of a wall hit, played by the platform: SDL audio on the desktop
// (wall_sound_sdl.cpp), Web Audio in the browser (wall_sound_web.cpp). Which clicks to play is
// decided by access/wall_clicks.h.

#include <string>

namespace swarmlab {

class WallSound {
 public:
  WallSound() = default;
  WallSound(const WallSound&) = delete;
  WallSound& operator=(const WallSound&) = delete;
  ~WallSound() { close(); }

  /// Opens the audio output; "" when it plays, else why not (no audio device). Never throws.
  std::string open();
  void close();
  bool is_open() const { return open_; }
  /// Plays `clicks` clicks spread evenly over the next `seconds`; false when they were
  /// dropped (the output is behind, so they would be heard late).
  bool play(int clicks, double seconds);

 private:
  bool open_ = false;
  [[maybe_unused]] unsigned device_ = 0;  // SDL_AudioDeviceID on the desktop
};

}  // namespace swarmlab
