// The read-outs over the 3D view: each quantity with the equation behind it on hover.

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "i18n/printed.h"
#include "i18n/translator.h"
#include "swarm/measure/speed_distribution.h"
#include "swarm/measure/virial_balance.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/physics/regime.h"
#include "swarm/physics/wall.h"
#include "ui/lesson_player/lesson_panel.h"
#include "ui/panels/panels.h"
#include "ui/parallel_dom/parallel_dom.h"
#include "ui/state/instruments.h"

namespace swarmlab {
namespace {

/// One name and value, and the equation behind it (shown on hover).
struct Row {
  std::string name, value, equation;
};

/// The rows of this frame, laid out once all are known (lay_out).
std::vector<Row>& rows() {
  static std::vector<Row> all;
  return all;
}

/// One name and value: two cells of the table, which wraps to its next row by itself. The
/// caller translates the name and the equation; the value's decimal points are written as the
/// language writes them.
void row(const char* name, const char* printed_value, const char* equation) {
  rows().push_back({name, translator().numbers(printed_value), equation});
}

/// The rows as a table of name-value pairs, as many pairs across as the width holds (a strip
/// under the view is short): at most one per 14 font sizes, fewer where the columns, each as
/// wide as its longest name or value, would not fit (a translation's longer values), so that
/// no pair is pushed out of sight.
void lay_out(const char* id) {
  const float font = ImGui::GetFontSize();
  const float padding = 2 * ImGui::GetStyle().CellPadding.x;
  const float room = ImGui::GetContentRegionAvail().x;
  const std::vector<Row>& all = rows();
  auto width_of = [&](int pairs) {  // the table's width with `pairs` pairs across
    std::vector<float> name(std::size_t(pairs), 0.0f), value(std::size_t(pairs), 0.0f);
    for (std::size_t i = 0; i < all.size(); ++i) {
      const std::size_t column = i % std::size_t(pairs);
      name[column] = std::max(name[column], ImGui::CalcTextSize(all[i].name.c_str()).x);
      value[column] = std::max(value[column], ImGui::CalcTextSize(all[i].value.c_str()).x);
    }
    float width = 0;
    for (int c = 0; c < pairs; ++c) width += name[std::size_t(c)] + value[std::size_t(c)] + 2 * padding;
    return width;
  };
  int pairs = std::clamp(int(room / (14 * font)), 1, 6);
  while (pairs > 1 && width_of(pairs) > room) --pairs;
  // One pair across and still too wide: the value column takes the rest and wraps.
  const bool wrap = pairs == 1 && width_of(1) > room;
  const ImGuiTableFlags flags = ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_NoSavedSettings;
  // Cells fit their text (a panel's text otherwise wraps at its edge: panel_windows.cpp).
  ImGui::PushTextWrapPos(-1.0f);
  if (!ImGui::BeginTable(id, 2 * pairs, flags)) {
    ImGui::PopTextWrapPos();
    return;
  }
  if (wrap) {
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
  }
  for (const Row& r : rows()) {
    // A screen reader reads the row as it is shown (the parallel DOM keeps it up to date).
    mirror_text(ItemRole::paragraph, r.name + " = " + r.value);
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(r.name.c_str());
    bool hovered = ImGui::IsItemHovered();
    ImGui::TableNextColumn();
    if (wrap) ImGui::PushTextWrapPos(0);
    ImGui::TextUnformatted(r.value.c_str());
    if (wrap) ImGui::PopTextWrapPos();
    hovered |= ImGui::IsItemHovered();
    if (hovered) {
      ImGui::BeginTooltip();
      ImGui::PushTextWrapPos(font * 26);
      ImGui::TextUnformatted(r.equation.c_str());
      ImGui::PopTextWrapPos();
      ImGui::EndTooltip();
    }
  }
  ImGui::EndTable();
  ImGui::PopTextWrapPos();
}

/// Wall hits per unit of simulated time over the plots' averaging window (or the whole run).
double hit_rate(LiveRun& run, double window) {
  const auto& samples = run.primary().samples();
  if (samples.size() < 2) return 0;
  const double now = samples.back().t;
  const double from = window > 0 ? now - window : 0;
  long hits = 0;
  double start = now;
  for (auto s = samples.rbegin(); s != samples.rend() - 1; ++s) {
    if (s->t <= from) break;
    hits += s->hits;
    start = (s + 1)->t;
  }
  return now > start ? double(hits) / (now - start) : 0;
}

/// "1.234 ± 0.05", or the value alone without an uncertainty.
void format_estimate(char* out, std::size_t size, double v, const std::optional<double>& error) {
  if (error)
    std::snprintf(out, size, "%.4g ± %.2g", v, *error);
  else
    std::snprintf(out, size, "%.4g", v);
}

/// Where the ± comes from, in a few words for the row and a sentence for its tooltip; `out`
/// holds the words while P's ± from the window's parts is withheld (shown_wall_error).
const char* error_source_words(const swarm::WallEstimate& w, char* out, std::size_t size) {
  if (w.source == swarm::WallErrorSource::parts && !shown_wall_error(w.mean.P, w.P_stderr, w.source)) {
    std::snprintf(out, size, tr("± after %.0f windows"), swarm::kWallHistoryWindows);
    return out;
  }
  switch (w.source) {
    case swarm::WallErrorSource::history:
      return tr("± from past windows");
    case swarm::WallErrorSource::parts:
      return tr("± from its parts");
    case swarm::WallErrorSource::none: break;
  }
  return tr("no ± yet");
}

/// P and T over the plots' averaging window, with their standard errors.
void wall_rows(const swarm::WallEstimate& w) {
  char value[160], help[2400];
  if (w.intervals == 0) {
    row("P", tr("waiting for samples"), tr("Wall pressure, once the first samples arrive."));
    return;
  }
  format_estimate(value, sizeof value, w.mean.P, shown_wall_error(w.mean.P, w.P_stderr, w.source));
  // Each tooltip one whole text, the window's length and samples put into it.
  std::snprintf(help, sizeof help,
                tr("P = Σ |Δpᵣ| / (4π R² t) over the last %.4g of time (%d samples; the plots' "
                   "'average over', 0: the whole run). ±: the standard error of that window's "
                   "mean (see 'P, T over')."),
                w.window, w.intervals);
  row("P", value, translator().numbers(help).c_str());
  if (w.mean.hits > 0)
    format_estimate(value, sizeof value, w.mean.T, shown_wall_error(w.mean.T, w.T_stderr, w.source));
  else
    // True whether none has hit yet or the swarm has drawn in from the wall since ("yet" was
    // read after a shrinking swarm's last hit long ago).
    std::snprintf(value, sizeof value, tr("no wall hit in the last %.4g: the swarm stays inside"),
                  w.window);
  std::snprintf(help, sizeof help,
                tr("T = half the mean kinetic energy of the particles hitting the wall (k_B = 1) "
                   "over the last %.4g of time (%d samples; the plots' 'average over', 0: the "
                   "whole run). ±: the standard error of that window's mean (see 'P, T over')."),
                w.window, w.intervals);
  row("T", value, translator().numbers(help).c_str());
  char words[120];
  std::snprintf(value, sizeof value, tr("last %.4g; %s"), w.window,
                error_source_words(w, words, sizeof words));
  // The two tooltips share their start, each one whole text for a translator.
  if (w.source == swarm::WallErrorSource::history)
    std::snprintf(help, sizeof help,
                  tr("The averaging window of P and T: the plots' 'average over' (Wall P, T "
                     "tab), or the whole run when it is 0.\n\n± is how much the mean of a "
                     "window this long varies, measured from every window of the same length "
                     "in the run's recent past at this wall: here the last %.4g of time."),
                  w.history);
  else
    std::snprintf(help, sizeof help,
                  tr("The averaging window of P and T: the plots' 'average over' (Wall P, T "
                     "tab), or the whole run when it is 0.\n\n± is how much the mean of a "
                     "window this long varies, measured from every window of the same length "
                     "in the run's recent past at this wall, once it holds %.0f windows' "
                     "worth. Until then (and for the whole run) ± comes from the window's own "
                     "quarters and sixteenths, carried on to its length by how their spread "
                     "shrinks: regular motion (each particle hits the wall at steady "
                     "intervals) makes a long window's mean vary less than its parts suggest. "
                     "With fewer than %d samples in the window there is no ± yet rather than a "
                     "wrong one."),
                  swarm::kWallHistoryWindows, int(swarm::kWallPartsIntervals));
  if (w.source != swarm::WallErrorSource::history) {
    const std::size_t used = std::strlen(help);
    std::snprintf(help + used, sizeof help - used, "\n\n%s",
                  printed(tr("A ± from the parts as large as P or T itself says nothing yet, so "
                             "it is not shown until it is smaller than the value or %.0f "
                             "windows of history give it."),
                          swarm::kWallHistoryWindows)
                      .c_str());
  }
  // What the ± is about, the same for both sources.
  const std::size_t used = std::strlen(help);
  std::snprintf(help + used, sizeof help - used, "\n\n%s",
                tr("This ± is about this run: how far its window's mean may lie from what this "
                   "run would give if it went on for ever. Runs from other seeds differ by more "
                   "(their energies differ: 3 to 17 times more at long windows); for that "
                   "spread, and a mean over seeds, run an ensemble (docs/command-line.md, 'Ensembles: "
                   "numbers with error bars')."));
  row(tr("P, T over"), value, translator().numbers(help).c_str());
}

/// A warning while the read-outs' window is not yet in equilibrium by the virial balance
/// (swarm/measure/virial_balance.h), where the balance applies; nothing once it holds.
void virial_row(const std::optional<swarm::VirialBalance>& b, const swarm::WallEstimate& w) {
  if (!b || b->holds) return;
  char value[160], help[1200];
  std::snprintf(value, sizeof value, tr("not in equilibrium yet: the virial balance is off by %.2g %%"),
                100 * std::abs(b->relative()));
  std::snprintf(help, sizeof help,
                tr("The virial balance: G = Σ mᵢ rᵢ·vᵢ (about the container's centre) changes as "
                   "dG/dt = 2 KE − 2 U − 3 P V (U: the springs' energy), so over the window "
                   "mean(3PV) − mean(2KE − 2U) = −ΔG / Δt. In equilibrium G only fluctuates "
                   "and the two means agree within their statistical error. Over the last %.4g "
                   "of time they differ by %.3g ± %.2g (3PV = %.4g): the swarm still remembers "
                   "its start, so this window's P is not yet the equilibrium's. Wait, or "
                   "average over a later stretch."),
                w.window, b->imbalance, b->error, b->wall);
  row(tr("equilibrium"), value, translator().numbers(help).c_str());
}

}  // namespace

void draw_readouts(AppState& state) {
  if (!ImGui::CollapsingHeader(tr_id("Read-outs"), ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (draw_hidden_by_lesson(state, LessonHidden::readouts)) return;
  // The O(N) diagnostics below only run while the section is open.
  const swarm::System& s = state.run->system();
  const double M = swarm::total_mass(s);
  const double k = swarm::stiffness(s);
  const swarm::Regime regime = swarm::regime_of(k);
  const double rate = swarm::omega_of(k);
  const swarm::EnergyParts energy = state.run->primary().energy_now();
  const double E = energy.kinetic + energy.potential;  // with gravity's potential
  const double p = swarm::total_momentum(s).norm();
  const double L = swarm::angular_momentum_cm(s).norm();

  char value[96];
  rows().clear();
  std::snprintf(value, sizeof value, "%zu", s.particles.size());
  row("N", value, tr("Number of particles."));
  std::snprintf(value, sizeof value, "%.5g", M);
  row("M", value,
      tr("M = \u03a3 m\u1d62, the total mass. Every particle feels one spring "
         "k\u1d62 = J M m\u1d62 to the centre of mass."));
  if (regime == swarm::Regime::attractive) {
    std::snprintf(value, sizeof value, "%.5g", rate);
    row("\u03c9", value,
        tr("\u03c9 = \u221a(J M): the one angular frequency of every particle "
           "about the centre of mass (J > 0)."));
    std::snprintf(value, sizeof value, "%.5g", swarm::period_of(k));
    row(tr("period"), value,
        tr("2\u03c0 / \u03c9 = 2\u03c0 / \u221a(J M): every orbit closes after "
           "this time, whatever its size and mass."));
  } else if (regime == swarm::Regime::repulsive) {
    std::snprintf(value, sizeof value, "%.5g", rate);
    row("\u03a9", value,
        tr("\u03a9 = \u221a(\u2212J M) (J < 0): distances from the centre of mass "
           "grow as e^(\u03a9t); no period."));
  } else {
    row("\u03c9", "0", tr("J = 0: no force, every particle moves in a straight line."));
  }
  std::snprintf(value, sizeof value, "%.6g", E);
  row("E", value,
      tr("E = \u03a3 \u00bd m\u1d62 v\u1d62\u00b2 + \u00bd J M \u03a3 m\u1d62 "
         "|r\u1d62 \u2212 R|\u00b2: kinetic plus the springs' potential energy (eq. 13), "
         "and \u2212\u03a3 m\u1d62 g\u00b7r\u1d62 under gravity. "
         "Conserved by the exact solution and by elastic wall hits; drag and an inelastic "
         "floor take energy out (Gravity, floor, drag panel)."));
  std::snprintf(value, sizeof value, "%+.2e",
                swarm::relative_energy_change(state.run->primary().samples().front(), E));
  row("\u0394E/|E\u2080|", value,
      tr("Relative change of the energy since t = 0 (over KE\u2080 + |PE\u2080| when "
         "E\u2080 = 0). Euler's grows, Euler-Cromer's wobbles. The analytic method's orbits "
         "are exact but for rounding, yet E = KE + PE is a difference: for J < 0 both grow as "
         "e^(2\u03a9t) while E stays put, so their rounding (10\u207b\u00b9\u2076 of KE + |PE|) "
         "shows as a \u0394E of percents once \u03a9t passes about 17. Walls stop the growth."));
  std::snprintf(value, sizeof value, "%.5g", p);
  row("|p|", value,
      tr("p = \u03a3 m\u1d62 v\u1d62 = M V: constant for an isolated system; wall "
         "hits exchange momentum with the container."));
  std::snprintf(value, sizeof value, "%.5g", L);
  row("|L|", value,
      tr("L = \u03a3 m\u1d62 (r\u1d62 \u2212 R) \u00d7 (v\u1d62 \u2212 V) about the "
         "centre of mass: conserved by the central springs, changed by wall hits "
         "only through the moving centre of mass."));
  if (const auto R = state.run->primary().engine().container_radius()) {
    std::snprintf(value, sizeof value, "%.4g   V = %.4g", *R, swarm::sphere_volume(*R));
    row("R", value, tr("Container radius and volume V = 4/3 \u03c0 R\u00b3."));
    wall_rows(state.instruments.wall);
    virial_row(state.instruments.virial, state.instruments.wall);
    std::snprintf(value, sizeof value, "%.4g", swarm::kinetic_temperature(s));
    row(tr("T kinetic"), value,
        tr("T kinetic = (2/3) KE / N in the centre of mass's frame (k_B = 1), now. The wall's "
           "T equals it only while the speeds follow the Maxwell distribution: with J = 0 and "
           "a still wall every particle keeps its speed, so a start that is not Maxwellian "
           "never becomes one, and the two differ. A hot wall or hard spheres make the speeds "
           "Maxwellian (Projects tab: the speeds against the Maxwellian)."));
    std::snprintf(value, sizeof value, "%.4g", hit_rate(*state.run, state.plots.average_window));
    row(tr("hits/time"), value,
        tr("Wall hits per unit of simulated time, over the plots' averaging "
           "window. P = \u03a3 |\u0394p\u1d63| / (4\u03c0 R\u00b2 t)."));
  }
  if (state.stats.idle)
    std::snprintf(value, sizeof value, "%s", tr("idle"));
  else
    std::snprintf(value, sizeof value, "%.0f  (%.1f ms)", 1000.0 / state.stats.frame_ms,
                  state.stats.frame_ms);
  row("FPS", value,
      tr("Frames per second and the time of one frame. Paused and still, the app draws only "
         "when something changes, to spare the battery."));
  std::snprintf(value, sizeof value, "%.1f + %.1f ms", state.stats.simulation_ms,
                state.stats.scene_ms);
  row(tr("step + draw"), value,
      tr("Time per frame spent advancing the simulation, and preparing the "
         "particles for drawing (colours, sizes, upload)."));
  lay_out("readouts");
}

}  // namespace swarmlab
