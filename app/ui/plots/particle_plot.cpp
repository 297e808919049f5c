// The selected particle's x(t) about the centre of mass, with a line at its starting value:
// each return to that line in the same direction is one period.

#include <imgui.h>

#include <cstdio>

#include "i18n/translator.h"
#include "ui/kit/theme_style.h"
#include "ui/panels/panels.h"
#include "ui/plots/plot_widget.h"

namespace swarmlab {

void draw_particle_tab(AppState& state, float plot_height) {
  const std::optional<ParticleTrack>& track = state.instruments.track;
  if (!track) {
    ImGui::TextWrapped("%s", tr(
        "Click a particle in the view (or call swarmlab.select(i) in the browser) to plot its "
        "x(t) about the centre of mass."));
    return;
  }
  // The start marker and a level line at the starting value, from the first frame to now.
  static std::vector<double> start_t, start_x, level_t, level_x;
  start_t.assign(1, track->t.empty() ? 0.0 : track->t.front());
  start_x.assign(1, track->x_start);
  level_t = {start_t[0], track->t.empty() ? start_t[0] : track->t.back()};
  level_x.assign(2, track->x_start);
  PlotSpec p;
  char title[256];
  std::snprintf(title, sizeof title, tr("Particle %zu: x(t) \u2212 X_cm(t)"),
                track->particle + 1);
  p.title = title;
  p.file_title = "Particle " + std::to_string(track->particle + 1) + ": x(t) \u2212 X_cm(t)";
  p.x = {tr("t (time)"), false, std::nullopt, std::nullopt};
  p.y = {tr("x about the CM (length)"), false, std::nullopt, std::nullopt};
  const Palette& colours = palette(state.presentation.theme);
  p.series = {
      {tr("starting value"), &level_t, &level_x, colours.starting_value.packed(), false, 1.0f},
      {"x(t)", &track->t, &track->x, colours.particle_track.packed(), false, 2.0f},
      {tr("start"), &start_t, &start_x, colours.particle_start.packed(), true, 2.0f}};
  draw_plot("particle_x", p, plot_height, state);
  ImGui::TextWrapped("%s", tr(
      "Each time x(t) crosses its starting value in the same direction, one period has passed. "
      "The period meter (Instruments, above the plots) times these returns."));
}

}  // namespace swarmlab
