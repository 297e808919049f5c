#pragma once
/// A lesson (JSON, "lesson": 1): a guided path of steps through the app, each of which may set
/// the scene (a preset, a plot, a selected particle, an overlay) and ask a question. A lesson is
/// data, not physics: this library reads and checks it, and marks an answer against a value the
/// caller measured from the running simulation. docs/lessons.md documents every field.

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lessons/lesson_claim.h"
#include "swarm/preset/preset.h"

namespace swarmlab {

inline constexpr int kLessonVersion = 1;

/// The plots panel's tabs a step can open.
enum class LessonPlot { wall, energy, expansion, compare, particle, projects };
/// The Fig. 1 springs drawn over the view: none, every pair, or each particle to the CM.
enum class LessonOverlay { none, springs, springs_to_cm };
/// What a measure task asks for, each read from the running simulation: the period 2 pi / omega
/// (J > 0), omega = sqrt(|J| M), the total mass M, the energy E, the wall pressure P and
/// temperature T (need a container).
enum class Quantity { period, omega, M, E, P, T };
/// What a step can keep off the screen while its task is open, because it would give the
/// answer away: the read-outs (the period, omega, M, E, P, T by formula), the selected
/// particle's card (its period and amplitude) and the plots.
enum class LessonHidden { readouts, card, plots };

struct LessonTask {
  enum class Kind { measure, choice, predict };
  Kind kind = Kind::choice;
  std::string prompt;
  // measure
  Quantity quantity = Quantity::period;
  std::optional<std::size_t> particle;  ///< whose quantity (all share the period); shown only
  double tolerance = 0.02;              ///< relative
  double window = 0;  ///< P and T: averaged over the last this much time (0: the whole run)
  // choice and predict
  std::vector<std::string> options;
  std::optional<std::size_t> answer;  ///< choice: the right option
  std::vector<std::string> feedback;  ///< choice: one per option
  std::string outcome;                ///< predict: what the run shows, revealed after the choice
};

struct LessonStep {
  std::string text;  ///< paragraphs split by a blank line; *emphasis*
  /// The scene: a shipped preset's file name or an inline preset. Empty: keep what runs.
  std::string preset_name;
  std::optional<swarm::Preset> preset;
  std::optional<LessonPlot> plot;
  std::optional<std::size_t> select;
  std::optional<LessonOverlay> overlay;
  /// Kept off the screen while the step is shown and its task is not yet answered.
  std::vector<LessonHidden> hide;
  /// How long the run lasts while the step is shown (and the steps after it in the same scene),
  /// so that it never ends while the student reads: on to at least t = run_until (the run is
  /// continued past the preset's end), or started again from its first moment whenever it
  /// ends (run_loop).
  std::optional<double> run_until;
  bool run_loop = false;
  std::optional<LessonTask> task;
  /// What the step says the simulation does, in a form `swarmlab check-lesson` tests.
  std::vector<LessonClaim> claims;

  bool hides(LessonHidden what) const;
};

struct Lesson {
  std::string id;  ///< lowercase letters, digits and '-': the key of the student's progress
  std::string title;
  std::string summary;
  std::vector<LessonStep> steps;
  /// The lesson's own translations (a teacher's lesson; the shipped ones are in the app's
  /// tables): language code -> English text of this lesson -> the text in that language.
  std::map<std::string, std::map<std::string, std::string>> translations;

  /// Every text of the lesson a student reads: title, summary, and each step's text, prompt,
  /// options, feedback and outcome.
  std::vector<std::string> texts() const;
  /// `english` (one of texts()) in the language `code`: the lesson's own translation, or null.
  const std::string* translation(const std::string& code, const std::string& english) const;
};

/// Finds a shipped preset by file name ("two-body-circular.json"): the preset, or an error
/// (an unknown name). The app passes its shipped list; tests pass their own.
using PresetLookup = std::function<swarm::PresetParse(const std::string& name)>;

/// Either a valid lesson or one message naming the field and the rule it breaks, e.g.
/// "steps[2].task.tolerance: must be > 0".
struct LessonParse {
  std::optional<Lesson> lesson;
  std::string error;
};

/// Refuses text that is not exactly one JSON object (a key given twice, anything after it),
/// more than kMaxLessonBytes, and any field that breaks its rule. Inline presets follow
/// swarm::parse_preset's rules, their messages prefixed "steps[i].preset.".
LessonParse parse_lesson(std::string_view json_text, const PresetLookup& lookup);
inline constexpr std::size_t kMaxLessonBytes = 1'000'000;

/// Whether JSON text is a lesson rather than a preset: an object with a "lesson" key, or text
/// (broken or oversized) whose first key is "lesson".
bool looks_like_lesson(std::string_view json_text);

/// The name used in a lesson file for a plot, an overlay and a quantity ("springs-to-cm").
std::string_view name_of(LessonPlot plot);
std::string_view name_of(LessonOverlay overlay);
std::string_view name_of(Quantity quantity);
std::string_view name_of(LessonTask::Kind kind);
std::string_view name_of(LessonHidden hidden);

/// How a quantity is named in feedback: omega is "ω" for an attracting system and
/// "Ω" (the growth rate) for a repulsive one, as the read-outs and the lessons write it.
std::string quantity_symbol(Quantity quantity, bool repulsive);

/// Lesson text as it is read aloud or mirrored for a screen reader: without its *emphasis*
/// marks.
std::string without_emphasis(std::string_view text);

/// A student's answer, marked.
struct Marking {
  std::optional<bool> correct;  ///< none for a prediction: it is recorded, not marked
  std::string feedback;
};

/// A measured number against the running simulation's value `expected`: right when within the
/// task's relative tolerance of it. The feedback names the quantity as `symbol` writes it
/// (quantity_symbol), and says so when only the sign is wrong.
Marking mark_measurement(const LessonTask& task, double answer, double expected,
                         const std::string& symbol);
/// A picked option (choice: marked, with that option's feedback; predict: recorded, with the
/// outcome to compare it with).
Marking mark_option(const LessonTask& task, std::size_t option);

}  // namespace swarmlab
