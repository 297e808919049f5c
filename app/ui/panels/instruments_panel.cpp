// The instruments over the bottom left of the 3D view: a stopwatch on the simulated clock, the
// period meter of the selected particle beside the formula's value, and the particle's card.
// Every number comes from the core (swarm::Stopwatch, swarm::PeriodMeter, particle_orbit).

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "i18n/translator.h"
#include "swarm/measure/stopwatch.h"
#include "swarm/physics/regime.h"
#include "swarm/physics/system.h"
#include "ui/kit/touch_target.h"
#include "ui/panels/panels.h"

namespace swarmlab {
namespace {

const ImVec4 kNote(1.0f, 0.82f, 0.4f, 1.0f);  // notes and caveats: amber
constexpr std::size_t kLapsShown = 4;

/// "12.35 (3.538 periods)", or "12.35" when J M <= 0, with the language's decimal separator.
void format_time(char* out, std::size_t size, double time, double k) {
  if (const auto periods = swarm::in_periods(time, k))
    std::snprintf(out, size, tr("%.4g  (%.4g periods)"), time, *periods);
  else
    std::snprintf(out, size, "%.4g", time);
  std::snprintf(out, size, "%s", translator().numbers(out).c_str());
}

void draw_stopwatch(AppState& state) {
  swarm::Stopwatch& w = state.instruments.stopwatch;
  const double t = state.run->time();
  const double k = swarm::stiffness(state.run->system());
  // The buttons first, each as wide whatever its label, and the growing time after them: no
  // button moves while a finger is on it.
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(tr("Stopwatch"));
  // Times in periods would give the period away where a lesson step hides the read-outs.
  const double k_shown = state.lessons.hides(LessonHidden::readouts) ? 0 : k;
  help_marker(
      tr("Measures simulated time: pausing the simulation pauses it, and it runs as fast as the "
         "simulation. In periods 2\u03c0/\u03c9 = 2\u03c0/\u221a(J M) when J > 0; for J \u2264 0 "
         "the motion has no period."));
  const float start_width = std::max(target_width(tr("Start")), target_width(tr("Stop")));
  same_line_if_fits(start_width);
  if (ImGui::Button(w.running() ? tr_id("Stop###start") : tr_id("Start###start"),
                    ImVec2(start_width, 0))) {
    if (w.running())
      w.stop(t);
    else
      w.start(t);
  }
  same_line_if_fits(target_width(tr_id("Lap")));
  ImGui::BeginDisabled(!w.running());
  if (ImGui::Button(tr_id("Lap"), ImVec2(target_width(tr_id("Lap")), 0))) w.lap(t);
  ImGui::EndDisabled();
  same_line_if_fits(target_width(tr_id("Reset##stopwatch")));
  if (ImGui::Button(tr_id("Reset##stopwatch"), ImVec2(target_width(tr_id("Reset##stopwatch")), 0)))
    w.reset();
  char text[160];
  format_time(text, sizeof text, w.elapsed(), k_shown);
  ImGui::Text("  %s", text);
  if (swarm::regime_of(k) != swarm::Regime::attractive)
    ImGui::TextDisabled("%s", tr("J \u2264 0: the motion has no period"));
  const auto& laps = w.laps();
  for (std::size_t i = laps.size() > kLapsShown ? laps.size() - kLapsShown : 0; i < laps.size();
       ++i) {
    const double split = laps[i] - (i > 0 ? laps[i - 1] : 0.0);
    format_time(text, sizeof text, split, k_shown);
    ImGui::Text(tr("  lap %zu: %s"), i + 1, text);
  }
}

void draw_period_meter(AppState& state) {
  const std::optional<ParticleTrack>& track = state.instruments.track;
  if (!track) {
    ImGui::TextDisabled("%s", tr("Period meter: click a particle to time its period."));
    return;
  }
  const swarm::PeriodMeter& m = track->meter;
  ImGui::Text(tr("Period of particle %zu"), track->particle + 1);
  help_marker(
      tr("Measured from its motion: the times at which it passes the centre of mass's plane "
         "(across its starting direction) again in the same direction, each found between two "
         "frames on a cubic through their positions and velocities. Shown beside the formula "
         "2\u03c0/\u221a(J M), the same for every particle whatever its mass."));
  switch (m.status()) {
    case swarm::PeriodStatus::no_period:
      ImGui::TextColored(kNote, "%s",
                         tr("J \u2264 0: free flight or a runaway, no period to measure."));
      return;
    case swarm::PeriodStatus::at_centre:
      ImGui::TextColored(kNote, "%s",
                         tr("It sits at rest on the centre of mass: no motion to time."));
      return;
    case swarm::PeriodStatus::measuring:
      ImGui::TextDisabled("%s", tr("measuring... (it must pass the same phase twice)"));
      break;
    case swarm::PeriodStatus::measured: {
      // One sentence for one period and one for several, so a language words each its way.
      char text[160];
      std::snprintf(text, sizeof text,
                    m.periods_measured() == 1 ? tr("measured  %.6g  (%d period timed)")
                                              : tr("measured  %.6g  (%d periods timed)"),
                    *m.period(), m.periods_measured());
      ImGui::TextUnformatted(translator().numbers(text).c_str());
      // The formula's value is a read-out: a lesson step that hides them hides it too.
      if (!state.lessons.hides(LessonHidden::readouts)) {
        std::snprintf(text, sizeof text, tr("formula   %.6g  = 2\u03c0/\u221a(J M)"),
                      *m.formula_period());
        ImGui::TextUnformatted(translator().numbers(text).c_str());
        std::snprintf(text, sizeof text, tr("difference %+.2e  (relative)"),
                      *m.relative_difference());
        ImGui::TextUnformatted(translator().numbers(text).c_str());
      }
      break;
    }
  }
  if (m.status() == swarm::PeriodStatus::measuring &&
      !state.lessons.hides(LessonHidden::readouts)) {
    char text[160];
    std::snprintf(text, sizeof text, tr("formula 2\u03c0/\u221a(J M) = %.6g"), *m.formula_period());
    ImGui::TextDisabled("%s", translator().numbers(text).c_str());
  }
  if (m.gaps() > 0)
    ImGui::TextColored(kNote, tr("%d jump(s) too long to time across (over a quarter period)"),
                       m.gaps());
  if (state.preset.container_radius) {
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 24);
    ImGui::TextColored(kNote, "%s",
                       tr("In a container wall hits change the orbit and move the centre of mass: "
                          "after a hit, the time between returns is no longer 2\u03c0/\u03c9."));
    ImGui::PopTextWrapPos();
  }
}

}  // namespace

void draw_instruments(AppState& state) {
  if (ImGui::CollapsingHeader(tr_id("Instruments"), ImGuiTreeNodeFlags_DefaultOpen)) {
    draw_stopwatch(state);
    ImGui::Separator();
    draw_period_meter(state);
  }
  if (state.instruments.track) draw_particle_card(state);
}

}  // namespace swarmlab
