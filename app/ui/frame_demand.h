#pragma once
// Whether the window draws a frame now. Paused, with no input and nothing moving, the app draws
// only when something changes: every frame costs a tablet's battery and a Chromebook's fan as
// much paused as playing (in the browser about a core's worth at 30 frames a second).

namespace swarmlab {

/// Now on a steady clock (s): the times FrameDemand is given.
double steady_seconds();

class FrameDemand {
 public:
  /// Frames drawn after the last change before the window idles: ImGui settles a new window's
  /// size, a popup or a scroll over the frame or two after the input that moved it.
  static constexpr int kSettleFrames = 4;
  /// While a text field is edited its caret blinks (ImGui: shown 0.8 s of every 1.2 s), so a
  /// frame is drawn this often (s).
  static constexpr double kCaretSeconds = 0.4;

  /// Something from outside changed what is shown: an input event, a call from the page, a
  /// file or a font that arrived.
  void wake() { settle_ = kSettleFrames; }
  /// Whether to draw a frame at `now` (s, a steady clock).
  bool wanted(double now) const {
    return moving_ || settle_ > 0 || (editing_ && now - last_drawn_ >= kCaretSeconds);
  }
  /// Seconds from `now` until a frame is wanted with nothing else happening (0: now; a large
  /// number: only on a wake). The desktop waits this long for an event.
  double seconds_to_next(double now) const;
  /// After a drawn frame at `now`: whether something moves by itself (a playing run, a seek, a
  /// finger down) and whether a text field is being edited.
  void drawn(double now, bool moving, bool editing);

 private:
  bool moving_ = true;
  bool editing_ = false;
  int settle_ = kSettleFrames;
  double last_drawn_ = 0;  // s
};

}  // namespace swarmlab
