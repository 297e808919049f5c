#pragma once
// What a screen reader is told: one sentence saying what runs (the preset, playing or paused,
// the time, P and T in a container, the selected particle, an error), said again when any of
// it changes and, while the run plays, every few seconds for the time. The browser puts it in
// an ARIA live region, and both front ends put the short form in the title.

#include <cstddef>
#include <optional>
#include <string>

namespace swarmlab {

/// The state as a listener needs it (from AppState, see app/ui/announcer.cpp).
struct Situation {
  std::string preset;  ///< the preset's name
  bool playing = false;
  bool finished = false;                ///< the run reached its duration (or stopped on an error)
  double t = 0;                         ///< simulated time
  std::optional<double> P, T;           ///< wall pressure and temperature (only with a container)
  std::optional<std::size_t> selected;  ///< particle index from 0
  std::string error;                    ///< the last error shown, "" when none
  /// What a lesson says now: the welcome, a step with its question, or the feedback on an
  /// answer (app/ui/classroom/classroom_outputs.cpp); "" outside a lesson.
  std::string lesson;
  /// Where the lesson is ("welcome", "<id>/<step>", "<id>/summary") and how many answers it
  /// has had: its words are said when either changes (the same feedback to a second try is said
  /// again), not when only their wording for the device does.
  std::string lesson_place;
  std::size_t lesson_turn = 0;
  /// A notice said once, first, when it appears or changes, and not repeated with the rest
  /// (lesson progress not kept as usual: app/ui/state/progress_record.h); "" when none.
  std::string notice;
};

/// "Four masses (paper Fig. 1). Playing, t = 12.5. P = 0.0312, T = 1.05. Particle 3 selected."
std::string describe(const Situation& s);

/// "Swarm Lab — Four masses (paper Fig. 1), playing": the window's and the page's title.
std::string page_title(const Situation& s);

/// Decides when to speak: at once when the preset, playing or paused, the selection or the
/// error changes; a notice once, first; a lesson's new words (a step, feedback) at once, before the rest, and its
/// feedback again on each new answer; while playing, at most every kTimeInterval seconds of wall
/// time for the time and P and T alone; otherwise never twice the same text.
class Announcer {
 public:
  static constexpr double kTimeInterval = 5;  ///< seconds of wall time

  /// The text to say now, or nothing. wall_seconds: a clock that only moves forward.
  std::optional<std::string> next(const Situation& now, double wall_seconds);

 private:
  std::optional<Situation> last_;
  std::string said_;
  double said_at_ = 0;
};

}  // namespace swarmlab
