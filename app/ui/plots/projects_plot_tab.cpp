// The plots of the Appendix B projects that fit the running preset: the centre of mass's
// height and the swarm's size, the energy books, the P-V loop of a moving wall, and the
// speeds against the Maxwellian. The numbers come from the run's samples and the core's speed
// histogram (state/project_plots.h, report/pv_loop.h), kept between frames in
// AppState::project_cache (state/plot_series.h); this file only draws them.

#include <imgui.h>

#include <cstdio>

#include "i18n/translator.h"
#include "report/pv_loop.h"
#include "ui/kit/theme_style.h"
#include "ui/panels/panels.h"
#include "ui/plots/plot_widget.h"
#include "ui/state/project_plots.h"

namespace swarmlab {
namespace {

ImU32 line(const Colour& c) { return c.packed(); }

}  // namespace

int project_plot_count(const swarm::Preset& preset) {
  const ProjectPlots p = project_plots_for(preset);
  return int(p.motion) + int(p.books) + int(p.pv_loop) + int(p.speeds);
}

void draw_projects_tab(AppState& state, float plot_height) {
  const ProjectPlots plots = project_plots_for(state.preset);
  if (!plots.any()) {
    ImGui::TextWrapped("%s", tr(
        "Plots for the Appendix B projects: gravity, a floor, drag, moving or hot walls, hard "
        "spheres. This preset has none of them: switch one on under 'Gravity, floor, drag' or "
        "'Walls and spheres', or open a project preset under Scenario."));
    return;
  }
  ProjectCache& cache = state.project_cache;
  cache.update(*state.run, state.preset, plots);
  const Palette& c = palette(state.presentation.theme);
  const ProjectSeries& s = cache.series;
  const PlotAxis time{tr("t (time)"), false, std::nullopt, std::nullopt};

  if (plots.motion) {
    PlotSpec m;
    m.title = tr("CM height and size");
    m.file_title = "CM height and size";
    m.x = time;
    m.y = {tr("length"), false, std::nullopt, std::nullopt};
    m.y_from_zero = true;
    m.series = {
        {tr("CM height z"), &s.t, &s.cm_height, line(c.pressure), false, 2.0f},
        {tr("size: rms distance from the CM"), &s.t, &s.size, line(c.temperature), false, 2.0f}};
    draw_plot("project_motion", m, plot_height, state);
  }
  if (plots.books) {
    PlotSpec b;
    // A short title: the axis label and its power-of-ten factor share the line. The sum is
    // drawn wide underneath, so E - E0 and a lone book on top of it stay visible.
    b.title = tr("Energy books");
    b.file_title = "Energy books";
    b.x = time;
    b.y = {tr("energy"), false, std::nullopt, std::nullopt};
    b.y_from_zero = true;
    b.series = {
        {tr("sum: work + heat - drag loss"), &s.t, &s.net, line(c.energy_books_sum), false, 6.0f},
        {"E - E\u2080", &s.t, &s.energy_change, line(c.total_energy), false, 2.0f},
        {tr("work by the walls"), &s.t, &s.wall_work, line(c.pressure), false, 1.5f},
        {tr("heat from the wall"), &s.t, &s.wall_heat, line(c.temperature), false, 1.5f},
        {tr("drag loss"), &s.t, &s.drag_loss, line(c.kinetic), false, 1.5f}};
    draw_plot("project_books", b, plot_height, state);
  }
  if (plots.pv_loop) {
    const report::PvLoop& l = cache.loop;
    PlotSpec p;
    p.title = tr("P-V loop");
    p.file_title = "P-V loop";
    p.x = {tr("V = 4/3 \u03c0 R\u00b3 (length\u00b3)"), false, std::nullopt, std::nullopt};
    p.y = {tr("P (force/area)"), false, std::nullopt, std::nullopt};
    p.y_from_zero = true;
    p.empty_message = tr("waiting for the wall to move");
    p.series = {
        {tr("wall moving in (P: running mean)"), &l.V_in, &l.P_in, line(c.pressure), false, 2.0f}};
    if (!l.V_out.empty())
      p.series.push_back({tr("wall moving out"), &l.V_out, &l.P_out, line(c.temperature), false, 2.0f});
    draw_plot("project_pv", p, plot_height, state);
  }
  if (plots.speeds) {
    const HistogramSeries& h = cache.histogram;
    char maxwell[256];
    std::snprintf(maxwell, sizeof maxwell, tr("Maxwellian at their T = %.4g"), cache.speeds.T);
    PlotSpec v;
    v.title = tr("Speeds now");
    v.file_title = "Speeds now";
    v.x = {tr("speed v \u221a(m/T)"), false, 0.0, cache.speeds.histogram.x_max};
    v.y = {tr("probability density"), false, std::nullopt, std::nullopt};
    v.y_from_zero = true;
    v.empty_message = tr("no motion yet: T = 0");
    v.series = {{tr("the particles now"), &h.x, &h.measured, line(c.kinetic), true, 2.0f},
                {translator().numbers(maxwell), &h.x, &h.maxwell, line(c.fit), false, 2.0f}};
    draw_plot("project_speeds", v, plot_height, state);
  }
}

}  // namespace swarmlab
