// The instruments over the bottom left of the 3D view: a stopwatch on the simulated clock, the
// period meter of the selected particle beside the formula's value, and the particle's card.
// Every number comes from the core (swarm::Stopwatch, swarm::PeriodMeter, particle_orbit).

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "swarm/measure/stopwatch.h"
#include "swarm/physics/regime.h"
#include "swarm/physics/system.h"
#include "ui/input/touch_target.h"
#include "ui/panels/panels.h"

namespace swarmlab {
namespace {

const ImVec4 kNote(1.0f, 0.82f, 0.4f, 1.0f);  // notes and caveats: amber
constexpr std::size_t kLapsShown = 4;

/// "12.35 (3.538 periods)", or "12.35" when J M <= 0.
void format_time(char* out, std::size_t size, double time, double k) {
  if (const auto periods = swarm::in_periods(time, k))
    std::snprintf(out, size, "%.4g  (%.4g periods)", time, *periods);
  else
    std::snprintf(out, size, "%.4g", time);
}

void draw_stopwatch(AppState& state) {
  swarm::Stopwatch& w = state.instruments.stopwatch;
  const double t = state.run->time();
  const double k = swarm::stiffness(state.run->system());
  // The buttons first, each as wide whatever its label, and the growing time after them: no
  // button moves while a finger is on it.
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("Stopwatch");
  // Times in periods would give the period away where a lesson step hides the read-outs.
  const double k_shown = state.lessons.hides(LessonHidden::readouts) ? 0 : k;
  help_marker(
      "Measures simulated time: pausing the simulation pauses it, and it runs as fast as the "
      "simulation. In periods 2\u03c0/\u03c9 = 2\u03c0/\u221a(J M) when J > 0; for J \u2264 0 "
      "the motion has no period.");
  const float start_width = std::max(target_width("Start"), target_width("Stop"));
  same_line_if_fits(start_width);
  if (ImGui::Button(w.running() ? "Stop###start" : "Start###start", ImVec2(start_width, 0))) {
    if (w.running())
      w.stop(t);
    else
      w.start(t);
  }
  same_line_if_fits(target_width("Lap"));
  ImGui::BeginDisabled(!w.running());
  if (ImGui::Button("Lap", ImVec2(target_width("Lap"), 0))) w.lap(t);
  ImGui::EndDisabled();
  same_line_if_fits(target_width("Reset"));
  if (ImGui::Button("Reset##stopwatch", ImVec2(target_width("Reset"), 0))) w.reset();
  char text[96];
  format_time(text, sizeof text, w.elapsed(), k_shown);
  ImGui::Text("  %s", text);
  if (swarm::regime_of(k) != swarm::Regime::attractive)
    ImGui::TextDisabled("J \u2264 0: the motion has no period");
  const auto& laps = w.laps();
  for (std::size_t i = laps.size() > kLapsShown ? laps.size() - kLapsShown : 0; i < laps.size();
       ++i) {
    const double split = laps[i] - (i > 0 ? laps[i - 1] : 0.0);
    format_time(text, sizeof text, split, k_shown);
    ImGui::Text("  lap %zu: %s", i + 1, text);
  }
}

void draw_period_meter(AppState& state) {
  const std::optional<ParticleTrack>& track = state.instruments.track;
  if (!track) {
    ImGui::TextDisabled("Period meter: click a particle to time its period.");
    return;
  }
  const swarm::PeriodMeter& m = track->meter;
  ImGui::Text("Period of particle %zu", track->particle + 1);
  help_marker(
      "Measured from its motion: the times at which it passes the centre of mass's plane "
      "(across its starting direction) again in the same direction, each found between two "
      "frames on a cubic through their positions and velocities. Shown beside the formula "
      "2\u03c0/\u221a(J M), the same for every particle whatever its mass.");
  switch (m.status()) {
    case swarm::PeriodStatus::no_period:
      ImGui::TextColored(kNote, "J \u2264 0: free flight or a runaway, no period to measure.");
      return;
    case swarm::PeriodStatus::at_centre:
      ImGui::TextColored(kNote, "It sits at rest on the centre of mass: no motion to time.");
      return;
    case swarm::PeriodStatus::measuring:
      ImGui::TextDisabled("measuring... (it must pass the same phase twice)");
      break;
    case swarm::PeriodStatus::measured:
      ImGui::Text("measured  %.6g  (%d period%s timed)", *m.period(), m.periods_measured(),
                  m.periods_measured() == 1 ? "" : "s");
      // The formula's value is a read-out: a lesson step that hides them hides it too.
      if (!state.lessons.hides(LessonHidden::readouts)) {
        ImGui::Text("formula   %.6g  = 2\u03c0/\u221a(J M)", *m.formula_period());
        ImGui::Text("difference %+.2e  (relative)", *m.relative_difference());
      }
      break;
  }
  if (m.status() == swarm::PeriodStatus::measuring && !state.lessons.hides(LessonHidden::readouts))
    ImGui::TextDisabled("formula 2\u03c0/\u221a(J M) = %.6g", *m.formula_period());
  if (m.gaps() > 0)
    ImGui::TextColored(kNote, "%d jump(s) too long to time across (over a quarter period)",
                       m.gaps());
  if (state.preset.container_radius) {
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 24);
    ImGui::TextColored(kNote,
                       "In a container wall hits change the orbit and move the centre of mass: "
                       "after a hit, the time between returns is no longer 2\u03c0/\u03c9.");
    ImGui::PopTextWrapPos();
  }
}

}  // namespace

void draw_instruments(AppState& state) {
  if (ImGui::CollapsingHeader("Instruments", ImGuiTreeNodeFlags_DefaultOpen)) {
    draw_stopwatch(state);
    ImGui::Separator();
    draw_period_meter(state);
  }
  if (state.instruments.track) draw_particle_card(state);
}

}  // namespace swarmlab
