// [SECTION] prose: wrapped paragraphs with *emphasis*
// [SECTION] the lesson panel: step text, task, feedback, back and next
// [SECTION] the welcome window and the Lessons menu
// [SECTION] the progress notice: progress not kept as usual, download it, load it again

#include "ui/lesson_player/lesson_panel.h"

#include "i18n/printed.h"
#include "i18n/translator.h"
#include "lessons/device_words.h"
#include "ui/kit/theme_style.h"
#include "ui/lesson_player/input_kind.h"
#include "ui/lesson_player/lesson_scene.h"
#include "ui/parallel_dom/item_tooltip.h"
#include "ui/parallel_dom/parallel_dom.h"
#include "ui/platform/save_dialog.h"

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

/// The progress as a JSON file: a download in the browser, the save dialog on the desktop.
void download_progress(AppState& state) {
  request_save(state, {tr("your lesson progress"), "swarmlab-progress.json",
                       state.lessons.progress_json() + "\n", "application/json", false});
}

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

void draw_prose(const AppState& state, const std::string& text) {
  // A screen reader reads it where it stands (the parallel DOM).
  mirror_text(ItemRole::paragraph, without_emphasis(text));
  struct Piece {
    std::string text;
    bool emphasis;
  };
  // Words, each made of pieces whose emphasis may change inside the word ("*Play*,"). Chinese
  // writes no spaces: each of its characters is a word of its own, set without a space before
  // it, so a line may break between any two of them.
  struct Word {
    std::vector<Piece> pieces;
    bool space_before = false;
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
      std::vector<Word> words(1);
      bool spaced = false;  // a space since the last word ended
      auto add = [&](const std::string& c) {
        if (words.back().pieces.empty()) words.back().pieces.push_back({"", emphasis});
        words.back().pieces.back().text += c;
      };
      for (std::size_t i = 0; i < line.size();) {
        const unsigned char c = static_cast<unsigned char>(line[i]);
        const std::size_t n = c < 0x80 ? 1 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;
        // U+2E80 and above (CJK, its punctuation, full-width forms) is three or four bytes
        // from E2 BA 80 on.
        const bool cjk = n >= 3 && line.compare(i, 3, "\xE2\xBA\x80") >= 0;
        if (c == '*') {
          emphasis = !emphasis;
          if (words.back().pieces.empty()) words.back().space_before = spaced;
          words.back().pieces.push_back({"", emphasis});
          spaced = false;
        } else if (c == ' ') {
          if (!words.back().pieces.empty()) words.emplace_back();
          spaced = true;
        } else if (cjk) {
          // Closing punctuation never starts a line: it stays with the character before it.
          static const std::string closing = "，。、：；！？）」』】";
          const std::string ch = line.substr(i, n);
          const bool closes = closing.find(ch) != std::string::npos && words.size() > 1 &&
                              words.back().pieces.empty() && !spaced;
          if (closes) words.pop_back();
          if (!closes && !words.back().pieces.empty()) words.emplace_back();
          if (!closes) words.back().space_before = spaced;
          add(ch);
          words.emplace_back();
          spaced = false;
        } else {
          if (words.back().pieces.empty()) words.back().space_before = spaced;
          add(line.substr(i, n));
          spaced = false;
        }
        i += n;
      }
      float x = 0;
      for (const Word& word : words) {
        float width = 0;
        for (const Piece& p : word.pieces) width += ImGui::CalcTextSize(p.text.c_str()).x;
        if (width == 0) continue;
        const float gap = word.space_before ? space : 0;
        if (x > 0 && x + gap + width > wrap)
          x = 0;
        else if (x > 0)
          ImGui::SameLine(0, gap);
        bool first = true;
        for (const Piece& p : word.pieces) {
          if (p.text.empty()) continue;
          if (!first) ImGui::SameLine(0, 0);
          first = false;
          if (p.emphasis)
            ImGui::TextColored(colour_vec4(palette(state.presentation.theme).lesson_keyword), "%s",
                               p.text.c_str());
          else
            ImGui::TextUnformatted(p.text.c_str());
        }
        x += (x > 0 ? gap : 0) + width;
      }
    }
    start = end + 1;
  }
}

// [SECTION] the lesson panel ---------------------------------------------------------------------

namespace {

/// A lesson's text (its step, prompt, option, feedback or outcome) in the language in use, its
/// device words chosen for this device: the translation keeps the {tap|click} choices.
std::string lesson_words(const AppState& state, const std::string& text) {
  return device_words(tr(text.c_str()), input_kind(state));
}

void draw_lesson_prose(const AppState& state, const std::string& text) {
  draw_prose(state, lesson_words(state, text));
}

ImVec4 marking_colour(const AppState& state, const std::optional<bool>& correct) {
  const Palette& p = palette(state.presentation.theme);
  return colour_vec4(!correct ? p.feedback_note : *correct ? p.feedback_right : p.feedback_wrong);
}

void draw_feedback(const AppState& state, const Marking& m) {
  ImGui::PushStyleColor(ImGuiCol_Text, marking_colour(state, m.correct));
  draw_lesson_prose(state, m.feedback);
  ImGui::PopStyleColor();
}

/// A heading in the lesson's title colour, also a heading for a screen reader.
void heading(const AppState& state, const char* text) {
  mirror_text(ItemRole::heading, text);
  ImGui::TextColored(colour_vec4(palette(state.presentation.theme).lesson_title), "%s", text);
}

/// A short line in a colour, read as a paragraph.
void coloured_line(const ImVec4& colour, const char* text) {
  mirror_text(ItemRole::paragraph, text);
  ImGui::TextColored(colour, "%s", text);
}

/// A button on the same line as the last item when it fits there, else on the next line: the
/// row of buttons wraps on a phone rather than running off the panel.
bool button_in_row(const char* label) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float width = ImGui::CalcTextSize(label, nullptr, true).x + 2 * style.FramePadding.x;
  const float right = ImGui::GetItemRectMax().x + style.ItemSpacing.x + width;
  if (right <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
  return ImGui::Button(label);
}

/// Whether Enter (the main key or the keypad's) was pressed this frame.
bool enter_pressed() {
  return ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) ||
         ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_KeyPadEnter), false);
}

/// The task area under the step's text: the prompt, the options or the answer field, Check,
/// and the feedback right under them, all outside the text's scrolling box so that they stay
/// in view. Returns whether feedback was drawn.
bool draw_task(AppState& state, const LessonTask& task) {
  LessonSession& lessons = state.lessons;
  const Palette& palette = swarmlab::palette(state.presentation.theme);
  draw_lesson_prose(state, task.prompt);
  if (task.kind == LessonTask::Kind::measure) {
    ImGui::SetNextItemWidth(8 * ImGui::GetFontSize());
    const bool entered = ImGui::InputText(tr_id("Your answer##answer"), &lessons.typed,
                                          ImGuiInputTextFlags_CharsScientific |
                                              ImGuiInputTextFlags_EnterReturnsTrue);
    // Enter in the field checks, whichever Enter key it was (the field may give up its focus
    // on the main Enter key before EnterReturnsTrue reports it).
    const bool enter = entered || (ImGui::IsItemFocused() && enter_pressed()) ||
                       (ImGui::IsItemDeactivated() && enter_pressed());
    ImGui::SameLine();
    if (ImGui::Button(tr_id("Check")) || enter) {
      char* end = nullptr;
      const double value = std::strtod(lessons.typed.c_str(), &end);
      lessons.answer_number(*state.run, end != lessons.typed.c_str() ? value : NAN);
    }
  } else if (task.kind == LessonTask::Kind::choice) {
    for (std::size_t i = 0; i < task.options.size(); ++i) {
      ImGui::PushID(int(i));
      const char letter = char('A' + i);
      // Shown in the language in use, with the English label as its ID (as tr_id gives it).
      const std::string label = printed(tr("Pick %c"), letter) + "###Pick " + letter + "##pick";
      if (ImGui::Button(label.c_str())) answer_lesson_option(state, i);
      name_item(printed(tr("Pick %c: %s"), letter, lesson_words(state, task.options[i]).c_str()));
      ImGui::SameLine();
      draw_lesson_prose(state, task.options[i]);
      ImGui::PopID();
    }
  } else {
    const std::optional<std::size_t> predicted = lessons.prediction();
    if (!predicted) {
      const char* waits = tr("The run waits for your prediction.");
      mirror_text(ItemRole::paragraph, waits);
      ImGui::TextDisabled("%s", waits);
      for (std::size_t i = 0; i < task.options.size(); ++i) {
        ImGui::PushID(int(i));
        const char letter = char('A' + i);
        const std::string label =
            printed(tr("Predict %c"), letter) + "###Predict " + letter + "##predict";
        if (ImGui::Button(label.c_str())) answer_lesson_option(state, i);
        name_item(
            printed(tr("Predict %c: %s"), letter, lesson_words(state, task.options[i]).c_str()));
        ImGui::SameLine();
        draw_lesson_prose(state, task.options[i]);
        ImGui::PopID();
      }
    } else {
      coloured_line(colour_vec4(palette.feedback_note), tr("Your prediction:"));
      draw_lesson_prose(state, task.options[*predicted]);
      if (!task.outcome.empty()) {
        coloured_line(colour_vec4(palette.feedback_note), tr("Now compare:"));
        draw_lesson_prose(state, task.outcome);
      }
      return true;  // the outcome is already shown beside the prediction
    }
  }
  if (!lessons.marking()) return false;
  draw_feedback(state, *lessons.marking());
  return true;
}

/// The height the lesson's parts other than the text box took on the last frame (kept in
/// ImGui's storage under the lesson's id), so that the text box leaves them room.
float& chrome_height() {
  return *ImGui::GetStateStorage()->GetFloatRef(ImGui::GetID("chrome-height"), 0);
}

/// The finished lesson: each task, the student's answer and whether it was right; Restart and
/// the next lesson.
void draw_summary(AppState& state, float box_height) {
  LessonSession& lessons = state.lessons;
  const Lesson& lesson = *lessons.open_lesson();
  const LessonProgress* progress = lessons.progress_of(lesson.id);
  const std::string finished = lessons.finished_line();
  heading(state, tr("Summary"));
  mirror_text(ItemRole::paragraph, finished);
  ImGui::PushTextWrapPos(0);  // a narrow panel wraps it rather than cut it off
  ImGui::TextUnformatted(finished.c_str());
  ImGui::PopTextWrapPos();
  ImGui::BeginChild("summary", ImVec2(0, box_height), true);
  std::size_t number = 0;
  for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
    const LessonStep& step = lesson.steps[i];
    if (!step.task) continue;
    ImGui::PushID(int(i));
    ++number;
    heading(state, printed(tr("Task %zu (step %zu)"), number, i + 1).c_str());
    draw_lesson_prose(state, step.task->prompt);
    const StepAnswer* a = nullptr;
    if (progress) {
      const auto found = progress->answers.find(i);
      if (found != progress->answers.end()) a = &found->second;
    }
    if (!a) {
      const char* not_answered = tr("Not answered.");
      mirror_text(ItemRole::paragraph, not_answered);
      ImGui::TextDisabled("%s", not_answered);
    } else {
      // The answer: a number typed, or an option's text (a key, as the lesson's texts are).
      const std::string answer = step.task->kind == LessonTask::Kind::measure
                                     ? translator().numbers(a->answer)
                                     : std::string(tr(a->answer.c_str()));
      const char* format;
      if (a->tries > 1)
        format = !a->correct    ? tr("Your answer: %s \u2014 recorded (a prediction is not marked) "
                                     "(after %zu tries)")
                 : *a->correct ? tr("Your answer: %s \u2014 right (after %zu tries)")
                               : tr("Your answer: %s \u2014 not right yet (after %zu tries)");
      else
        format = !a->correct    ? tr("Your answer: %s \u2014 recorded (a prediction is not marked)")
                 : *a->correct ? tr("Your answer: %s \u2014 right")
                               : tr("Your answer: %s \u2014 not right yet");
      const std::string text = printed(format, answer.c_str(), a->tries);
      ImGui::PushStyleColor(ImGuiCol_Text, marking_colour(state, a->correct));
      draw_prose(state, text);
      ImGui::PopStyleColor();
    }
    ImGui::Spacing();
    ImGui::PopID();
  }
  ImGui::EndChild();
  if (ImGui::Button(tr_id("Restart lesson"))) show_lesson_scene(state, lessons.restart());
  if (const Lesson* next = lessons.next_lesson()) {
    const std::string label = printed(tr("Next lesson: %s"), tr(next->title.c_str())) +
                              "###Next lesson: " + next->title + "##next-lesson";
    if (button_in_row(label.c_str())) open_lesson(state, *next);
  }
}

}  // namespace

bool draw_hidden_by_lesson(const AppState& state, LessonHidden what) {
  if (!state.lessons.hides(what)) return false;
  const std::string text =
      what == LessonHidden::readouts
          ? tr("The read-outs are hidden until you answer the lesson's question: it would give "
               "the answer away.")
      : what == LessonHidden::card
          ? tr("The particle's card is hidden until you answer the lesson's question: it would "
               "give the answer away.")
          : tr("The plots are hidden until you answer the lesson's question: it would give the "
               "answer away.");
  mirror_text(ItemRole::paragraph, text);
  ImGui::PushTextWrapPos(0);
  ImGui::TextDisabled("%s", text.c_str());
  ImGui::PopTextWrapPos();
  return true;
}

void draw_lesson(AppState& state, float height) {
  LessonSession& lessons = state.lessons;
  const Lesson* lesson = lessons.open_lesson();
  if (!lesson) return;
  const Palette& palette = swarmlab::palette(state.presentation.theme);
  const float font = ImGui::GetFontSize();
  ImGui::PushID("lesson");
  const float top = ImGui::GetCursorPosY();
  // A new step (or the summary) opens at its top, in the text box and in the panel around it.
  const int shown = lessons.showing_summary() ? -1 : int(lessons.step());
  int& last_shown = *ImGui::GetStateStorage()->GetIntRef(ImGui::GetID("shown-step"), -2);
  const ImGuiID lesson_key = ImGui::GetID(lesson->id.c_str());
  int& last_lesson = *ImGui::GetStateStorage()->GetIntRef(ImGui::GetID("shown-lesson"), 0);
  const bool new_page = shown != last_shown || int(lesson_key) != last_lesson;
  last_shown = shown, last_lesson = int(lesson_key);
  if (new_page) ImGui::SetScrollY(0);

  const char* title = tr(lesson->title.c_str());
  mirror_text(ItemRole::heading, title);
  ImGui::PushStyleColor(ImGuiCol_Text, colour_vec4(palette.lesson_title));
  ImGui::PushTextWrapPos(0);
  ImGui::TextUnformatted(title);
  ImGui::PopTextWrapPos();
  ImGui::PopStyleColor();
  const std::size_t step = lessons.step(), steps = lesson->steps.size();
  if (!lessons.showing_summary()) {
    const std::string progress = printed(tr("step %zu of %zu"), step + 1, steps);
    mirror_text(ItemRole::paragraph, printed(tr("Step %zu of %zu"), step + 1, steps));
    ImGui::ProgressBar(float(step + 1) / float(steps), ImVec2(-1, 0), progress.c_str());
  }
  if (!lessons.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, colour_vec4(palette.feedback_wrong));
    draw_prose(state, lessons.error);
    ImGui::PopStyleColor();
  }
  // The text box takes what the task area, the buttons and the title leave, and at least four
  // lines: on a short screen the text scrolls in its box while the task stays in view.
  const float box = std::max(4 * ImGui::GetTextLineHeightWithSpacing() +
                                 2 * ImGui::GetStyle().WindowPadding.y,
                             height - chrome_height());
  bool close = false;
  if (lessons.showing_summary()) {
    draw_summary(state, box);
    if (button_in_row(tr_id("Close lesson"))) close = true;
  } else {
    const LessonStep& s = lesson->steps[step];
    ImGui::BeginChild("step", ImVec2(0, box), true);
    if (new_page) ImGui::SetScrollY(0);
    draw_lesson_prose(state, s.text);
    // The step's text is all the box holds: shorter text leaves the rest of the box empty
    // rather than pushing the task down and up from step to step.
    ImGui::EndChild();
    bool feedback = false;
    if (s.task) {
      ImGui::Separator();
      feedback = draw_task(state, *s.task);
    }
    // Feedback that has just appeared is brought into view in a panel that scrolls.
    int& last_answers = *ImGui::GetStateStorage()->GetIntRef(ImGui::GetID("answers"), 0);
    if (feedback && int(lessons.answer_count()) != last_answers) ImGui::SetScrollHereY(1.0f);
    last_answers = int(lessons.answer_count());
    ImGui::BeginDisabled(step == 0);
    if (ImGui::Button(tr_id("\u2190 Back"))) show_lesson_scene(state, lessons.back());
    ImGui::EndDisabled();
    if (step + 1 < steps) {
      if (button_in_row(tr_id("Next \u2192"))) show_lesson_scene(state, lessons.next());
    } else if (button_in_row(tr_id("Finish"))) {
      lessons.finish();
    }
    if (button_in_row(tr_id("Close lesson"))) close = true;
  }
  if (lessons.share) {
    if (button_in_row(tr_id("Share lesson"))) lessons.share(lessons.share_fragment());
    item_tooltip("%s",
                 tr("A link that opens this lesson for a student: copied, and shown on the page"));
  }
  // What is not the text box, for the next frame's box height.
  chrome_height() = ImGui::GetCursorPosY() - top - box + 0.25f * font;
  ImGui::PopID();
  if (close) lessons.close();
}

// [SECTION] the welcome window and the Lessons menu ---------------------------------------------

void draw_lessons_menu(AppState& state) {
  if (!ImGui::BeginMenu(tr_id("Lessons"))) return;
  for (const Lesson& l : state.lessons.shipped()) {
    const std::string done = progress_note(l, state.lessons.progress_of(l.id));
    const Lesson* open = state.lessons.open_lesson();
    if (ImGui::MenuItem(tr_id(l.title.c_str()), done.c_str(), open && open->id == l.id))
      open_lesson(state, l);
  }
  ImGui::Separator();
  if (ImGui::MenuItem(tr_id("Welcome..."))) state.lessons.show_welcome = true;
  // The progress as a file, to carry it to another computer or to keep it where the browser
  // will not.
  if (ImGui::MenuItem(tr_id("Download progress"))) download_progress(state);
  if (state.lessons.pick_progress_file && ImGui::MenuItem(tr_id("Load progress...")))
    state.lessons.pick_progress_file();
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
  if (ImGui::Begin(tr_id("Welcome"), &open,
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    keep_inside_viewport();
    ImGui::PushTextWrapPos(0);
    heading(state, tr("Welcome to Swarm Lab"));
    draw_prose(
        state,
        tr("Particles that pull on each other like springs (F = J m\u2081 m\u2082 r), solved "
           "exactly. The *3D view*: drag to turn it, scroll or pinch to zoom, right-drag or "
           "drag two fingers to slide it, click or tap a particle to follow it. Above it the "
           "play buttons and the clock, below it the "
           "*read-outs* (hover one for its equation) and the timeline. Beside it (on a phone, in "
           "the tabs below) the *Controls* (the scenario, the masses, the container, the method) "
           "and live *Plots* with the *Instruments*: a stopwatch and a period meter."));
    ImGui::Spacing();
    heading(state, tr("Three things to try"));
    draw_prose(state,
               tr("1. Press *Space* to pause and play; click a ball and watch all four close "
                  "their orbits together."));
    draw_prose(state,
               tr("2. Open *Scenario* and pick the repulsive fireball: the push turns into a gas "
                  "pressing on its wall."));
    draw_prose(state, tr("3. In *Controls \u2192 System*, change a mass and see the period in the "
                         "read-outs change."));
    ImGui::Spacing();
    heading(state, tr("Lessons (10 to 20 minutes each)"));
    for (const Lesson& l : lessons.shipped()) {
      ImGui::PushID(l.id.c_str());
      if (ImGui::Button(tr_id("Start"))) {
        open_lesson(state, l);
        lessons.dismiss_welcome();
      }
      const char* title = tr(l.title.c_str());
      const char* summary = tr(l.summary.c_str());
      name_item(printed(tr("Start: %s"), title));
      describe_item(summary);
      ImGui::SameLine();
      ImGui::TextUnformatted(title);
      if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(24 * font);
        ImGui::TextUnformatted(summary);
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
      }
      ImGui::PopID();
    }
    ImGui::Spacing();
    if (ImGui::Button(tr_id("Just the simulation"))) lessons.dismiss_welcome();
    ImGui::SameLine();
    ImGui::TextDisabled("%s", tr("(this window is in Lessons \u2192 Welcome)"));
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
  if (!open) lessons.dismiss_welcome();
}

// [SECTION] the progress notice: progress not kept as usual, download it, load it again -------

void draw_progress_notice(AppState& state) {
  LessonSession& lessons = state.lessons;
  if (lessons.take_progress_notice()) {
    // Shown once: the window, and the status line (the live region says it once too:
    // classroom_outputs.cpp).
    lessons.show_progress_notice = true;
    state.status = lessons.progress_notice();
    state.status_is_error = false;
  }
  if (!lessons.show_progress_notice) return;
  const std::string text = lessons.progress_notice();
  if (text.empty()) {
    lessons.show_progress_notice = false;
    return;
  }
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float font = ImGui::GetFontSize();
  ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + 0.5f * viewport->Size.x, viewport->Pos.y + 3 * font),
                          ImGuiCond_Appearing, ImVec2(0.5f, 0));
  ImGui::SetNextWindowSize(ImVec2(std::min(30 * font, viewport->Size.x - font), 0),
                           ImGuiCond_Appearing);
  bool open = true;
  if (ImGui::Begin(tr_id("Lesson progress"), &open,
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse |
                       ImGuiWindowFlags_AlwaysAutoResize)) {
    keep_inside_viewport();
    ImGui::PushTextWrapPos(std::min(30 * font, viewport->Size.x - 2 * font));
    ImGui::TextUnformatted(text.c_str());
    mirror_text(ItemRole::paragraph, text);
    ImGui::PopTextWrapPos();
    if (ImGui::Button(tr_id("Download progress"))) download_progress(state);
    if (lessons.pick_progress_file && button_in_row(tr_id("Load progress...")))
      lessons.pick_progress_file();
    if (button_in_row(tr_id("Close"))) open = false;
  }
  ImGui::End();
  if (!open) lessons.show_progress_notice = false;
}

}  // namespace swarmlab
