// The live plots: wall pressure and temperature with a running average, the energies, the
// expansion's P-V, T-V and P-T with power-law fits, and the errors of the numerical methods.

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <vector>

#include "i18n/translator.h"
#include "swarm/physics/regime.h"
#include "ui/kit/theme_style.h"
#include "ui/kit/wrapping_tabs.h"
#include "ui/lesson_player/lesson_panel.h"
#include "ui/panels/panels.h"
#include "ui/plots/fit_quality.h"
#include "ui/plots/plot_widget.h"

namespace swarmlab {
namespace {

/// The series colours of the app's theme (access/theme_palette.h).
const Palette& colours(const AppState& state) { return palette(state.presentation.theme); }

/// A method's plot colour, from the core's method table.
std::uint32_t colour_of(swarm::Method m, const AppState& state) {
  const auto& [r, g, b] = swarm::info_of(m).colour;
  return plot_line_colour(Colour{std::uint8_t(r), std::uint8_t(g), std::uint8_t(b), 255},
                          state.presentation.theme)
      .packed();
}

std::optional<double> window_start(const AppState& state, double now) {
  if (state.plots.scroll_window <= 0) return std::nullopt;
  return std::max(0.0, now - state.plots.scroll_window);
}

void draw_wall_tab(AppState& state, float plot_height) {
  if (!state.preset.container_radius) {
    // Without a wall there is nothing to measure: no plots of zeros and blanks.
    ImGui::TextWrapped("%s", tr(
        "No container: pressure and temperature are measured where the particles hit the "
        "wall. Switch one on under Container (in the Controls) to measure them."));
    return;
  }
  const float width = 0.42f * ImGui::GetContentRegionAvail().x;
  ImGui::SetNextItemWidth(width);
  ImGui::InputDouble(tr_id("average over"), &state.plots.average_window, 0, 0, "%.4g");
  state.plots.average_window = std::max(0.0, state.plots.average_window);
  help_marker(
      tr("Running average of P and T over this much simulated time (0: none). P and T "
         "from a single interval are noisy: few particles hit the wall in each one."));
  ImGui::SetNextItemWidth(width);
  ImGui::InputDouble(tr_id("show last"), &state.plots.scroll_window, 0, 0, "%.4g");
  state.plots.scroll_window = std::max(0.0, state.plots.scroll_window);
  help_marker(tr("Scroll: show only this much of the most recent time (0: the whole run)."));

  SampleSeries& series = state.sample_series;
  series.update(*state.run, state.plots.average_window);
  const std::string empty = tr("waiting for the first samples");
  PlotSpec p;
  p.title = tr("Wall pressure");
  p.file_title = "Wall pressure";
  p.x = {tr("t (time)"), false, window_start(state, state.run->time()), std::nullopt};
  p.y = {tr("P (force/area)"), false, std::nullopt, std::nullopt};
  p.y_from_zero = true;
  p.empty_message = empty;
  p.series = {{tr("each sample"), &series.t, &series.P,
               colours(state).pressure_each_sample.packed(), false, 1.0f},
              {tr("running average"), &series.t, &series.P_mean, colours(state).pressure.packed(),
               false, 2.5f}};
  draw_plot("pressure", p, plot_height, state);

  PlotSpec t = p;
  t.title = tr("Wall temperature");
  t.file_title = "Wall temperature";
  t.y = {tr("T (energy, k_B = 1)"), false, std::nullopt, std::nullopt};
  t.series = {{tr("each sample"), &series.t, &series.T,
               colours(state).temperature_each_sample.packed(), false, 1.0f},
              {tr("running average"), &series.t, &series.T_mean,
               colours(state).temperature.packed(), false, 2.5f}};
  draw_plot("temperature", t, plot_height, state);
}

void draw_energy_tab(AppState& state, float plot_height) {
  SampleSeries& series = state.sample_series;
  series.update(*state.run, state.plots.average_window);
  // Timing the energy plot's swings gives half the period, a trap worth naming.
  if (swarm::regime_of(swarm::stiffness(state.run->system())) == swarm::Regime::attractive)
    ImGui::TextColored(colour_vec4(colours(state).text_warning), "%s",
                       tr("KE and PE swing at 2ω: one swing is half a period."));
  const std::vector<double>& t_all = series.t_all;
  PlotSpec e;
  e.title = tr("KE, PE and E");
  e.file_title = "KE, PE and E";
  e.x = {tr("t (time)"), false, window_start(state, state.run->time()), std::nullopt};
  e.y = {tr("energy"), false, std::nullopt, std::nullopt};
  e.y_from_zero = true;
  e.series = {
      {"KE", &t_all, &series.KE, colours(state).kinetic.packed(), false, 2.0f},
      {"PE", &t_all, &series.PE, colours(state).potential.packed(), false, 2.0f},
      {"E = KE + PE", &t_all, &series.E, colours(state).total_energy.packed(), false, 2.5f}};
  draw_plot("energies", e, plot_height, state);

  PlotSpec d;
  d.title = tr("Energy change");
  d.file_title = "Energy change";
  d.x = e.x;
  d.y = {"(E - E\u2080) / |E\u2080|", false, std::nullopt, std::nullopt};
  d.series = {{std::string(swarm::name_of(state.preset.method)), &t_all, &series.drift,
               colour_of(state.preset.method, state), false, 2.0f}};
  draw_plot("drift", d, plot_height, state);
}

void draw_expansion_tab(AppState& state, float plot_height) {
  if (!state.preset.expansion && state.run->primary().stages().empty()) {
    ImGui::TextWrapped("%s", tr(
        "No stages yet. With a container, each Expand now (E) ends a stage, averaged like "
        "the protocol's, and plots it here; or under Container switch on the stepwise "
        "expansion."));
    return;
  }
  ImGui::Checkbox(tr_id("log-log axes"), &state.plots.log_log);
  help_marker(
      tr("On log-log axes a power law y = a x^b is a straight line of slope b. The fit is "
         "least squares of ln y on ln x over the stages with P, T > 0 (paper Appendix C)."));
  const auto& stages = state.run->primary().stages();
  static std::vector<double> V, P, T;
  V.clear(), P.clear(), T.clear();
  for (const swarm::Stage& s : stages) {
    V.push_back(s.V);
    P.push_back(s.P);
    T.push_back(s.T);
  }
  const swarm::StageFits fits = state.run->primary().fits();
  const bool log = state.plots.log_log;
  std::string first_stage = tr("the first stage ends with Expand now (E)");
  if (state.preset.expansion) {
    char text[256];
    std::snprintf(text, sizeof text, tr("the first stage ends at t = tau = %.4g"),
                  state.preset.expansion->tau);
    first_stage = translator().numbers(text);
  }
  // title: in the language in use; file_title: in English, for the saved files' names.
  auto plot = [&](const char* id, const char* title, const char* file_title, const char* x_label,
                  const std::vector<double>& x, const char* y_label, const std::vector<double>& y,
                  const swarm::PowerLawFit& fit, const char* law, std::uint32_t colour) {
    PlotSpec s;
    s.title = title;
    s.file_title = file_title;
    s.x = {x_label, log, std::nullopt, std::nullopt};
    s.y = {y_label, log, std::nullopt, std::nullopt};
    s.y_from_zero = !log;
    s.empty_message = first_stage;
    s.series = {{tr("stages"), &x, &y, colour, true, 2.0f}};
    if (fit.valid) {
      char label[96];
      std::snprintf(label, sizeof label, "%s^%.3f \u00b1 %.3f", law, fit.slope, fit.slope_stderr);
      s.fits.push_back({translator().numbers(label), std::exp(fit.intercept), fit.slope,
                        colours(state).fit.packed()});
    }
    if (draw_plot(id, s, plot_height, state) && fit.valid) {
      ImGui::BeginTooltip();
      char line[256];
      std::snprintf(line, sizeof line,
                    tr("ln y = %.4g + (%.4g \u00b1 %.2g) ln x,  R\u00b2 = %.4f over %zu stages"),
                    fit.intercept, fit.slope, fit.slope_stderr, fit.r_squared, fit.used.size());
      ImGui::TextUnformatted(translator().numbers(line).c_str());
      ImGui::EndTooltip();
    }
    draw_fit_quality((std::string(id) + " residuals").c_str(), x, fit, log, 0.45f * plot_height,
                     state);
  };
  plot("pv", tr("P against V"), "P against V", tr("V (length\u00b3)"), V, tr("P (force/area)"), P,
       fits.P_V, "P \u221d V", colours(state).pressure.packed());
  plot("tv", tr("T against V"), "T against V", tr("V (length\u00b3)"), V, tr("T (energy)"), T,
       fits.T_V, "T \u221d V", colours(state).temperature.packed());
  plot("pt", tr("P against T"), "P against T", tr("T (energy)"), T, tr("P (force/area)"), P,
       fits.P_T, "P \u221d T", colours(state).pressure_against_temperature.packed());
}

void draw_compare_tab(AppState& state, float plot_height) {
  const auto& errors = state.run->errors();
  if (state.preset.compare.empty()) {
    ImGui::TextWrapped("%s", tr(
        "Nothing runs side by side. Under Simulation, tick 'analytic' next to a "
        "numerical method (or the other way round) to compare them here."));
    return;
  }
  static std::vector<std::vector<double>> energy_t, energy;
  PlotSpec e;
  e.title = tr("Energy error");
  e.file_title = "Energy error";
  e.x = {tr("t (time)"), false, window_start(state, state.run->time()), std::nullopt};
  e.y = {"(E - E\u2080) / |E\u2080|", false, std::nullopt, std::nullopt};
  // Every run's energy from its own samples, so methods compare even without 'analytic'.
  const std::size_t runs = 1 + state.run->compared_count();
  energy_t.resize(runs);
  energy.resize(runs);
  for (std::size_t k = 0; k < runs; ++k) {
    swarm::Run& run = k == 0 ? state.run->primary() : state.run->compared(k - 1);
    const swarm::Method m = k == 0 ? state.preset.method : state.run->compared_method(k - 1);
    energy_t[k].clear();
    energy[k].clear();
    for (const swarm::Sample& s : run.samples()) {
      energy_t[k].push_back(s.t);
      energy[k].push_back(swarm::relative_energy_change(run.samples().front(), s.E));
    }
    e.series.push_back({std::string(swarm::name_of(m)), &energy_t[k], &energy[k],
                        colour_of(m, state), false, 2.0f});
  }
  draw_plot("energy_error", e, plot_height, state);

  PlotSpec p;
  p.title = tr("Position error");
  p.file_title = "Position error";
  p.x = e.x;
  p.y = {tr("max |\u0394r| from the exact orbit (length)"), false, std::nullopt, std::nullopt};
  p.y_from_zero = true;
  p.empty_message = tr("tick 'analytic' under Side by side to measure position errors");
  for (const swarm::ErrorFromExact& track : errors)
    p.series.push_back({std::string(swarm::name_of(track.method)), &track.t, &track.position_error,
                        colour_of(track.method, state), false, 2.0f});
  draw_plot("position_error", p, plot_height, state);
}

/// A plot tab: its label, the rows of options above its plots, how many plots share its height
/// and what draws them. One row per PlotTab, in its order.
struct PlotTabDescriptor {
  PlotTab tab;
  const char* (*label)();  ///< the tab's label in the language in use (tr_id)
  float option_rows;  ///< in frame heights
  int (*plot_count)(const AppState& state);
  void (*draw)(AppState& state, float plot_height);
};

int two(const AppState&) { return 2; }
int three(const AppState&) { return 3; }
int one(const AppState&) { return 1; }
int projects(const AppState& state) { return std::max(1, project_plot_count(state.preset)); }

// Tabs keep their full names and wrap in a narrow panel ("W... E..." told nothing).
constexpr PlotTabDescriptor kPlotTabs[] = {
    {PlotTab::wall, [] { return tr_id("Wall P, T"); }, 2.6f, two, draw_wall_tab},
    {PlotTab::energy, [] { return tr_id("Energy"); }, 1.0f, two, draw_energy_tab},
    {PlotTab::expansion, [] { return tr_id("Expansion"); }, 1.4f, three, draw_expansion_tab},
    {PlotTab::compare, [] { return tr_id("Compare"); }, 0.0f, two, draw_compare_tab},
    {PlotTab::particle, [] { return tr_id("Particle"); }, 3.0f, one, draw_particle_tab},
    {PlotTab::projects, [] { return tr_id("Projects"); }, 0.0f, projects, draw_projects_tab},
};
// The rows follow the enum, so that --plot-tab's numbers are the tabs' places on screen.
constexpr bool in_plot_tab_order() {
  for (std::size_t i = 0; i < std::size(kPlotTabs); ++i)
    if (kPlotTabs[i].tab != PlotTab(i)) return false;
  return std::size(kPlotTabs) == kPlotTabCount;
}
static_assert(in_plot_tab_order(), "one descriptor per plot tab, in PlotTab's order");

}  // namespace

void draw_plots_panel(AppState& state) {
  // Another window draws the tabs after a change of layout or presentation mode: its new tab
  // bar opens on the tab that was open, not on the first.
  const unsigned window = ImGui::GetID("##plot-tabs");  // differs with the window drawing it
  if (window != state.plots.tab_window && !state.plots.tab)
    state.plots.tab = state.plots.shown_tab;
  state.plots.tab_window = window;
  auto draw_tab = [&](const PlotTabDescriptor& d) {
    state.plots.shown_tab = d.tab;
    const float available =
        ImGui::GetContentRegionAvail().y - d.option_rows * ImGui::GetFrameHeightWithSpacing();
    const float height =
        std::max(8 * ImGui::GetFontSize(),
                 available / float(d.plot_count(state)) - ImGui::GetStyle().ItemSpacing.y);
    if (!draw_hidden_by_lesson(state, LessonHidden::plots)) d.draw(state, height);
  };
  // Where the tabs do not fit in one row they wrap onto more (wrapping_tabs.h).
  std::vector<const char*> labels;
  for (const PlotTabDescriptor& d : kPlotTabs) labels.push_back(d.label());
  if (!tabs_fit(labels)) {
    const PlotTab open = state.plots.tab.value_or(state.plots.shown_tab.value_or(PlotTab::wall));
    draw_tab(kPlotTabs[draw_wrapping_tabs(labels, int(open))]);
    state.plots.tab.reset();
    state.plots.tabs_wrapped = true;
    return;
  }
  // Back from wrapped tabs: the same tab.
  if (state.plots.tabs_wrapped && !state.plots.tab) state.plots.tab = state.plots.shown_tab;
  state.plots.tabs_wrapped = false;
  if (!ImGui::BeginTabBar("plots", ImGuiTabBarFlags_FittingPolicyScroll)) return;
  for (const PlotTabDescriptor& d : kPlotTabs) {
    const ImGuiTabItemFlags flags = state.plots.tab == d.tab ? ImGuiTabItemFlags_SetSelected : 0;
    if (!ImGui::BeginTabItem(d.label(), nullptr, flags)) continue;
    draw_tab(d);
    ImGui::EndTabItem();
  }
  state.plots.tab.reset();
  ImGui::EndTabBar();
}

}  // namespace swarmlab
