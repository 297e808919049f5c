#include "report/ensemble_figures.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace swarmlab::report {
namespace {

using json = nlohmann::json;

std::vector<double> numbers(const json& a) {
  std::vector<double> out;
  for (const json& x : a) out.push_back(x.is_number() ? x.get<double>() : NAN);
  return out;
}

/// The mean as a line and the 95 % interval as two thin lines of the same colour, leaving out
/// the points without an interval (one run). The interval is named in the legend by a
/// panel's first band only (`name_interval`): the thin lines of every colour mean the same.
void add_band(Panel& panel, const std::vector<double>& x, const json& band, const std::string& name,
              int colour, bool points, bool name_interval = true) {
  const std::vector<double> mean = numbers(band.at("mean")), lo = numbers(band.at("lo")),
                            hi = numbers(band.at("hi"));
  Series m{name, {}, {}, points ? Mark::line_and_points : Mark::line, colour};
  Series l{name_interval ? "95 % interval over runs" : "", {}, {}, Mark::line, colour};
  Series h{"", {}, {}, Mark::line, colour};
  l.thin = h.thin = true;
  for (std::size_t i = 0; i < x.size() && i < mean.size(); ++i) {
    if (!std::isfinite(mean[i])) continue;
    m.x.push_back(x[i]);
    m.y.push_back(mean[i]);
    if (i < lo.size() && std::isfinite(lo[i]) && std::isfinite(hi[i])) {
      l.x.push_back(x[i]);
      l.y.push_back(lo[i]);
      h.x.push_back(x[i]);
      h.y.push_back(hi[i]);
    }
  }
  panel.series.push_back(std::move(m));
  if (!l.x.empty()) {
    panel.series.push_back(std::move(l));
    panel.series.push_back(std::move(h));
  }
}

/// The figures of one set of bands (a plain ensemble's, or one sweep point's).
void add_band_figures(std::vector<NamedFigure>& out, const json& bands, long runs,
                      const std::string& point, const std::string& prefix) {
  const std::string subtitle = (point.empty() ? "" : point + "; ") + std::to_string(runs) +
                               " runs; lines: the mean over runs, thin lines: its 95 % interval";
  if (bands.contains("time")) {
    const json& b = bands.at("time");
    const std::vector<double> t = numbers(b.at("t"));
    Figure f{"Wall pressure and temperature over time, ensemble", subtitle, {}, true};
    Panel P{{"time t", "time"}, {"pressure P", "", false, true}};
    add_band(P, t, b.at("P"), "P", 0, false);
    Panel T{{"time t", "time"}, {"temperature T", "energy", false, true}};
    add_band(T, t, b.at("T"), "T at the wall", 1, false);
    // Reports merged before run records carried T kinetic (format 4) have none.
    if (b.contains("T_kinetic")) add_band(T, t, b.at("T_kinetic"), "T kinetic, (2/3) KE/N", 2, false, false);
    f.panels = {P, T};
    out.push_back({prefix + "ensemble-time", f});
  }
  if (bands.contains("stages")) {
    const json& b = bands.at("stages");
    const std::vector<double> V = numbers(b.at("V"));
    Figure f{"Stage pressure and temperature against volume, ensemble", subtitle, {}, true};
    Panel P{{"volume V", "length³", true}, {"pressure P", "", true}};
    add_band(P, V, b.at("P"), "P", 0, true);
    Panel T{{"volume V", "length³", true}, {"temperature T", "energy", true}};
    add_band(T, V, b.at("T"), "T at the wall", 1, true);
    if (b.contains("T_kinetic")) add_band(T, V, b.at("T_kinetic"), "T kinetic, (2/3) KE/N", 2, true, false);
    f.panels = {P, T};
    out.push_back({prefix + "ensemble-stages", f});
  }
}

}  // namespace

EnsembleFigures ensemble_figures(const std::string& report_text) {
  EnsembleFigures out;
  const json r = json::parse(report_text, nullptr, false);
  if (r.is_discarded() || !r.is_object() || r.value("format", "") != kEnsembleReportFormat) {
    out.error = "not an ensemble report (swarmlab merge writes one)";
    return out;
  }
  try {
    if (r.contains("points")) {
      // A sweep: each point's bands, named by its number, its values in the subtitle.
      const json& points = r.at("points");
      for (std::size_t p = 0; p < points.size(); ++p)
        if (points[p].contains("bands"))
          add_band_figures(out.figures, points[p].at("bands"), points[p].at("runs").get<long>(),
                           "point " + std::to_string(p) + " " + points[p].at("values").dump(),
                           "point" + std::to_string(p) + "-");
    } else if (r.contains("bands")) {
      add_band_figures(out.figures, r.at("bands"), r.at("runs").get<long>(), "", "");
    }
  } catch (const json::exception& e) {
    out.figures.clear();
    out.error = std::string("bands: ") + e.what();
    return out;
  }
  if (out.figures.empty()) out.error = "the report has no bands to draw (no run had a wall series)";
  return out;
}

}  // namespace swarmlab::report
