// [SECTION] prose: wrapped paragraphs with *emphasis*
// [SECTION] the lesson panel: step text, task, feedback, back and next
// [SECTION] the welcome window and the Lessons menu

#include "ui/lesson_player/lesson_panel.h"

#include "ui/lesson_player/lesson_scene.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace swarmlab {
namespace {

const ImVec4 kEmphasis(1.0f, 0.80f, 0.35f, 1.0f);
const ImVec4 kRight(0.45f, 0.90f, 0.45f, 1.0f);
const ImVec4 kWrong(1.0f, 0.55f, 0.45f, 1.0f);
const ImVec4 kNeutral(0.65f, 0.80f, 1.0f, 1.0f);

/// Keeps the current window inside the main viewport (after the browser window shrinks, a
/// phone turns, or the student drags it off), no wider or taller than the viewport.
void keep_inside_viewport() {
  const ImGuiViewport* v = ImGui::GetMainViewport();
  ImVec2 size = ImGui::GetWindowSize();
  const ImVec2 fitted(std::min(size.x, v->Size.x), std::min(size.y, v->Size.y));
  if (fitted.x != size.x || fitted.y != size.y) ImGui::SetWindowSize(fitted);
  ImVec2 pos = ImGui::GetWindowPos();
  const ImVec2 clamped(std::clamp(pos.x, v->Pos.x, v->Pos.x + v->Size.x - fitted.x),
                       std::clamp(pos.y, v->Pos.y, v->Pos.y + v->Size.y - fitted.y));
  if (clamped.x != pos.x || clamped.y != pos.y) ImGui::SetWindowPos(clamped);
}

}  // namespace

// [SECTION] prose ------------------------------------------------------------------------------

void draw_prose(const std::string& text) {
  struct Piece {
    std::string text;
    bool emphasis;
  };
  const float wrap = ImGui::GetContentRegionAvail().x;
  const float space = ImGui::CalcTextSize(" ").x;
  bool emphasis = false;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    if (line.empty()) {
      ImGui::Spacing();  // a blank line: a new paragraph
    } else {
      // Words, each made of pieces whose emphasis may change inside the word ("*Play*,").
      std::vector<std::vector<Piece>> words(1);
      for (char c : line) {
        if (c == '*') {
          emphasis = !emphasis;
          words.back().push_back({"", emphasis});
        } else if (c == ' ') {
          if (!words.back().empty()) words.emplace_back();
        } else {
          if (words.back().empty()) words.back().push_back({"", emphasis});
          words.back().back().text += c;
        }
      }
      float x = 0;
      for (const auto& word : words) {
        float width = 0;
        for (const Piece& p : word) width += ImGui::CalcTextSize(p.text.c_str()).x;
        if (width == 0) continue;
        if (x > 0 && x + space + width > wrap)
          x = 0;
        else if (x > 0)
          ImGui::SameLine(0, space);
        bool first = true;
        for (const Piece& p : word) {
          if (p.text.empty()) continue;
          if (!first) ImGui::SameLine(0, 0);
          first = false;
          if (p.emphasis)
            ImGui::TextColored(kEmphasis, "%s", p.text.c_str());
          else
            ImGui::TextUnformatted(p.text.c_str());
        }
        x += (x > 0 ? space : 0) + width;
      }
    }
    start = end + 1;
  }
}

// [SECTION] the lesson panel ---------------------------------------------------------------------

namespace {

void draw_feedback(const Marking& m) {
  const ImVec4 colour = !m.correct ? kNeutral : *m.correct ? kRight : kWrong;
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  draw_prose(m.feedback);
  ImGui::PopStyleColor();
}

void draw_task(AppState& state, const LessonTask& task) {
  LessonSession& lessons = state.lessons;
  ImGui::Separator();
  draw_prose(task.prompt);
  if (task.kind == LessonTask::Kind::measure) {
    ImGui::SetNextItemWidth(8 * ImGui::GetFontSize());
    const bool entered = ImGui::InputText("##answer", &lessons.typed,
                                          ImGuiInputTextFlags_CharsScientific |
                                              ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("Check") || entered) {
      char* end = nullptr;
      const double value = std::strtod(lessons.typed.c_str(), &end);
      lessons.answer_number(*state.run, end != lessons.typed.c_str() ? value : NAN);
    }
  } else if (task.kind == LessonTask::Kind::choice) {
    for (std::size_t i = 0; i < task.options.size(); ++i) {
      ImGui::PushID(int(i));
      if (ImGui::Button("Pick")) answer_lesson_option(state, i);
      ImGui::SameLine();
      draw_prose(task.options[i]);
      ImGui::PopID();
    }
  } else {
    const std::optional<std::size_t> predicted = lessons.prediction();
    if (!predicted) {
      ImGui::TextDisabled("The run waits for your prediction.");
      for (std::size_t i = 0; i < task.options.size(); ++i) {
        ImGui::PushID(int(i));
        if (ImGui::Button("Predict")) answer_lesson_option(state, i);
        ImGui::SameLine();
        draw_prose(task.options[i]);
        ImGui::PopID();
      }
    } else {
      ImGui::TextColored(kNeutral, "Your prediction:");
      draw_prose(task.options[*predicted]);
      if (!task.outcome.empty()) {
        ImGui::TextColored(kNeutral, "Now compare:");
        draw_prose(task.outcome);
      }
      return;  // the outcome is already shown beside the prediction
    }
  }
  if (lessons.marking()) draw_feedback(*lessons.marking());
}

}  // namespace

void draw_lesson(AppState& state, float step_height) {
  LessonSession& lessons = state.lessons;
  const Lesson* lesson = lessons.open_lesson();
  if (!lesson) return;
  ImGui::PushID("lesson");
  ImGui::TextColored(kEmphasis, "%s", lesson->title.c_str());
  const std::size_t step = lessons.step(), steps = lesson->steps.size();
  char progress[48];
  std::snprintf(progress, sizeof progress, "step %zu of %zu", step + 1, steps);
  ImGui::ProgressBar(float(step + 1) / float(steps), ImVec2(-1, 0), progress);
  if (!lessons.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kWrong);
    draw_prose(lessons.error);
    ImGui::PopStyleColor();
  }
  ImGui::BeginChild("step", ImVec2(0, step_height), true);
  const LessonStep& s = lesson->steps[step];
  draw_prose(s.text);
  if (s.task) draw_task(state, *s.task);
  ImGui::EndChild();
  ImGui::BeginDisabled(step == 0);
  if (ImGui::Button("\u2190 Back")) show_lesson_scene(state, lessons.back());
  ImGui::EndDisabled();
  ImGui::SameLine();
  bool close = false;
  if (step + 1 < steps) {
    if (ImGui::Button("Next \u2192")) show_lesson_scene(state, lessons.next());
  } else if (ImGui::Button("Finish")) {
    close = true;
  }
  ImGui::SameLine();
  if (ImGui::Button("Close lesson")) close = true;
  ImGui::PopID();
  if (close) lessons.close();
}

// [SECTION] the welcome window and the Lessons menu ---------------------------------------------

void draw_lessons_menu(AppState& state) {
  if (!ImGui::BeginMenu("Lessons")) return;
  for (const Lesson& l : state.lessons.shipped()) {
    const LessonProgress* p = state.lessons.progress_of(l.id);
    const std::string done =
        p ? std::to_string(p->solved.size()) + "/" + std::to_string(l.steps.size()) : "";
    const Lesson* open = state.lessons.open_lesson();
    if (ImGui::MenuItem(l.title.c_str(), done.c_str(), open && open->id == l.id))
      open_lesson(state, l);
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Welcome...")) state.lessons.show_welcome = true;
  ImGui::EndMenu();
}

void draw_welcome_window(AppState& state) {
  LessonSession& lessons = state.lessons;
  if (!lessons.show_welcome) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float font = ImGui::GetFontSize();
  const float width = std::min(34 * font, viewport->Size.x - font);
  ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + 0.5f * viewport->Size.x,
                                 viewport->Pos.y + 0.5f * viewport->Size.y),
                          ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(width, std::min(30 * font, 0.9f * viewport->Size.y)),
                           ImGuiCond_Appearing);
  bool open = true;
  if (ImGui::Begin("Welcome", &open,
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    keep_inside_viewport();
    ImGui::PushTextWrapPos(0);
    ImGui::TextColored(kEmphasis, "Welcome to Swarm Lab");
    draw_prose(
        "Particles that pull on each other like springs (F = J m\u2081 m\u2082 r), solved "
        "exactly. The *3D view*: drag to turn it, scroll or pinch to zoom, right-drag or "
        "drag two fingers to slide it, click or tap a particle to follow it. Above it the "
        "play buttons and the clock, below it the "
        "*read-outs* (hover one for its equation) and the timeline. Beside it (on a phone, in "
        "the tabs below) the *Controls* (the scenario, the masses, the container, the method) "
        "and live *Plots* with the *Instruments*: a stopwatch and a period meter.");
    ImGui::Spacing();
    ImGui::TextColored(kEmphasis, "Three things to try");
    draw_prose("1. Press *Space* to pause and play; click a ball and watch all four close their "
               "orbits together.");
    draw_prose("2. Open *Scenario* and pick the repulsive fireball: the push turns into a gas "
               "pressing on its wall.");
    draw_prose("3. In *Controls \u2192 System*, change a mass and see the period in the "
               "read-outs change.");
    ImGui::Spacing();
    ImGui::TextColored(kEmphasis, "Lessons (10 to 20 minutes each)");
    for (const Lesson& l : lessons.shipped()) {
      ImGui::PushID(l.id.c_str());
      if (ImGui::Button("Start")) {
        open_lesson(state, l);
        lessons.dismiss_welcome();
      }
      ImGui::SameLine();
      ImGui::TextUnformatted(l.title.c_str());
      if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(24 * font);
        ImGui::TextUnformatted(l.summary.c_str());
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
      }
      ImGui::PopID();
    }
    ImGui::Spacing();
    if (ImGui::Button("Just the simulation")) lessons.dismiss_welcome();
    ImGui::SameLine();
    ImGui::TextDisabled("(this window is in Lessons \u2192 Welcome)");
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
  if (!open) lessons.dismiss_welcome();
}

}  // namespace swarmlab
