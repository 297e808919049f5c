#include "ui/state/lesson_session.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

#include "files/atomic_file.h"
#include "i18n/translator.h"
#include "lessons/lesson_file.h"
#include "lessons/lesson_link.h"
#include "swarm/measure/thermometry.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/physics/regime.h"
#include "files/text_file.h"

namespace swarmlab {
namespace {

using json = nlohmann::json;
constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

class FileProgressStore final : public ProgressStore {
 public:
  FileProgressStore() {
    const char* config = std::getenv("XDG_CONFIG_HOME");
    const char* home = std::getenv("HOME");
    if (config && *config)
      folder_ = std::string(config) + "/swarmlab";
    else if (home && *home)
      folder_ = std::string(home) + "/.config/swarmlab";
  }
  std::string load() override {
    if (folder_.empty()) return {};
    std::string error;
    std::string text = read_text_file(folder_ + "/progress.json", error);
    return error.empty() ? text : std::string();
  }
  std::string save(const std::string& json) override {
    if (folder_.empty()) return tr("no home folder to keep it in");
    std::error_code ignored;
    std::filesystem::create_directories(folder_, ignored);
    const std::string error = write_file_atomically(folder_ + "/progress.json", json + "\n");
    if (!error.empty()) std::fprintf(stderr, "swarmlab: lesson progress not saved: %s\n", error.c_str());
    return error;
  }
  std::string set_aside(const std::string& text) override {
    if (folder_.empty()) return {};
    char stamp[32];
    const std::time_t now = std::time(nullptr);
    std::strftime(stamp, sizeof stamp, "%Y%m%dT%H%M%SZ", std::gmtime(&now));
    std::string path = folder_ + "/progress.unreadable-" + stamp + ".json";
    for (int n = 2; std::filesystem::exists(path); ++n)
      path = folder_ + "/progress.unreadable-" + stamp + "-" + std::to_string(n) + ".json";
    const std::string error = write_file_atomically(path, text);
    if (!error.empty()) {
      std::fprintf(stderr, "swarmlab: unreadable lesson progress not copied: %s\n", error.c_str());
      return {};
    }
    return path;
  }

 private:
  std::string folder_;
};

/// A record's true/false field; anything else (a newer build's, a hand edit) counts as false.
bool flag(const json& j, const char* key) {
  const auto found = j.find(key);
  return found != j.end() && found->is_boolean() && found->get<bool>();
}

/// The step whose preset sets the scene of step i (the last one at or before it).
std::size_t scene_of(const Lesson& lesson, std::size_t i) {
  while (i > 0 && !lesson.steps[i].preset) --i;
  return i;
}

}  // namespace

std::string MemoryProgressStore::save(const std::string& json) {
  if (refuses) return "refused";
  text = json;
  return {};
}

std::string MemoryProgressStore::set_aside(const std::string& record) {
  if (refuses) return {};
  const std::string name = "unreadable-" + std::to_string(aside.size() + 1);
  aside[name] = record;
  return name;
}

std::unique_ptr<ProgressStore> make_memory_progress_store(std::string initial) {
  return std::make_unique<MemoryProgressStore>(std::move(initial));
}

std::unique_ptr<ProgressStore> make_file_progress_store() {
  return std::make_unique<FileProgressStore>();
}

std::string progress_note(const Lesson& lesson, const LessonProgress* p) {
  if (!p) return {};
  if (p->finished) return tr("done");
  std::size_t tasks = 0, right = 0;
  for (std::size_t i = 0; i < lesson.steps.size(); ++i)
    if (lesson.steps[i].task) {
      ++tasks;
      right += p->solved.count(i);
    }
  char note[128];
  std::snprintf(note, sizeof note, tr("%zu/%zu tasks"), right, tasks);
  return note;
}

void LessonSession::load(const std::string& lesson_directory, std::unique_ptr<ProgressStore> store,
                         const PresetLookup& lookup) {
  lookup_ = lookup;
  store_ = std::move(store);
  std::string problems;
  shipped_ = load_shipped_lessons(lesson_directory, lookup, problems);
  if (!problems.empty()) std::fprintf(stderr, "%s", problems.c_str());
  progress_.clear();
  welcomed_ = false;
  trouble_ = ProgressTrouble::none;
  notice_due_ = false;
  aside_.clear();
  const std::string text = store_->load();
  switch (progress_record_kind(text)) {
    case ProgressRecordKind::none:
      break;
    case ProgressRecordKind::readable:
      read_progress(text);
      break;
    case ProgressRecordKind::unreadable:
      // Lessons start afresh, the record kept for whoever can mend it; if it cannot be copied
      // it is not written over.
      aside_ = store_->set_aside(text);
      trouble(aside_.empty() ? ProgressTrouble::unreadable_left
                             : ProgressTrouble::unreadable_set_aside);
      break;
    case ProgressRecordKind::newer: {
      // Left alone; only whether the welcome was seen is read, so that it does not return.
      welcomed_ = flag(json::parse(text, nullptr, false), "welcomed");
      trouble(ProgressTrouble::newer);
      break;
    }
  }
  // The welcome is shown once: on the first start, whether or not it is closed.
  show_welcome = !welcomed_;
  if (!welcomed_) {
    welcomed_ = true;
    save_progress();
  }
}

void LessonSession::read_progress(const std::string& text) {
  const json j = json::parse(text, nullptr, false);
  progress_.clear();
  welcomed_ = flag(j, "welcomed");
  if (!j.contains("lessons") || !j["lessons"].is_object()) return;
  for (const auto& [id, p] : j["lessons"].items()) {
    if (!p.is_object()) continue;
    LessonProgress& lp = progress_[id];
    if (p.contains("step") && p["step"].is_number_unsigned()) lp.step = p["step"].get<std::size_t>();
    if (p.contains("solved") && p["solved"].is_array())
      for (const json& s : p["solved"])
        if (s.is_number_unsigned()) lp.solved.insert(s.get<std::size_t>());
    if (p.contains("predicted") && p["predicted"].is_object())
      for (const auto& [step, option] : p["predicted"].items())
        if (option.is_number_unsigned())
          lp.predicted[std::size_t(std::atol(step.c_str()))] = option.get<std::size_t>();
    if (p.contains("answers") && p["answers"].is_object())
      for (const auto& [step, a] : p["answers"].items()) {
        if (!a.is_object() || !a.contains("answer") || !a["answer"].is_string()) continue;
        StepAnswer& sa = lp.answers[std::size_t(std::atol(step.c_str()))];
        sa.answer = a["answer"].get<std::string>();
        if (a.contains("correct") && a["correct"].is_boolean()) sa.correct = a["correct"].get<bool>();
        if (a.contains("tries") && a["tries"].is_number_unsigned()) sa.tries = a["tries"].get<std::size_t>();
      }
    lp.finished = flag(p, "finished");
  }
}

void LessonSession::trouble(ProgressTrouble t) {
  if (t == trouble_) return;
  trouble_ = t;
  notice_due_ = t != ProgressTrouble::none;
}

bool LessonSession::take_progress_notice() {
  const bool due = notice_due_;
  notice_due_ = false;
  return due;
}

std::string LessonSession::progress_json() const {
  json lessons = json::object();
  for (const auto& [id, p] : progress_) {
    json predicted = json::object();
    for (const auto& [step, option] : p.predicted) predicted[std::to_string(step)] = option;
    json answers = json::object();
    for (const auto& [step, a] : p.answers)
      answers[std::to_string(step)] = {{"answer", a.answer},
                                       {"correct", a.correct ? json(*a.correct) : json(nullptr)},
                                       {"tries", a.tries}};
    lessons[id] = {{"step", p.step},       {"solved", p.solved},     {"predicted", predicted},
                   {"answers", answers},   {"finished", p.finished}};
  }
  return json{{"version", kProgressVersion}, {"welcomed", welcomed_}, {"lessons", lessons}}.dump();
}

void LessonSession::save_progress() {
  if (!progress_writes(trouble_)) return;  // a record left alone stays as it is
  if (!store_->save(progress_json()).empty())
    trouble(ProgressTrouble::not_saved);
  else if (trouble_ == ProgressTrouble::not_saved)
    trouble(ProgressTrouble::none);  // room again (a quota freed): saved as usual, nothing to say
}

std::string LessonSession::load_progress_json(const std::string& text) {
  switch (progress_record_kind(text)) {
    case ProgressRecordKind::none:
    case ProgressRecordKind::unreadable:
      return tr("This file is not Swarm Lab lesson progress.");
    case ProgressRecordKind::newer:
      return tr("This file was saved by a newer version of Swarm Lab.");
    case ProgressRecordKind::readable:
      break;
  }
  read_progress(text);
  welcomed_ = true;
  save_progress();
  return {};
}

void LessonSession::dismiss_welcome() { show_welcome = false; }

const LessonStep* LessonSession::current_step() const {
  return open_ ? &open_->steps[step_] : nullptr;
}

const LessonProgress* LessonSession::progress_of(const std::string& id) const {
  const auto found = progress_.find(id);
  return found == progress_.end() ? nullptr : &found->second;
}

LessonScene LessonSession::open(const Lesson& lesson) {
  open_ = lesson;
  error.clear();
  summary_ = false;
  open_json_.clear();
  open_is_shipped_ = false;
  for (const Lesson& l : shipped_) open_is_shipped_ = open_is_shipped_ || l.id == lesson.id;
  const LessonProgress* p = progress_of(lesson.id);
  // The scene of the step resumed at is set even when it has no preset of its own, and even
  // when the same lesson was open.
  scene_.reset();
  return go_to(p ? std::min(p->step, lesson.steps.size() - 1) : 0);
}

std::string LessonSession::open_json(const std::string& text, LessonScene* scene) {
  const LessonParse parsed = parse_lesson(text, lookup_);
  if (!parsed.lesson) return parsed.error;
  *scene = open(*parsed.lesson);
  // A lesson from a link or a file is shared as the JSON it came in, even when its id is a
  // shipped one's.
  open_is_shipped_ = false;
  open_json_ = text;
  return {};
}

std::string LessonSession::open_id(const std::string& id, LessonScene* scene) {
  for (const Lesson& l : shipped_)
    if (l.id == id) {
      *scene = open(l);
      return {};
    }
  return "no shipped lesson \"" + id + "\"";
}

void LessonSession::close() {
  open_.reset();
  scene_.reset();
  marking_.reset();
  summary_ = false;
}

void LessonSession::finish() {
  if (!open_) return;
  progress_[open_->id].finished = true;
  summary_ = true;
  marking_.reset();
  save_progress();
}

LessonScene LessonSession::restart() {
  if (!open_) return {};
  progress_[open_->id] = LessonProgress{};
  summary_ = false;
  scene_.reset();  // step 1's preset opens again, from its start
  return go_to(0);
}

const Lesson* LessonSession::next_lesson() const {
  if (!open_ || !open_is_shipped_) return nullptr;
  for (std::size_t i = 0; i + 1 < shipped_.size(); ++i)
    if (shipped_[i].id == open_->id) return &shipped_[i + 1];
  return nullptr;
}

bool LessonSession::hides(LessonHidden what) const {
  const LessonStep* s = current_step();
  if (!s || summary_ || !s->hides(what)) return false;
  if (!s->task) return true;
  const LessonProgress* p = progress_of(open_->id);
  return !(p && p->solved.count(step_));
}

const LessonStep* LessonSession::run_step() const {
  if (!open_ || summary_) return nullptr;
  for (std::size_t i = step_ + 1; i-- > 0;) {
    const LessonStep& s = open_->steps[i];
    if (s.run_until || s.run_loop) return &s;
    if (s.preset) break;  // an earlier step's run belongs to another scene
  }
  return nullptr;
}

std::size_t LessonSession::task_count() const {
  std::size_t n = 0;
  if (open_)
    for (const LessonStep& s : open_->steps) n += s.task ? 1 : 0;
  return n;
}

std::size_t LessonSession::answered_count() const {
  if (!open_) return 0;
  const LessonProgress* p = progress_of(open_->id);
  std::size_t n = 0;
  if (p)
    for (std::size_t i : p->solved) n += i < open_->steps.size() && open_->steps[i].task ? 1 : 0;
  return n;
}

std::string LessonSession::finished_line() const {
  char line[512];
  std::snprintf(line, sizeof line,
                tr("Finished: %zu of %zu tasks done (answered right, or predicted)."),
                answered_count(), task_count());
  return line;
}

std::string LessonSession::share_fragment() const {
  if (!open_) return {};
  return lesson_link_fragment(open_is_shipped_ ? open_->id : std::string(), open_json_);
}

void LessonSession::record_answer(const std::string& answer, const std::optional<bool>& correct) {
  StepAnswer& a = progress_[open_->id].answers[step_];
  a.answer = answer;
  a.correct = correct;
  ++a.tries;
}

LessonScene LessonSession::go_to(std::size_t i) {
  if (!open_) return {};
  summary_ = false;
  step_ = std::min(i, open_->steps.size() - 1);
  marking_.reset();
  typed.clear();
  LessonScene scene;
  scene.step = &open_->steps[step_];
  const std::size_t with_preset = scene_of(*open_, step_);
  if (with_preset != scene_) {
    scene.preset_step = &open_->steps[with_preset];
    const std::string& name = scene.preset_step->preset_name;
    scene.location = "my-" + (name.empty() ? open_->id + ".json" : name);
    scene_ = with_preset;
  }
  // A prediction is made before the run: the clock waits for it.
  const LessonStep& s = *scene.step;
  scene.pause = s.task && s.task->kind == LessonTask::Kind::predict && !prediction();
  progress_[open_->id].step = step_;
  save_progress();
  return scene;
}

double LessonSession::reading(LiveRun& run) const {
  const LessonStep* s = current_step();
  if (!s || !s->task || s->task->kind != LessonTask::Kind::measure) return kNone;
  const LessonTask& task = *s->task;
  const swarm::System& system = run.system();
  const double k = swarm::stiffness(system);
  switch (task.quantity) {
    case Quantity::period:
      return swarm::regime_of(k) == swarm::Regime::attractive ? swarm::period_of(k) : kNone;
    case Quantity::omega:
      return k != 0 ? swarm::omega_of(k) : kNone;
    case Quantity::M:
      return swarm::total_mass(system);
    case Quantity::E:
      return swarm::kinetic_energy(system) + swarm::potential_energy_cm(system);
    case Quantity::P:
    case Quantity::T: {
      if (!run.primary().engine().container_radius()) return kNone;
      const std::vector<swarm::WallInterval> intervals =
          swarm::wall_intervals(run.primary().samples());
      std::size_t first = 0;
      if (task.window > 0 && !intervals.empty()) {
        const double from = intervals.back().t_end - task.window;
        while (first < intervals.size() && intervals[first].t_end <= from) ++first;
      }
      const swarm::WallReading r = swarm::wall_average(intervals, first, intervals.size());
      if (r.hits == 0) return kNone;
      return task.quantity == Quantity::P ? r.P : r.T;
    }
  }
  return kNone;
}

Marking LessonSession::answer_number(LiveRun& run, double value) {
  const LessonStep* s = current_step();
  if (!s || !s->task || s->task->kind != LessonTask::Kind::measure) {
    marking_ = Marking{std::nullopt, tr("This step asks for no number.")};
    return *marking_;
  }
  ++answer_count_;
  const bool repulsive = swarm::stiffness(run.system()) < 0;
  marking_ = mark_measurement(*s->task, value, reading(run),
                              quantity_symbol(s->task->quantity, repulsive));
  if (std::isfinite(value)) {
    char shown[32];
    std::snprintf(shown, sizeof shown, "%.6g", value);
    record_answer(shown, marking_->correct);
  }
  if (marking_->correct && *marking_->correct) progress_[open_->id].solved.insert(step_);
  save_progress();
  return *marking_;
}

Marking LessonSession::answer_option(std::size_t option, bool* play) {
  const LessonStep* s = current_step();
  if (!s || !s->task || s->task->kind == LessonTask::Kind::measure) {
    marking_ = Marking{std::nullopt, tr("This step has no options to pick from.")};
    return *marking_;
  }
  ++answer_count_;
  marking_ = mark_option(*s->task, option);
  if (option < s->task->options.size()) record_answer(s->task->options[option], marking_->correct);
  LessonProgress& p = progress_[open_->id];
  if (s->task->kind == LessonTask::Kind::predict && option < s->task->options.size()) {
    p.predicted[step_] = option;
    p.solved.insert(step_);
    *play = true;
  } else if (marking_->correct && *marking_->correct) {
    p.solved.insert(step_);
  }
  save_progress();
  return *marking_;
}

std::optional<std::size_t> LessonSession::prediction() const {
  if (!open_) return std::nullopt;
  const LessonProgress* p = progress_of(open_->id);
  if (!p) return std::nullopt;
  const auto found = p->predicted.find(step_);
  if (found == p->predicted.end()) return std::nullopt;
  return found->second;
}

}  // namespace swarmlab
