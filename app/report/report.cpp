#include "report/report.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <variant>

#include "plotting/decimate.h"
#include "report/walls_figures.h"
#include "swarm/measure/fit.h"
#include "swarm/physics/analytic.h"

namespace swarmlab::report {
namespace {

// Colours by quantity, so that a reader learns them once.
enum Colour { blue, orange, green, red, purple, brown, pink, grey };

// The paper normalises Fig. 4 by the mean over omega t > 6.
constexpr double kEquilibratedOmegaT = 6.0;
// Small explicit systems get their orbits drawn; a swarm would be a blur.
constexpr std::size_t kMaxOrbitsDrawn = 12;

std::string printed(const char* format, double a, double b = 0, double c = 0) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, format, a, b, c);
  return buffer;
}

Series series(std::string name, const std::vector<double>& x, const std::vector<double>& y,
              int colour, Mark mark = Mark::line) {
  const plotting::XY d = plotting::decimated(x, y, kMaxPointsPerSeries);
  Series s;
  s.name = std::move(name);
  s.x = d.x;
  s.y = d.y;
  s.colour = colour;
  s.mark = mark;
  return s;
}

/// Time in units of the oscillation, omega t, when the system has a rate; plain t otherwise.
struct TimeAxis {
  double omega;
  Axis axis() const { return omega > 0 ? Axis{"ωt", "rad"} : Axis{"time t", ""}; }
  std::vector<double> of(const std::vector<swarm::Sample>& samples) const {
    std::vector<double> t;
    for (const swarm::Sample& s : samples) t.push_back(omega > 0 ? omega * s.t : s.t);
    return t;
  }
};

template <class Row, class F>
std::vector<double> column(const std::vector<Row>& rows, F f) {
  std::vector<double> out;
  for (const Row& row : rows) out.push_back(f(row));
  return out;
}

/// Whether a record holds the kinetic temperature (RESULT.json files written before it was
/// recorded read it as NaN).
bool recorded(const std::vector<double>& values) {
  return std::any_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

// The two temperatures' legend entries: the wall's (from the hitters' kinetic energy, the
// paper's) is the gas's temperature only for a Maxwellian gas; the kinetic one always.
constexpr const char* kWallT = "T at the wall";
constexpr const char* kKineticT = "T kinetic, (2/3) KE/N";

/// The relative energy change as the run's summary defines it (swarm::relative_energy_change).
auto energy_change(const RunRecord& r) {
  const swarm::Sample first = r.samples.front();
  return [first](double E) { return swarm::relative_energy_change(first, E); };
}

NamedFigure energy_figure(const RunRecord& r, const TimeAxis& time) {
  const std::vector<double> t = time.of(r.samples);
  const auto change = energy_change(r);
  Panel energies{time.axis(), {"energy", "mass·length²/time²"}};
  energies.y.include_zero = true;  // room for the legend below or above the curves
  energies.series = {
      series("kinetic KE", t, column(r.samples, [](auto& s) { return s.KE; }), red),
      series("potential PE", t, column(r.samples, [](auto& s) { return s.PE; }), blue),
      series("total E", t, column(r.samples, [](auto& s) { return s.E; }), grey)};
  Panel drift{time.axis(), {"(E − E₀)/|E₀|", ""}};
  drift.height = 0.45;
  drift.zero_line = true;
  drift.series = {series("", t, column(r.samples, [&](auto& s) { return change(s.E); }), grey)};
  drift.note =
      printed("relative change of the total energy: %.2e at the end", r.summary.energy_drift);
  Figure f{"Energy over time", r.preset.name, {energies, drift}, true};
  return {"energy", f};
}

/// The samples that carry wall readings: the one at t = 0 covers no step.
std::vector<swarm::Sample> wall_samples(const RunRecord& r) {
  return {r.samples.begin() + 1, r.samples.end()};
}

/// Fig. 4: P and T at every sample of a fixed container, each over its mean once equilibrated.
NamedFigure equilibration_figure(const RunRecord& r, const TimeAxis& time) {
  const std::vector<swarm::Sample> samples = wall_samples(r);
  const std::vector<double> t = time.of(samples);
  // The paper's window, omega t > 6, when the run reaches well past it; else the later half.
  const bool paper_window = time.omega > 0 && t.back() > 2 * kEquilibratedOmegaT;
  const double start = paper_window ? kEquilibratedOmegaT : 0.5 * t.back();
  // Means and running means alike are wall averages (swarm::wall_average): P weighted by
  // time, T by wall hits, so intervals without hits do not pull T down.
  const std::vector<swarm::WallInterval> intervals = swarm::wall_intervals(r.samples);
  std::size_t first_equilibrated = 0;
  while (first_equilibrated < t.size() && t[first_equilibrated] <= start) ++first_equilibrated;
  const swarm::WallReading equilibrated =
      swarm::wall_average(intervals, first_equilibrated, intervals.size());
  const double P_mean = equilibrated.P > 0 ? equilibrated.P : 1;
  const double T_mean = equilibrated.T > 0 ? equilibrated.T : 1;
  const std::vector<double> P = column(samples, [&](auto& s) { return s.P / P_mean; });
  const std::vector<double> T = column(samples, [&](auto& s) { return s.T / T_mean; });
  const std::vector<double> T_kinetic =
      column(samples, [&](auto& s) { return s.T_kinetic / T_mean; });
  // Centred on each sample, 1% of the run wide.
  const double half_window = 0.005 * (samples.back().t - r.samples.front().t);
  const std::vector<swarm::WallReading> running =
      swarm::windowed_wall_averages(intervals, half_window, half_window);
  const std::vector<double> P_running =
      column(running, [&](const swarm::WallReading& w) { return w.P / P_mean; });
  const std::vector<double> T_running =
      column(running, [&](const swarm::WallReading& w) { return w.T / T_mean; });
  const std::string window_text = paper_window ? "ωt > 6" : "the later half";
  const std::string averaged = "running mean over 1% of the run";

  auto panel = [&](const char* name, const std::vector<double>& y,
                   const std::vector<double>& y_running, int colour) {
    Panel p{time.axis(), {std::string(name) + " / mean", ""}};
    p.height = 0.55;
    Series raw = series(std::string(name) + " per sample", t, y, colour);
    raw.thin = true;
    p.series = {raw, series(averaged, t, y_running, colour == blue ? purple : brown)};
    p.note = std::string(name) + " normalised by its mean over " + window_text +
             printed(" (%.4g)", name[0] == 'P' ? P_mean : T_mean);
    return p;
  };
  Panel temperature = panel(kWallT, T, T_running, orange);
  if (recorded(T_kinetic)) {
    // Over the wall's mean too, so that where the two differ the panel shows by how much.
    temperature.series.push_back(
        series(std::string(kKineticT) + ", over the same mean", t, T_kinetic, green));
    temperature.note += "; T kinetic over the same mean";
  }
  Figure f{"Wall pressure and temperature in a fixed container",
           r.preset.name,
           {panel("P", P, P_running, blue), temperature},
           true};
  return {"equilibration", f};
}

/// P, T and R of an expansion as sampled over time.
NamedFigure wall_history_figure(const RunRecord& r, const TimeAxis& time) {
  const std::vector<swarm::Sample> samples = wall_samples(r);
  const std::vector<double> t = time.of(samples);
  auto panel = [&](Axis y, std::vector<double> v, int colour, double height) {
    Panel p{time.axis(), std::move(y)};
    p.height = height;
    p.series = {series("", t, v, colour)};
    return p;
  };
  Panel temperature =
      panel({"temperature T", "energy"}, column(samples, [](auto& s) { return s.T; }), orange, 0.4);
  const std::vector<double> T_kinetic = column(samples, [](auto& s) { return s.T_kinetic; });
  if (recorded(T_kinetic)) {
    temperature.series.front().name = kWallT;
    temperature.series.push_back(series(kKineticT, t, T_kinetic, green));
  }
  Figure f{
      "Wall readings during the expansion",
      r.preset.name,
      {panel({"pressure P", "force/area"}, column(samples, [](auto& s) { return s.P; }), blue, 0.4),
       temperature,
       panel({"radius R", "length"}, column(samples, [](auto& s) { return s.R; }), grey, 0.3)},
      true};
  return {"wall-history", f};
}

struct StageColumn {
  const char* symbol;  ///< "V", "P", "T" (the wall's) or "Tk" (the kinetic T)
  Axis axis;
  std::vector<double> values;
  bool is_T() const { return std::string(symbol) == "T"; }
};

/// V, P, T and, where the record has it, T kinetic (stage_figure draws it beside T).
std::vector<StageColumn> stage_columns(const std::vector<swarm::Stage>& stages) {
  std::vector<double> V, P, T, T_kinetic;
  // A stage without a wall hit has no wall T (the record's 0 means "none"): a gap in the line
  // and "nan" in the CSV, never a point at T = 0. Its P of 0 is a measurement and stays.
  for (const swarm::Stage& s : stages)
    V.push_back(s.V), P.push_back(s.P),
        T.push_back(s.hits > 0 ? s.T : std::numeric_limits<double>::quiet_NaN()),
        T_kinetic.push_back(s.T_kinetic);
  std::vector<StageColumn> out = {{"V", {"volume V", "length³"}, V},
                                  {"P", {"pressure P", "force/area"}, P},
                                  {"T", {"temperature T", "energy"}, T}};
  if (recorded(T_kinetic)) out.push_back({"Tk", {"temperature T", "energy"}, T_kinetic});
  return out;
}

/// The kinetic T's column, when stage_columns found one.
const StageColumn* kinetic_column(const std::vector<StageColumn>& columns) {
  return columns.size() > 3 ? &columns[3] : nullptr;
}

/// (y, x) pairs of the paper's Figs. 2 and 3: T-V, P-V, P-T.
const std::pair<int, int> kStagePairs[] = {{2, 0}, {1, 0}, {1, 2}};

NamedFigure stage_figure(const RunRecord& r, const StageColumn& y, const StageColumn& x,
                         const StageColumn* kinetic) {
  Panel p{x.axis, y.axis};
  const std::string against = x.is_T() ? std::string(" against ") + kWallT : "";
  p.series = {
      series(std::string(y.is_T() ? kWallT : y.symbol) + against + " at the end of each stage",
             x.values, y.values, y.is_T() ? orange : blue, Mark::line_and_points)};
  if (kinetic && y.is_T())
    p.series.push_back(series(std::string(kKineticT) + ", over the same window", x.values,
                              kinetic->values, green, Mark::line_and_points));
  if (kinetic && x.is_T())
    p.series.push_back(series(std::string(y.symbol) + " against " + kKineticT, kinetic->values,
                              y.values, green, Mark::line_and_points));
  p.y.include_zero = true;
  p.note = std::to_string(r.stages.size()) + " stages; each value averaged over the last " +
           printed("%.0f%% of its stage", 100 * (1 - r.preset.expansion->thermalize_fraction));
  const std::string name = std::string("stages-") + y.symbol + "-" + x.symbol;
  return {name, Figure{std::string(y.symbol) + " against " + x.symbol, r.preset.name, {p}}};
}

/// "−0.639 ± 0.002": the exponent to the precision its standard error allows.
std::string with_uncertainty(double value, double stderr_value) {
  const int decimals =
      stderr_value > 0 ? std::clamp(1 - int(std::floor(std::log10(stderr_value))), 1, 6) : 3;
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f ± %.*f", decimals, value, decimals, stderr_value);
  std::string s = buffer;
  if (s[0] == '-') s = "−" + s.substr(1);  // a true minus sign, as on a printed page
  return s;
}

/// Appendix C: ln y against ln x with its least-squares line, and the residuals beneath.
NamedFigure loglog_figure(const RunRecord& r, const StageColumn& y, const StageColumn& x,
                          const StageColumn* kinetic) {
  const swarm::PowerLawFit fit = swarm::fit_power_law(x.values, y.values);
  std::vector<double> xs, ys;
  for (int i : fit.used)
    xs.push_back(x.values[std::size_t(i)]), ys.push_back(y.values[std::size_t(i)]);

  Axis x_axis = x.axis, y_axis = y.axis;
  x_axis.log = y_axis.log = true;
  Panel main{x_axis, y_axis};
  main.height = 0.8;
  const bool two_temperatures = kinetic && (y.is_T() || x.is_T());
  std::string points = "stages with P, T > 0";
  if (two_temperatures)
    points = (x.is_T() ? std::string(y.symbol) + " against " + kWallT : kWallT) + ", " + points;
  main.series = {series(points, xs, ys, y.is_T() ? orange : blue, Mark::points)};
  // The fit is the paper's, of the wall's T; the kinetic T is drawn beside it, not fitted.
  if (two_temperatures && y.is_T())
    main.series.push_back(series(std::string(kKineticT) + " (not fitted)", x.values,
                                 kinetic->values, green, Mark::points));
  if (two_temperatures && x.is_T())
    main.series.push_back(series(std::string(y.symbol) + " against " + kKineticT + " (not fitted)",
                                 kinetic->values, y.values, green, Mark::points));
  Panel residuals{x_axis, {"residual of ln " + std::string(y.symbol), ""}};
  residuals.height = 0.35;
  residuals.zero_line = true;
  if (fit.valid) {
    const auto [lo, hi] = std::minmax_element(xs.begin(), xs.end());
    std::vector<double> line_x = {*lo, *hi}, line_y;
    for (double v : line_x) line_y.push_back(std::exp(fit.intercept + fit.slope * std::log(v)));
    main.series.push_back(series(std::string("fit ") + y.symbol + " ∝ " + x.symbol + "^(" +
                                     with_uncertainty(fit.slope, fit.slope_stderr) + ")" +
                                     printed(",  R² = %.4f", fit.r_squared),
                                 line_x, line_y, grey));
    Series guide = series("", xs, fit.residuals, purple);
    guide.thin = true;
    residuals.series = {guide, series("", xs, fit.residuals, purple, Mark::points)};
    residuals.note = "ln " + std::string(y.symbol) + " − (a + b ln " + x.symbol +
                     "): a wave, not scatter, means no power law";
  }
  main.note = printed("least squares of ln y on ln x over %.0f of %.0f stages", double(xs.size()),
                      double(r.stages.size()));
  const std::string name = std::string("loglog-") + y.symbol + "-" + x.symbol;
  return {name, Figure{"log-log fit of " + std::string(y.symbol) + " against " + x.symbol,
                       r.preset.name,
                       {main, residuals},
                       true}};
}

/// Energy and position error of each method run side by side with the preset's own.
std::vector<NamedFigure> comparison_figures(const RunRecord& r, const TimeAxis& time) {
  const std::string primary(swarm::name_of(r.preset.method));
  const std::vector<double> t = time.of(r.samples);
  const auto change_of = energy_change(r);
  auto relative = [&](double E) { return std::abs(change_of(E)); };

  Panel energy{time.axis(), {"total energy E", "mass·length²/time²"}};
  Panel change{time.axis(), {"|E − E₀|/|E₀|", ""}};
  change.y.log = true;
  change.height = 0.6;
  change.note = "zero (exact conservation) cannot be drawn on a log axis and is left out";
  energy.series.push_back(series(primary, t, column(r.samples, [](auto& s) { return s.E; }), 0));
  // The upper panel's legend names the colours for both.
  change.series.push_back(
      series("", t, column(r.samples, [&](auto& s) { return relative(s.E); }), 0));

  Panel error{time.axis(), {"max |rᵢ − rᵢ(" + primary + ")|", "length"}};
  error.y.log = true;
  int colour = 1;
  for (const ComparisonTrack& track : r.comparisons) {
    std::vector<double> tc, E, dE, dr;
    for (const swarm::ComparisonSample& c : track.samples) {
      tc.push_back(time.omega > 0 ? time.omega * c.t : c.t);
      E.push_back(c.E), dE.push_back(relative(c.E)), dr.push_back(c.position_error);
    }
    energy.series.push_back(series(track.method, tc, E, colour));
    change.series.push_back(series("", tc, dE, colour));
    error.series.push_back(series(track.method + " against " + primary, tc, dr, colour));
    ++colour;
  }
  return {
      {"methods-energy", Figure{"Total energy by method", r.preset.name, {energy, change}, true}},
      {"methods-position-error",
       Figure{"Distance between the methods' orbits", r.preset.name, {error}}}};
}

bool has_drawable_orbits(const RunRecord& r) {
  const auto* list = std::get_if<std::vector<swarm::Particle>>(&r.preset.particles);
  // Gravity moves only the CM, so the orbits about it stay the paper's; drag and a floor do not.
  return list && list->size() <= kMaxOrbitsDrawn && !r.preset.container_radius && r.preset.J > 0 &&
         !r.preset.drag && !r.preset.floor;
}

/// Fig. 1 in motion: the exact orbits about the centre of mass over one period, projected on
/// the x-y plane (the plane of the paper's drawing), and the distance of each particle from
/// its start, which returns to zero for all of them at the same instant.
std::vector<NamedFigure> orbit_figures(const RunRecord& r) {
  const swarm::System initial = swarm::initial_system(r.preset);
  const swarm::AnalyticSolution exact(initial);
  const double period = exact.period();
  constexpr int kPointsPerPeriod = 400;

  Panel plane{{"x − X_cm", "length"}, {"y − Y_cm", "length"}};
  plane.equal_aspect = true;
  plane.note = printed("one period T = 2π/ω = %.4g, ω = √(JM) = %.4g; dots: positions at t = 0",
                       period, exact.omega());
  Panel distance{{"t / T", ""}, {"|rᵢ(t) − rᵢ(0)| in the CM frame", "length"}};
  for (std::size_t i = 0; i < initial.particles.size(); ++i) {
    std::vector<double> x, y, tau, d;
    const swarm::Vec3 r0 = initial.particles[i].r - exact.cm_position_at(initial.t);
    for (int k = 0; k <= 2 * kPointsPerPeriod; ++k) {
      const double t = initial.t + period * k / kPointsPerPeriod;
      const swarm::Vec3 rel = exact.particle_at(i, t).r - exact.cm_position_at(t);
      if (k <= kPointsPerPeriod) x.push_back(rel.x()), y.push_back(rel.y());
      tau.push_back(double(k) / kPointsPerPeriod);
      d.push_back((rel - r0).norm());
    }
    const std::string name = printed("m = %g", initial.particles[i].m);
    plane.series.push_back(series(name, x, y, int(i)));
    distance.series.push_back(series(name, tau, d, int(i)));
    plane.series.push_back(series("", {r0.x()}, {r0.y()}, int(i), Mark::points));
  }
  plane.series.push_back(series("centre of mass", {0.0}, {0.0}, grey, Mark::points));
  distance.note = "every particle is back where it started after each period";
  return {{"orbits",
           Figure{"Analytic orbits about the centre of mass", r.preset.name, {plane}, false, 700}},
          {"orbits-return", Figure{"One common period", r.preset.name, {distance}}}};
}

// [SECTION] Gravity, floor and drag (Appendix B)

/// The floor project's read-outs: the CM's height (each bounce kicks it back up) and the
/// swarm's size, the rms distance from the CM, over time.
NamedFigure floor_figure(const RunRecord& r, const TimeAxis& time) {
  const std::vector<double> t = time.of(r.samples);
  Panel height{time.axis(), {"height of the CM", "length"}};
  height.series = {series("CM height z", t, column(r.samples, [](auto& s) { return s.cm_height; }), blue)};
  if (r.preset.floor) {
    height.y.include_zero = r.preset.floor->z == 0;
    height.series.push_back(series("floor", {t.front(), t.back()},
                                   {r.preset.floor->z, r.preset.floor->z}, grey));
    height.note = printed("floor at z = %g, restitution %g", r.preset.floor->z,
                          r.preset.floor->restitution);
  }
  Panel size{time.axis(), {"swarm size", "length"}};
  size.height = 0.6;
  size.y.include_zero = true;
  size.series = {series("rms distance from the CM", t, column(r.samples, [](auto& s) { return s.size; }), green)};
  Figure f{"Centre-of-mass height and swarm size", r.preset.name, {height, size}, true};
  return {"floor", f};
}

/// The energy books: what the walls, the floor and drag put in or took out since t = 0, and
/// the balance E - E0 = work + heat - drag losses, whose residual should be rounding (exact
/// and analytic maps) or the method's own error (numerical methods).
NamedFigure energy_books_figure(const RunRecord& r, const TimeAxis& time) {
  const std::vector<double> t = time.of(r.samples);
  const double E0 = r.samples.front().E;
  Panel books{time.axis(), {"energy since t = 0", "mass·length²/time²"}};
  books.zero_line = true;
  // E - E0 last and dashed: when the books balance it lies on top of their sum.
  Series change = series("E − E₀", t, column(r.samples, [&](auto& s) { return s.E - E0; }), grey);
  change.dashed = true;
  books.series = {
      series("work by walls and floor", t, column(r.samples, [](auto& s) { return s.books.wall_work; }), blue),
      series("heat from the wall", t, column(r.samples, [](auto& s) { return s.books.wall_heat; }), orange),
      series("− drag losses", t, column(r.samples, [](auto& s) { return -s.books.drag_loss; }), red),
      change};
  Panel residual{time.axis(), {"(E − E₀) − books", "mass·length²/time²"}};
  residual.height = 0.45;
  residual.zero_line = true;
  residual.series = {series("", t, column(r.samples, [&](auto& s) { return s.E - E0 - s.books.net(); }), grey)};
  residual.note = "the books balance when this stays at zero (up to the method's error)";
  Figure f{"Energy books", r.preset.name, {books, residual}, true};
  return {"energy-books", f};
}

}  // namespace

std::vector<NamedFigure> run_figures(const RunRecord& r) {
  const TimeAxis time{r.summary.omega};
  std::vector<NamedFigure> out;
  if (r.samples.size() >= 2) out.push_back(energy_figure(r, time));
  if (r.preset.container_radius && r.samples.size() >= 2)
    out.push_back(r.preset.expansion ? wall_history_figure(r, time)
                                     : equilibration_figure(r, time));
  if (!r.stages.empty()) {
    const std::vector<StageColumn> columns = stage_columns(r.stages);
    for (const auto& [y, x] : kStagePairs)
      out.push_back(stage_figure(r, columns[std::size_t(y)], columns[std::size_t(x)],
                                 kinetic_column(columns)));
    for (const auto& [y, x] : kStagePairs)
      out.push_back(loglog_figure(r, columns[std::size_t(y)], columns[std::size_t(x)],
                                  kinetic_column(columns)));
  }
  if (!r.comparisons.empty())
    for (NamedFigure& f : comparison_figures(r, time)) out.push_back(std::move(f));
  if (has_drawable_orbits(r))
    for (NamedFigure& f : orbit_figures(r)) out.push_back(std::move(f));
  if ((r.preset.floor || r.preset.gravity || r.preset.drag) && r.samples.size() >= 2)
    out.push_back(floor_figure(r, time));
  if ((r.preset.floor || r.preset.drag) && r.samples.size() >= 2)
    out.push_back(energy_books_figure(r, time));
  if (auto pv = pv_loop_figure(r)) out.push_back(std::move(*pv));
  if (auto speeds = speed_histogram_figure(r)) out.push_back(std::move(*speeds));
  return out;
}

std::vector<NamedFigure> overlay_figures(const std::vector<RunRecord>& runs) {
  std::vector<NamedFigure> out;
  std::vector<const RunRecord*> expansions;
  for (const RunRecord& r : runs)
    if (!r.stages.empty()) expansions.push_back(&r);
  if (expansions.empty()) return out;
  for (const auto& [y, x] : kStagePairs) {
    Panel p;
    std::string symbols;
    for (std::size_t k = 0; k < expansions.size(); ++k) {
      const RunRecord& r = *expansions[k];
      const std::vector<StageColumn> columns = stage_columns(r.stages);
      const StageColumn &cy = columns[std::size_t(y)], &cx = columns[std::size_t(x)];
      p.x = cx.axis, p.y = cy.axis;
      p.y.include_zero = true;
      symbols = std::string(cy.symbol) + "-" + cx.symbol;
      const std::string run_name = r.preset.name + printed(" (τ = %g)", r.preset.expansion->tau);
      const bool has_T = cy.is_T() || cx.is_T();
      Series s = series(run_name + (has_T ? std::string(", ") + kWallT : ""), cx.values, cy.values,
                        int(k), Mark::line_and_points);
      s.dashed = k > 0;
      p.series.push_back(s);
      // The kinetic T in the run's colour, as points only.
      const StageColumn* kinetic = kinetic_column(columns);
      if (kinetic && has_T)
        p.series.push_back(series(run_name + ", " + kKineticT,
                                  cx.is_T() ? kinetic->values : cx.values,
                                  cy.is_T() ? kinetic->values : cy.values, int(k), Mark::points));
    }
    p.note = "each value averaged over the last part of its stage";
    out.push_back({"overlay-" + symbols, Figure{symbols.substr(0, 1) + " against " +
                                                    symbols.substr(2) + ", runs overlaid",
                                                "solid: " + expansions.front()->preset.name,
                                                {p}}});
  }
  return out;
}

}  // namespace swarmlab::report
