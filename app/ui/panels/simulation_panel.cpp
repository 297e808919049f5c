// The simulation panel (method, dt, duration, methods compared) and the transport bar over the
// 3D view (play, pause, step, reset, speed, clock).

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "i18n/translator.h"
#include "labels/system_labels.h"
#include "swarm/physics/regime.h"
#include "ui/classroom/presentation.h"
#include "ui/kit/theme_style.h"
#include "ui/kit/touch_target.h"
#include "ui/panels/panels.h"
#include "ui/parallel_dom/item_tooltip.h"
#include "ui/time/time_controls.h"
#include "ui/time/timeline_strip.h"

namespace swarmlab {
namespace {

/// The method's row of the core's table as a tooltip: what it does, its order and its cost.
/// The core's name and description go through tr() as they are (they are not in the tables
/// unless a translator adds them); the sentence around them is one text per case.
std::string describe(swarm::Method m) {
  const swarm::MethodInfo& info = swarm::info_of(m);
  const std::string name(info.display_name), description(info.description);
  const char* format = info.order == 0 ? (info.pairwise ? tr("%s: %s. Exact, O(N^2) per step.")
                                                        : tr("%s: %s. Exact, O(N) per step."))
                                       : (info.pairwise ? tr("%s: %s. Order %d, O(N^2) per step.")
                                                        : tr("%s: %s. Order %d, O(N) per step."));
  const char* shown_name = tr(name.c_str());
  const char* shown_description = tr(description.c_str());
  const int length = std::snprintf(nullptr, 0, format, shown_name, shown_description, info.order);
  std::string text(std::size_t(std::max(length, 0)), '\0');
  std::snprintf(text.data(), text.size() + 1, format, shown_name, shown_description, info.order);
  return text;
}

/// The width of a button labelled `text`.
float button_width(const char* text) {
  return ImGui::CalcTextSize(text).x + 2 * ImGui::GetStyle().FramePadding.x;
}

}  // namespace

void draw_simulation_panel(AppState& state) {
  swarm::Preset& d = state.draft;
  bool changed = false;
  const float width = 0.55f * ImGui::GetContentRegionAvail().x;
  ImGui::SetNextItemWidth(width);
  if (ImGui::BeginCombo(tr_id("method"), std::string(swarm::name_of(d.method)).c_str())) {
    for (const swarm::MethodInfo& info : swarm::method_table()) {
      const swarm::Method m = info.id;
      if (ImGui::Selectable(std::string(swarm::name_of(m)).c_str(), m == d.method)) {
        d.method = m;
        changed = true;
      }
      item_tooltip("%s", describe(m).c_str());
    }
    ImGui::EndCombo();
  }
  help_marker(describe(d.method).c_str());

  ImGui::SetNextItemWidth(width);
  ImGui::InputDouble("dt", &d.dt, 0, 0, "%.6g");
  changed |= committed();
  help_marker(
      tr("The time step. The analytic map is exact for any dt; the numerical methods' "
         "errors shrink as dt^order. Wall hits are placed to within one step (paper rule)."));
  if (!d.expansion) {
    ImGui::SetNextItemWidth(width);
    ImGui::InputDouble(tr_id("duration"), &d.duration, 0, 0, "%.6g");
    changed |= committed();
  }

  ImGui::TextUnformatted(tr("Side by side with"));
  help_marker(
      tr("Run other methods from the same initial state in lockstep. With 'analytic' "
         "among them, its positions are drawn as hollow ghosts and the Compare plots show "
         "each numerical method's position and energy errors."));
  // One row of checkboxes, wrapping where the next does not fit.
  bool first = true;
  for (const swarm::MethodInfo& info : swarm::method_table()) {
    const swarm::Method m = info.id;
    if (m == d.method) continue;
    const std::string name(swarm::name_of(m));
    if (!first) same_line_if_fits(radio_width(name.c_str()));
    first = false;
    bool on = std::find(d.compare.begin(), d.compare.end(), m) != d.compare.end();
    if (ImGui::Checkbox(name.c_str(), &on)) {
      if (on)
        d.compare.push_back(m);
      else
        d.compare.erase(std::find(d.compare.begin(), d.compare.end(), m));
      changed = true;
    }
  }
  // A method compared with itself tells nothing: drop it when it becomes the primary.
  if (changed)
    d.compare.erase(std::remove(d.compare.begin(), d.compare.end(), d.method), d.compare.end());
  if (changed) state.apply_draft(Section::simulation);
  show_refusal(state, Section::simulation);

  ImGui::Separator();
  const swarm::RunPlan& plan = state.run->primary().plan();
  ImGui::TextDisabled(tr("%ld steps, a sample every %ld steps"), plan.steps, plan.sample_every);
  char text[160];
  std::snprintf(text, sizeof text, tr("one step: %.3g ms"), state.stats.step_ms);
  ImGui::TextDisabled("%s", translator().numbers(text).c_str());
  const bool pairwise =
      swarm::is_pairwise(state.preset.method) ||
      std::any_of(state.preset.compare.begin(), state.preset.compare.end(), swarm::is_pairwise);
  if (pairwise && state.run->system().particles.size() > 2000) {
    ImGui::PushStyleColor(ImGuiCol_Text,
                          colour_vec4(palette(state.presentation.theme).text_warning));
    ImGui::TextWrapped(tr("The numerical methods sum over all %zu^2 / 2 pairs every step: expect a "
                          "slow simulation. The analytic method is O(N)."),
                       state.run->system().particles.size());
    ImGui::PopStyleColor();
  }
}

void draw_transport_bar(AppState& state) {
  const float font = ImGui::GetFontSize();
  const bool at_end = !state.playing && state.run->finished();
  // One ID for every label, so keyboard focus stays on the button when its label changes; the
  // symbol stays outside the word a translator sees.
  const std::string play = state.playing ? std::string("\u2016 ") + tr("Pause") + "###play"
                           : at_end      ? std::string("\u25b6 ") + tr("Continue") + "###play"
                                         : std::string("\u25b6 ") + tr("Play") + "###play";
  // As wide as the widest of its labels, so that the row does not shift as it changes.
  const float play_width =
      std::max({6.5f * font, button_width((std::string("\u2016 ") + tr("Pause")).c_str()),
                button_width((std::string("\u25b6 ") + tr("Continue")).c_str()),
                button_width((std::string("\u25b6 ") + tr("Play")).c_str())});
  if (ImGui::Button(play.c_str(), ImVec2(play_width, 0))) play_or_continue(state);
  item_tooltip("%s", at_end ? tr("Space: the run is over; continue it for another run length")
                            : tr("Space"));
  same_line_if_fits(button_width(tr("Step")));
  if (ImGui::Button(tr_id("Step"))) state.step_once = true, state.playing = false;
  item_tooltip("%s", tr("S: one step of dt"));
  same_line_if_fits(button_width(tr("Reset")));
  if (ImGui::Button(tr_id("Reset"))) state.restart();
  item_tooltip("%s", tr("R: back to t = 0"));
  // Wide enough for its text with the longest number it shows ("0.0012").
  const char* speed_format = tr("speed %.3g /s");
  char widest_speed[128];
  std::snprintf(widest_speed, sizeof widest_speed, speed_format, 0.00123);
  const float speed_width = std::max(9 * font, button_width(widest_speed));
  same_line_if_fits(speed_width);
  ImGui::SetNextItemWidth(speed_width);
  const double lo = 1e-3, hi = 1e4;
  ImGui::SliderScalar("##speed", ImGuiDataType_Double, &state.speed, &lo, &hi, speed_format,
                      ImGuiSliderFlags_Logarithmic);
  item_tooltip("%s", tr("Simulated time per second of real time (+ and - keys: x2, /2)."));
  same_line_if_fits(ImGui::GetFrameHeight() + button_width(tr("Sound")));
  draw_sound_toggle(state);

  draw_time_buttons(state);
  const double t = state.run->time();
  const double k = swarm::stiffness(state.run->system());
  // The clock in periods (omega t / 2 pi) would give the period away where a lesson step hides
  // the read-outs: then it shows t alone.
  const double k_shown = state.lessons.hides(LessonHidden::readouts) ? 0 : k;
  ImGui::PushTextWrapPos(0);  // on a narrow screen the clock wraps rather than run off
  ImGui::TextUnformatted(labels::clock_text(state.preset, k_shown, t).c_str());
  ImGui::PopTextWrapPos();
  item_tooltip(
      "%s", tr("Simulated time; for an isolated system also in periods of the common oscillation "
               "(\u03c9 = \u221a(J M)), or for J < 0 in e-foldings \u03a9t. In a container the "
               "wall changes the motion and neither applies."));
  if (state.run->finished()) {
    same_line_if_fits(ImGui::CalcTextSize(tr("end of run")).x);
    ImGui::TextColored(colour_vec4(palette(state.presentation.theme).text_warning), "%s",
                       tr("end of run"));
    item_tooltip("%s", tr("Continue (Space) runs on for as long again."));
  } else if (state.playing && state.stats.speed_ratio < 0.97) {
    same_line_if_fits(ImGui::CalcTextSize(tr("(%.0f%% of the speed)")).x);
    ImGui::TextColored(colour_vec4(palette(state.presentation.theme).text_warning),
                       tr("(%.0f%% of the speed)"), 100 * state.stats.speed_ratio);
    item_tooltip("%s", tr("The steps of this speed do not fit in a frame on this machine."));
  }
}

}  // namespace swarmlab
