#pragma once
// The lesson a student has open: which step, what they answered, and their progress over
// visits. Opening a step says what the app is to show (a LessonScene: preset, plot,
// selection, overlay), which lesson_scene.h carries out; between steps the student is free to
// play. The values a measure task is checked against are read from the running simulation
// through the core. lesson_panel.cpp draws it.

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "lessons/lesson.h"
#include "ui/state/live_run.h"
#include "ui/state/progress_record.h"

namespace swarmlab {

/// Where the student's progress lives between visits: a file on the desktop, localStorage in
/// the browser. One JSON text, read once and written on every change (progress_record.h says
/// what is done with which text).
class ProgressStore {
 public:
  virtual ~ProgressStore() = default;
  virtual std::string load() = 0;  ///< "" when there is none yet
  /// Writes the record: "" or why it could not (the session says so once).
  virtual std::string save(const std::string& json) = 0;
  /// Keeps a record that cannot be read under a new name beside it, never over another: that
  /// name, or "" when it could not (the record is then left where it is).
  virtual std::string set_aside(const std::string& text) = 0;
};

/// Keeps nothing between visits (scripted runs and screenshots leave the user's progress alone).
/// Tests read what it holds and make it refuse.
class MemoryProgressStore final : public ProgressStore {
 public:
  explicit MemoryProgressStore(std::string initial = {}) : text(std::move(initial)) {}
  std::string load() override { return text; }
  std::string save(const std::string& json) override;
  std::string set_aside(const std::string& record) override;

  std::string text;                       ///< the record
  std::map<std::string, std::string> aside;  ///< records set aside, by name
  bool refuses = false;                   ///< saves and set-asides fail, as a full storage's
};

std::unique_ptr<ProgressStore> make_memory_progress_store(std::string initial = {});
/// $XDG_CONFIG_HOME/swarmlab/progress.json (or ~/.config/...), written atomically; a record set
/// aside goes beside it as progress.unreadable-<time>.json.
std::unique_ptr<ProgressStore> make_file_progress_store();

/// A student's last answer to one step's task, for the summary.
struct StepAnswer {
  std::string answer;            ///< the number typed or the option picked, as shown
  std::optional<bool> correct;   ///< none for a prediction (recorded, not marked)
  std::size_t tries = 0;         ///< answers given to this task so far
};

/// What a student did in one lesson.
struct LessonProgress {
  std::size_t step = 0;                        ///< where they were
  /// Steps whose task they answered right (a prediction: once made).
  std::set<std::size_t> solved;
  std::map<std::size_t, std::size_t> predicted;  ///< step -> the option they predicted
  std::map<std::size_t, StepAnswer> answers;   ///< step -> the last answer to its task
  bool finished = false;                       ///< Finish was pressed on the last step
};

/// The Lessons menu's note on a lesson: "done" once finished, else the tasks answered right of
/// the tasks it has ("2/5 tasks"; steps without a task do not count), "" before a start.
std::string progress_note(const Lesson& lesson, const LessonProgress* progress);

/// What the app is to show for a step (lesson_scene.h sets it): the preset to open when the
/// step's scene changes, then the step's plot, selection and overlay.
struct LessonScene {
  const LessonStep* preset_step = nullptr;  ///< the step whose preset opens; none: keep the run
  std::string location;                     ///< the name the opened preset is saved under
  const LessonStep* step = nullptr;         ///< the step shown; none when no lesson is open
  bool pause = false;                       ///< a prediction is due: the clock waits for it
};

class LessonSession {
 public:
  /// Loads the shipped lessons (sorted by file name; an invalid one is left out with a message
  /// on stderr) and the progress.
  void load(const std::string& lesson_directory, std::unique_ptr<ProgressStore> store,
            const PresetLookup& lookup);

  const std::vector<Lesson>& shipped() const { return shipped_; }
  const Lesson* open_lesson() const { return open_ ? &*open_ : nullptr; }
  std::size_t step() const { return step_; }
  const LessonStep* current_step() const;
  const LessonProgress* progress_of(const std::string& id) const;

  /// Opens a lesson at the step the student reached last time: the scene to move the app to.
  LessonScene open(const Lesson& lesson);
  /// Opens a lesson from JSON text (a link, a file, the JS API) into *scene: "" or the message,
  /// in which case the running lesson stays.
  std::string open_json(const std::string& json, LessonScene* scene);
  /// Opens a shipped lesson by id into *scene: "" or a message.
  std::string open_id(const std::string& id, LessonScene* scene);
  void close();
  /// Moves to step i (clamped): the scene it shows.
  LessonScene go_to(std::size_t i);
  LessonScene next() { return go_to(step_ + 1); }
  LessonScene back() { return go_to(step_ > 0 ? step_ - 1 : 0); }
  /// Finish on the last step: the lesson is recorded as finished and its summary shown.
  void finish();
  /// Whether the summary (each task, the answer, right or not) is shown in place of a step.
  bool showing_summary() const { return open_ && summary_; }
  /// The lesson from step 1 again, its answers forgotten: the scene of step 1 (its preset
  /// opens again).
  LessonScene restart();
  /// The shipped lesson after the open one, none after the last (or for a lesson from a link).
  const Lesson* next_lesson() const;
  /// Whether the current step keeps `what` off the screen now: it hides it, and its task (if
  /// any) is not yet answered (right, or a prediction made).
  bool hides(LessonHidden what) const;
  /// The step whose "run" (how long the run lasts) applies now: the current step's, else that of
  /// the last step before it in the same scene (a step with a preset starts a new scene). None
  /// when no step of the scene sets it, and while the summary shows.
  const LessonStep* run_step() const;
  /// How many of the open lesson's steps have a task, and how many of them are answered.
  std::size_t task_count() const;
  std::size_t answered_count() const;
  /// "Finished: 4 of 5 tasks done (answered right, or predicted)." for the summary.
  std::string finished_line() const;
  /// The link fragment that opens the open lesson for a student (lesson_link.h): its id when it
  /// is shipped, else its JSON as opened. "" with no lesson open.
  std::string share_fragment() const;
  /// Set by the browser: makes the page's link from a fragment, copies and shows it (the
  /// lesson panel's Share button). Unset on the desktop, which has no page to link to.
  std::function<void(const std::string& fragment)> share;
  /// The running simulation's value of what the current measure task asks for (NaN when the
  /// running system has none, e.g. a period with J <= 0).
  double reading(LiveRun& run) const;
  /// Marks a typed number against reading().
  Marking answer_number(LiveRun& run, double value);
  /// Marks a picked option (choice), or records a prediction and sets *play: the run goes on.
  Marking answer_option(std::size_t option, bool* play);
  const std::optional<Marking>& marking() const { return marking_; }
  /// Answers given since the app started: the panel brings new feedback into view when it
  /// changes.
  std::size_t answer_count() const { return answer_count_; }
  /// The prediction made in the current step, if any (kept over visits).
  std::optional<std::size_t> prediction() const;

  /// The welcome window: shown on the first start (recorded at once, so it appears once), and
  /// from Help and the Lessons menu.
  bool show_welcome = false;
  void dismiss_welcome();

  /// Why progress is not kept as usual now (progress_record.h); none when it is.
  ProgressTrouble progress_trouble() const { return trouble_; }
  /// The notice for progress_trouble() in the language in use, "" when none.
  std::string progress_notice() const { return progress_trouble_text(trouble_, aside_); }
  /// True once for each new trouble: the app then shows the notice and says it aloud.
  bool take_progress_notice();
  /// The progress as the store keeps it: the file a student downloads to keep it.
  std::string progress_json() const;
  /// Progress from such a file, in place of the progress now (and saved where the store
  /// allows): "" or why the file was refused, in the language in use.
  std::string load_progress_json(const std::string& text);
  /// Set by the browser: a file picker whose file goes to load_progress_json (the notice's and
  /// the Lessons menu's Load progress...). Unset on the desktop.
  std::function<void()> pick_progress_file;
  /// The notice window (lesson_panel.h) is up.
  bool show_progress_notice = false;

  /// What the answer field of a measure task holds (the panel edits it).
  std::string typed;
  /// The last refusal of a lesson (a broken link or file), shown in the panel.
  std::string error;

 private:
  void save_progress();
  void read_progress(const std::string& text);
  void trouble(ProgressTrouble t);

  std::vector<Lesson> shipped_;
  std::optional<Lesson> open_;
  std::size_t step_ = 0;
  std::optional<std::size_t> scene_;  ///< the step whose preset the lesson opened last
  std::optional<Marking> marking_;
  bool summary_ = false;
  std::size_t answer_count_ = 0;
  bool open_is_shipped_ = false;  ///< the open lesson is a shipped one (shared by its id)
  std::string open_json_;         ///< the JSON a lesson from a link or file was opened from
  void record_answer(const std::string& answer, const std::optional<bool>& correct);
  std::map<std::string, LessonProgress> progress_;
  bool welcomed_ = false;
  std::unique_ptr<ProgressStore> store_ = make_memory_progress_store();
  ProgressTrouble trouble_ = ProgressTrouble::none;
  std::string aside_;            ///< where an unreadable record was kept
  bool notice_due_ = false;      ///< take_progress_notice() has a new trouble to give
  PresetLookup lookup_;
};

}  // namespace swarmlab
