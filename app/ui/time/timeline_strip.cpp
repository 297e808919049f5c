#include "ui/time/timeline_strip.h"

#include "ui/time/time_controls.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "ui/classroom/theme_style.h"

namespace swarmlab {
namespace {

const char* travel_name(TimeTravel::Kind kind) {
  switch (kind) {
    case TimeTravel::Kind::to_stage_end: return "to the end of the stage";
    case TimeTravel::Kind::to_run_end: return "to the end of the run";
    default: return "seeking";
  }
}

}  // namespace

float timeline_strip_height() { return 2.4f * ImGui::GetFontSize(); }

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
  if (!ImGui::Begin("Timeline###timeline", nullptr, flags)) {
    ImGui::End();
    return;
  }
  const float font = ImGui::GetFontSize();
  char clock[96];
  std::snprintf(clock, sizeof clock, "t = %.4g / %.4g reached", state.run->time(),
                double(timeline.reached()) * dt);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(clock);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "The present time and the furthest time computed. Drag on the bar to go back to any "
        "moment: the same state to the last bit, recomputed from snapshots.");
  ImGui::SameLine();

  const TimeTravel& travel = state.travel;
  float bar_width = ImGui::GetContentRegionAvail().x;
  if (travel.active() && travel.kind != TimeTravel::Kind::seek)
    bar_width -= 18 * font;  // room for the progress and Cancel
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float bar_height = ImGui::GetFrameHeight();
  ImGui::InvisibleButton("##scrub", ImVec2(std::max(bar_width, 4 * font), bar_height));
  const float x0 = origin.x, x1 = origin.x + std::max(bar_width, 4 * font);
  const double end = double(std::max(1L, timeline.end_step()));
  auto x_of = [&](long step) { return x0 + float(double(step) / end) * (x1 - x0); };
  auto step_at = [&](float px) {
    return long(std::clamp(double(px - x0) / double(x1 - x0), 0.0, 1.0) * end + 0.5);
  };
  // Dragging scrubs over the time computed so far; a click beyond it computes up to there.
  if (ImGui::IsItemActive()) {
    const long wanted = step_at(ImGui::GetIO().MousePos.x);
    const long target =
        ImGui::IsItemActivated() ? wanted : std::min(wanted, timeline.reached());
    if (!travel.active() || travel.target != target)
      travel_to(state, TimeTravel::Kind::seek, target);
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("t = %.4g", double(step_at(ImGui::GetIO().MousePos.x)) * dt);

  const Palette& colours = current_palette();
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
    char label[64];
    std::snprintf(label, sizeof label, "%s %.0f%%", travel_name(travel.kind),
                  100 * travel.progress(timeline.step()));
    ImGui::ProgressBar(float(travel.progress(timeline.step())), ImVec2(12 * font, 0), label);
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) cancel_travel(state);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Esc: stop here");
  }
  ImGui::End();
}

void draw_time_buttons(AppState& state) {
  if (ImGui::Button("\u25c0|")) step_back(state, false);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("B: one step back");
  ImGui::SameLine();
  if (ImGui::Button("\u25c0\u25c0")) step_back(state, true);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Left: back by 1/100 of a period");
  ImGui::SameLine();
  if (ImGui::Button("\u25b6\u25b6")) step_forward_coarse(state);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Right: on by 1/100 of a period");
  ImGui::SameLine();
  if (ImGui::Button("\u25b6| stage")) fast_forward_to_stage_end(state);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("N: fast-forward to the end of this stage, as fast as the machine allows");
  ImGui::SameLine();
  if (ImGui::Button("\u25b6| end")) fast_forward_to_run_end(state);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("End: fast-forward to the end of the run (Esc cancels)");
}

}  // namespace swarmlab
