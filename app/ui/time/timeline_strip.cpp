#include "ui/parallel_dom/item_tooltip.h"
#include "ui/time/timeline_strip.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "i18n/translator.h"
#include "ui/kit/theme_style.h"
#include "ui/kit/touch_target.h"
#include "ui/time/time_controls.h"
#include "ui/time/timeline_scale.h"

namespace swarmlab {
namespace {

/// The progress bar's text for a travel: where it goes and how far it got (%.0f%%).
const char* travel_progress(TimeTravel::Kind kind) {
  switch (kind) {
    case TimeTravel::Kind::to_stage_end: return tr("to the end of the stage %.0f%%");
    case TimeTravel::Kind::to_run_end: return tr("to the end of the run %.0f%%");
    default: return tr("seeking %.0f%%");
  }
}

}  // namespace

float timeline_strip_height() {
  return std::max(2.4f * ImGui::GetFontSize(),
                  ImGui::GetFrameHeight() + 2 * ImGui::GetStyle().WindowPadding.y);
}

void draw_timeline_strip(AppState& state, float x, float y, float width, float height) {
  const swarm::Timeline& timeline = state.run->timeline();
  const double dt = state.preset.dt;
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(width, height));
  ImGui::SetNextWindowBgAlpha(0.85f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus;
  if (!ImGui::Begin(tr_id("Timeline###timeline"), nullptr, flags)) {
    ImGui::End();
    return;
  }
  const float font = ImGui::GetFontSize();
  const char* clock_format = tr("t = %.4g / %.4g reached");
  char clock[256];
  std::snprintf(clock, sizeof clock, clock_format, state.run->time(),
                double(timeline.reached()) * dt);
  // The clock's text keeps one width, so the bar after it never moves under the pointer.
  const ImVec2 clock_at = ImGui::GetCursorScreenPos();
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(translator().numbers(clock).c_str());
  item_tooltip("%s", tr(
        "The present time and the furthest time computed. Drag on the bar to go back to any "
        "moment: the same state to the last bit, recomputed from snapshots."));
  // As wide as the clock with two values of five digits ("t = 00.000 / 00.000 reached").
  std::string widest = clock_format;
  for (std::size_t at = widest.find("%.4g"); at != std::string::npos; at = widest.find("%.4g", at))
    widest.replace(at, 4, "00.000");
  const float clock_width =
      std::max(ImGui::CalcTextSize(widest.c_str()).x, ImGui::GetItemRectSize().x);
  ImGui::SameLine();
  ImGui::SetCursorScreenPos(ImVec2(clock_at.x + clock_width + ImGui::GetStyle().ItemSpacing.x,
                                   ImGui::GetCursorScreenPos().y));

  const TimeTravel& travel = state.travel;
  float bar_width = ImGui::GetContentRegionAvail().x;
  if (travel.active() && travel.kind != TimeTravel::Kind::seek)
    bar_width -= 18 * font;  // room for the progress and Cancel
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float bar_height = ImGui::GetFrameHeight();
  bar_width = std::max(bar_width, 4 * font);
  ImGui::InvisibleButton("##scrub", ImVec2(bar_width, bar_height));
  state.layout.drag_at_once = {origin.x, origin.y, bar_width, bar_height};
  const TimelineScale scale{origin.x, origin.x + bar_width, std::max(1L, timeline.end_step())};
  const float x0 = scale.x0, x1 = scale.x1;
  auto x_of = [&](long step) { return scale.x_of(step); };
  // Dragging scrubs over the time computed so far; a click beyond it computes up to there. The
  // frame the button is let go counts too: a quick drag may move and release in one frame.
  if (ImGui::IsItemActive() || ImGui::IsItemDeactivated()) {
    const long target = TimelineScale::scrub_target(scale.step_at(ImGui::GetIO().MousePos.x),
                                                    ImGui::IsItemActivated(), timeline.reached());
    if (!travel.active() || travel.target != target)
      travel_to(state, TimeTravel::Kind::seek, target);
  }
  if (ImGui::IsItemHovered()) {
    char at[64];
    std::snprintf(at, sizeof at, "t = %.4g", double(scale.step_at(ImGui::GetIO().MousePos.x)) * dt);
    ImGui::SetTooltip("%s", translator().numbers(at).c_str());
  }
  name_item(tr("Timeline: the present and the time reached; drag to go back to any moment"));

  const Palette& colours = palette(state.presentation.theme);
  const ImU32 track = colours.timeline_track.packed(), reached = colours.timeline_reached.packed(),
              stage = colours.timeline_stage.packed(), present = colours.timeline_present.packed(),
              target = colours.timeline_target.packed();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float top = origin.y + 0.25f * bar_height, bottom = origin.y + 0.75f * bar_height;
  draw->AddRectFilled(ImVec2(x0, top), ImVec2(x1, bottom), track, 3);
  draw->AddRectFilled(ImVec2(x0, top), ImVec2(x_of(timeline.reached()), bottom), reached, 3);
  const std::vector<long> starts = timeline.stage_starts();
  if (starts.size() < std::size_t(x1 - x0) / 2)  // ticks no closer than 2 px
    for (long s : starts)
      draw->AddLine(ImVec2(x_of(s), origin.y), ImVec2(x_of(s), origin.y + bar_height), stage);
  if (travel.active())
    draw->AddLine(ImVec2(x_of(travel.target), origin.y),
                  ImVec2(x_of(travel.target), origin.y + bar_height), target, 2);
  const float px = x_of(timeline.step());
  draw->AddTriangleFilled(ImVec2(px - 0.4f * font, origin.y), ImVec2(px + 0.4f * font, origin.y),
                          ImVec2(px, top + 0.1f * font), present);
  draw->AddLine(ImVec2(px, top), ImVec2(px, origin.y + bar_height), present, 2);

  if (travel.active() && travel.kind != TimeTravel::Kind::seek) {
    ImGui::SameLine();
    char label[256];
    const double progress = travel.progress(timeline.step());
    std::snprintf(label, sizeof label, travel_progress(travel.kind), 100 * progress);
    ImGui::ProgressBar(float(progress), ImVec2(12 * font, 0), label);
    FastForwardRecord& record = state.last_fast_forward;
    ++record.frames;
    if (record.progress.size() < FastForwardRecord::kKept) record.progress.push_back(progress);
    ImGui::SameLine();
    if (ImGui::Button(tr_id("Cancel"))) cancel_travel(state);
    item_tooltip("%s", tr("Esc: stop here"));
  }
  ImGui::End();
}

void draw_time_buttons(AppState& state) {
  if (ImGui::Button("\u25c0|", ImVec2(target_width("\u25c0|"), 0))) step_back(state, false);
  item_tooltip("%s", tr("B: one step back"));
  same_line_if_fits(target_width("\u25c0\u25c0"));
  if (ImGui::Button("\u25c0\u25c0", ImVec2(target_width("\u25c0\u25c0"), 0)))
    step_back(state, true);
  item_tooltip("%s", tr("Left: back by 1/100 of a period"));
  same_line_if_fits(target_width("\u25b6\u25b6"));
  if (ImGui::Button("\u25b6\u25b6", ImVec2(target_width("\u25b6\u25b6"), 0)))
    step_forward_coarse(state);
  item_tooltip("%s", tr("Right: on by 1/100 of a period"));
  const char* to_stage_end = tr_id("\u25b6| stage");
  same_line_if_fits(target_width(to_stage_end));
  if (ImGui::Button(to_stage_end, ImVec2(target_width(to_stage_end), 0)))
    fast_forward_to_stage_end(state);
  item_tooltip("%s", tr("N: fast-forward to the end of this stage, as fast as the machine allows"));
  const char* to_run_end = tr_id("\u25b6| end");
  same_line_if_fits(target_width(to_run_end));
  if (ImGui::Button(to_run_end, ImVec2(target_width(to_run_end), 0)))
    fast_forward_to_run_end(state);
  item_tooltip("%s", tr("End: fast-forward to the end of the run (Esc cancels)"));
}

}  // namespace swarmlab
