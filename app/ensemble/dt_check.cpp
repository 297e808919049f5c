#include "ensemble/dt_check.h"

#include <cmath>
#include <cstdio>
#include <map>

#include "ensemble/merge.h"
#include "files/text_file.h"
#include "swarm/measure/confidence.h"

namespace swarmlab::ensemble {
namespace {

using json = nlohmann::json;

/// Each finished run's values by run index.
std::map<long, std::map<std::string, double>> finished_values(const std::string& dir,
                                                             const EnsemblePlan& plan,
                                                             std::string& mixed) {
  std::map<long, std::map<std::string, double>> out;
  const RunScan scan = scan_runs(dir, plan, [&](const RunRecord& r) {
    if (!r.failure.empty()) return;
    for (const auto& [name, v] : r.values) out[r.id.index][name] = v.value;
  });
  mixed = scan.mixed;
  return out;
}

/// "" when `half` is `plan` again at dt / 2, else what differs.
std::string not_the_same_runs(const std::string& dir, const EnsemblePlan& plan,
                              const EnsemblePlan& half) {
  if (plan.points.size() != 1) return "a dt check is of a plain ensemble, not a sweep";
  if (half.points.size() != 1 || half.seeds != plan.seeds || half.seed != plan.seed ||
      half.perturbation != plan.perturbation || half.version != plan.version)
    return "its plan is not this ensemble's seeds, master seed, perturbation and version";
  const TextFile text = read_regular_file(preset_path(dir, plan, 0));
  if (!text.error.empty()) return preset_path(dir, plan, 0) + ": " + text.error;
  const swarm::PresetParse p = swarm::parse_preset(text.text);
  if (!p.preset) return preset_path(dir, plan, 0) + ": " + p.error;
  if (preset_hash(with_half_dt(*p.preset)) != half.points[0].preset_hash)
    return "its preset is not this ensemble's at dt / 2";
  return {};
}

/// The terminal's line for one quantity: the shift, its interval, the bias at dt it implies
/// and the quantity's own half-width, each as a percentage of the quantity's mean at dt.
std::string table_line(const std::string& name, const json& d, double mean_at_dt) {
  auto percent = [&](double x) { return 100 * x / std::abs(mean_at_dt); };
  char line[400];
  std::snprintf(line, sizeof line,
                "dt check: %s moves by %+.3g %% [%+.3g, %+.3g] at dt / 2 (%zu pairs), a bias at "
                "dt of about %+.3g %%; its 95 %% interval (+-%.3g %%) is %s\n",
                name.c_str(), percent(d["shift"].get<double>()), percent(d["ci95"][0].get<double>()),
                percent(d["ci95"][1].get<double>()), d["pairs"].get<std::size_t>(),
                percent(d["bias_at_dt"].get<double>()), percent(d["half_width"].get<double>()),
                d["statistics_wider"].get<bool>()
                    ? "wider: the time step's bias is inside it"
                    : "narrower: the time step's bias is as large; halve dt or quote both");
  return line;
}

}  // namespace

swarm::Preset with_half_dt(const swarm::Preset& p) {
  swarm::Preset half = p;
  half.dt = p.dt / 2;
  if (p.sample_every) half.sample_every = 2 * *p.sample_every;
  return half;
}

DtCheck dt_check(const std::string& dir, const EnsemblePlan& plan, const json& quantities) {
  DtCheck out;
  const std::string half_dir = dir + "/" + kDtHalfFolder;
  const TextFile plan_text = read_regular_file(plan_path(half_dir));
  if (plan_text.missing) return out;
  const std::string where = half_dir + ": ";
  if (!plan_text.error.empty()) {
    out.error = plan_path(half_dir) + ": " + plan_text.error;
    return out;
  }
  const PlanRead half = parse_plan(plan_text.text);
  if (!half.plan) {
    out.error = plan_path(half_dir) + ": " + half.error;
    return out;
  }
  if (const std::string e = not_the_same_runs(dir, plan, *half.plan); !e.empty()) {
    out.error = where + e;
    return out;
  }
  std::string mixed;
  const auto at_dt = finished_values(dir, plan, mixed);
  const auto at_half = finished_values(half_dir, *half.plan, mixed);
  if (!mixed.empty()) {
    out.error = where + mixed;
    return out;
  }
  out.report = {{"runs_at_half_dt", at_half.size()},
                {"shift", "the mean over paired runs (the same seed) of the value at dt / 2 minus "
                          "the value at dt, with its Student-t 95 % interval"},
                {"quantities", json::object()}};
  for (const auto& [name, q] : quantities.items()) {
    std::vector<double> shifts;
    double sum = 0;
    for (const auto& [k, values] : at_dt) {
      const auto twin = at_half.find(k);
      if (twin == at_half.end()) continue;
      const auto a = values.find(name);
      const auto b = twin->second.find(name);
      if (a == values.end() || b == twin->second.end()) continue;
      shifts.push_back(b->second - a->second);
      sum += a->second;
    }
    const swarm::MeanInterval m = swarm::mean_interval(shifts);
    if (!m.lo || !std::isfinite(m.mean)) continue;
    const double mean_at_dt = sum / double(shifts.size());
    json d = {{"shift", m.mean}, {"ci95", {*m.lo, *m.hi}}, {"pairs", shifts.size()}};
    d["relative"] = mean_at_dt != 0 ? json(m.mean / mean_at_dt) : json();
    if (q.contains("ci95") && q["ci95"].is_array()) {
      const double half_width = (q["ci95"][1].get<double>() - q["ci95"][0].get<double>()) / 2;
      d["half_width"] = half_width;
      // Against the bias at dt, not the shift: a scheme of order p in dt has a bias at dt of
      // 2^p / (2^p - 1) times the shift, against it (Richardson). The paper's collision scheme
      // is first order, 2x; higher orders give less, so 2x never calls the interval wider while
      // the bias at dt could still reach past it.
      d["bias_at_dt"] = -2 * m.mean;
      d["statistics_wider"] = half_width > 2 * std::abs(m.mean);
    }
    const bool shown = name == "P" || name == "T" || name.compare(0, 4, "fit.") == 0;
    if (shown && mean_at_dt != 0 && d.contains("half_width"))
      out.table += table_line(name, d, mean_at_dt);
    out.report["quantities"][name] = d;
  }
  return out;
}

}  // namespace swarmlab::ensemble
