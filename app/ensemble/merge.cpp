#include "ensemble/merge.h"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "ensemble/dt_check.h"
#include "files/text_file.h"
#include "report/csv_field.h"
#include "report/ensemble_figures.h"
#include "report/provenance.h"
#include "swarm/measure/confidence.h"
#include "swarm/measure/fit.h"
#include "swarm/preset/ensemble_seed.h"
#include "swarm/preset/printable_text.h"

namespace swarmlab::ensemble {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

/// A statistic of finite values that is not finite itself: a sum passed the largest double
/// (six runs with P = 1.7e308). JSON would write it as null; the merge stops with this instead.
struct Overflow {
  std::string message;
};

/// Throws Overflow naming `quantity` unless every number of m is finite.
void require_finite(const swarm::MeanInterval& m, const std::string& quantity) {
  const bool finite = std::isfinite(m.mean) && std::isfinite(m.sd) && std::isfinite(m.se) &&
                      (!m.lo || (std::isfinite(*m.lo) && std::isfinite(*m.hi)));
  if (!finite)
    throw Overflow{quantity + ": the mean, spread or interval of " + std::to_string(m.n) +
                   " runs' values is beyond the range of a double (about 1.8e308); no report "
                   "written"};
}

json interval_json(const swarm::MeanInterval& m, const std::string& quantity) {
  require_finite(m, quantity);
  json j = {{"mean", m.mean}, {"sd", m.sd}, {"se", m.se}};
  j["ci95"] = m.lo ? json::array({*m.lo, *m.hi}) : json(nullptr);
  return j;
}

/// The pointwise mean and 95 % interval of runs' series of one length.
struct Band {
  std::vector<double> x;
  std::vector<std::vector<double>> values;  // per point, one per run
  /// name: the band's quantity in a message ("bands.time.P").
  json to_json(const std::string& name) const {
    json mean = json::array(), lo = json::array(), hi = json::array();
    for (std::size_t i = 0; i < values.size(); ++i) {
      std::vector<double> v;
      for (double x : values[i])
        if (std::isfinite(x)) v.push_back(x);
      const swarm::MeanInterval m = swarm::mean_interval(v);
      if (!v.empty()) require_finite(m, name + " at point " + std::to_string(i));
      if (v.empty()) {
        mean.push_back(nullptr), lo.push_back(nullptr), hi.push_back(nullptr);
        continue;
      }
      mean.push_back(m.mean);
      lo.push_back(m.lo ? json(*m.lo) : json(nullptr));
      hi.push_back(m.hi ? json(*m.hi) : json(nullptr));
    }
    return {{"mean", mean}, {"lo", lo}, {"hi", hi}};
  }
};

/// The exponent of a power law fitted to the runs' mean stage values, for the runs picked. A
/// stage's mean is over the runs that have the value there (a stage without hits has no T);
/// a stage none of them has is left out of the fit (as 0: fit_power_law skips it).
double pooled_exponent(const std::vector<std::vector<double>>& x_runs,
                       const std::vector<std::vector<double>>& y_runs,
                       const std::vector<std::size_t>& pick) {
  const std::size_t stages = x_runs.front().size();
  std::vector<double> x(stages, 0.0), y(stages, 0.0), nx(stages, 0.0), ny(stages, 0.0);
  for (std::size_t r : pick)
    for (std::size_t s = 0; s < stages; ++s) {
      if (std::isfinite(x_runs[r][s])) x[s] += x_runs[r][s], nx[s] += 1;
      if (std::isfinite(y_runs[r][s])) y[s] += y_runs[r][s], ny[s] += 1;
    }
  for (std::size_t s = 0; s < stages; ++s) {
    x[s] = nx[s] > 0 ? x[s] / nx[s] : 0.0;
    y[s] = ny[s] > 0 ? y[s] / ny[s] : 0.0;
  }
  const swarm::PowerLawFit f = swarm::fit_power_law(x, y);
  return f.valid ? f.slope : NAN;
}

/// A name from a file, as the terminal may show it.
std::string shown(const std::string& text) { return swarm::printable(text, 200); }

std::string format_interval(const json& q) {
  char buf[160];
  if (q["ci95"].is_array())
    std::snprintf(buf, sizeof buf, "%13.6g  [%.6g, %.6g]", q["mean"].get<double>(),
                  q["ci95"][0].get<double>(), q["ci95"][1].get<double>());
  else
    std::snprintf(buf, sizeof buf, "%13.6g  (one run: no interval)", q["mean"].get<double>());
  return buf;
}

}  // namespace

RunScan scan_runs(const std::string& dir, const EnsemblePlan& plan,
                  const std::function<void(const RunRecord&)>& each) {
  RunScan scan;
  std::error_code ec;
  const long runs = plan.runs();
  // The folder is listed once: the work follows the files that are there, whatever number of
  // runs the plan claims. Files that no run of this plan writes are named.
  std::vector<long> present;
  for (const auto& entry : fs::directory_iterator(dir + "/runs", ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() < 6 || name.substr(name.size() - 5) != ".json") continue;
    const std::string stem = name.substr(0, name.size() - 5);
    const bool numeric = !stem.empty() && stem.find_first_not_of("0123456789") == std::string::npos &&
                         stem.size() < 12 && (stem == "0" || stem[0] != '0');
    if (!numeric || std::stol(stem) >= runs)
      scan.mixed += (scan.mixed.empty() ? "" : "; ") + ("runs/" + shown(name)) +
                    ": not a run of this plan (runs 0 to " + std::to_string(runs - 1) + ")";
    else
      present.push_back(std::stol(stem));
  }
  std::sort(present.begin(), present.end());
  for (long k = 0, next = 0; k < runs; ++k)
    if (next < long(present.size()) && present[std::size_t(next)] == k)
      ++next;
    else
      scan.missing.push_back(k);
  for (const long k : present) {
    const TextFile file = read_regular_file(run_path(dir, k));
    if (!file.error.empty()) {
      scan.corrupted.push_back({k, file.error});
      continue;
    }
    const RecordRead read = parse_record(file.text);
    if (!read.record) {
      scan.corrupted.push_back({k, read.error});
      continue;
    }
    const RunRecord& r = *read.record;
    const std::string& hash = plan.points[std::size_t(plan.point_of(k))].preset_hash;
    std::string why;
    if (r.id.preset_hash != hash)
      why = "a run of another preset (hash " + shown(r.id.preset_hash) + ", the plan's " + hash + ")";
    else if (r.id.version != plan.version)
      why = "made by swarmlab " + shown(r.id.version) + ", the plan's is " + shown(plan.version);
    else if (r.id.index != k)
      why = "holds run " + std::to_string(r.id.index);
    else if (r.id.seed != swarm::run_seed(plan.seed, std::uint64_t(plan.seed_index_of(k))))
      why = "started from seed " + std::to_string(r.id.seed) + ", not the plan's for this run";
    else if (r.id.perturbation != plan.perturbation)
      why = "perturbed by " + std::to_string(r.id.perturbation) + ", not the plan's " +
            std::to_string(plan.perturbation);
    if (!why.empty()) {
      scan.mixed += (scan.mixed.empty() ? "" : "; ") + ("runs/" + std::to_string(k) + ".json: " + why);
      continue;
    }
    scan.done.push_back(k);
    if (!r.failure.empty()) {
      scan.failed.push_back({k, r.failure});
      continue;
    }
    if (each) each(r);
  }
  return scan;
}

namespace {

/// What one point's report needs, gathered run by run: nothing grows with a run's length.
struct PointRuns {
  std::vector<long> indices;
  std::vector<std::uint64_t> seeds;
  std::map<std::string, std::vector<double>> values;  // one per run, NAN where a run lacks it
  std::map<std::string, std::vector<double>> errors;  // within-run se of P and T
  std::vector<double> starts;
  Band P_t, T_t, T_kinetic_t;
  std::vector<std::vector<double>> stage_V, stage_P, stage_T, stage_T_kinetic;
  bool bands_agree = true;

  void add(const RunRecord& r) {
    const std::size_t n = indices.size();
    indices.push_back(r.id.index);
    seeds.push_back(r.id.seed);
    starts.push_back(r.equilibration_start);
    for (auto& [name, v] : values) v.push_back(NAN);
    for (const auto& [name, v] : r.values) {
      auto& column = values[name];
      column.resize(n + 1, NAN);
      column[n] = v.value;
      if (v.se) {
        auto& e = errors[name];
        e.resize(n + 1, NAN);
        e[n] = *v.se;
      }
    }
    if (n == 0) {
      P_t.x = T_t.x = T_kinetic_t.x = r.t;
      P_t.values.assign(r.t.size(), {});
      T_t.values.assign(r.t.size(), {});
      T_kinetic_t.values.assign(r.t.size(), {});
    }
    if (r.t.size() != P_t.x.size()) bands_agree = false;
    for (std::size_t i = 0; bands_agree && i < r.t.size(); ++i) {
      P_t.values[i].push_back(r.P[i]);
      T_t.values[i].push_back(r.T[i]);
      T_kinetic_t.values[i].push_back(r.T_kinetic[i]);
    }
    stage_V.push_back(r.stage_V);
    stage_P.push_back(r.stage_P);
    stage_T.push_back(r.stage_T);
    stage_T_kinetic.push_back(r.stage_T_kinetic);
  }
};

/// Per quantity: values, mean, sd, se, ci95, and the rest (see merge.h); the table's rows.
json point_quantities(const PointRuns& p, double relative_half_width, std::string& table) {
  json quantities = json::object();
  char line[320];
  for (const auto& [name, column] : p.values) {
    std::vector<double> v;
    for (double x : column)
      if (std::isfinite(x)) v.push_back(x);
    const swarm::MeanInterval m = swarm::mean_interval(v);
    json q = interval_json(m, name);
    q["values"] = column;
    q["runs"] = v.size();
    if (m.lo && m.mean != 0)
      q["runs_for_half_width"] = {
          {"relative", relative_half_width},
          {"runs", swarm::runs_for_half_width(m.sd, relative_half_width * std::abs(m.mean))}};
    double within = NAN;
    if (const auto e = p.errors.find(name); e != p.errors.end()) {
      double sum = 0;
      std::size_t count = 0;
      for (double se : e->second)
        if (std::isfinite(se)) sum += se * se, ++count;
      if (count > 0) {
        within = std::sqrt(sum / double(count));
        if (!std::isfinite(within))
          throw Overflow{name + ": the runs' within-run errors, squared and summed, pass the "
                                "largest double; no report written"};
        q["within_se"] = within;
        // sd over runs against the rms within-run error: near 1 when the error bars are honest.
        if (within > 0 && m.lo) {
          if (!std::isfinite(m.sd / within))
            throw Overflow{name + ": the spread over runs divided by the within-run error "
                                  "passes the largest double; no report written"};
          q["spread_ratio"] = m.sd / within;
        }
      }
    }
    const std::string fit_prefix = "fit.";
    if (name.compare(0, fit_prefix.size(), fit_prefix) == 0 && p.stage_V.front().size() >= 3) {
      const std::string kind = name.substr(fit_prefix.size());  // P_V, T_V or P_T
      const auto& x = kind == "P_T" ? p.stage_T : p.stage_V;
      const auto& y = kind == "T_V" ? p.stage_T : p.stage_P;
      bool same_stages = true;
      for (std::size_t r = 0; r < x.size(); ++r)
        same_stages = same_stages && x[r].size() == x[0].size() && y[r].size() == x[0].size();
      if (same_stages) {
        const auto b = swarm::bca_interval(x.size(), [&](const std::vector<std::size_t>& pick) {
          return pooled_exponent(x, y, pick);
        });
        if (b) {
          q["mean_of_run_fits"] = interval_json(m, name);
          q["mean"] = b->estimate;
          q["ci95"] = {b->lo, b->hi};
          q["interval"] = "BCa bootstrap over whole runs, the fit to the runs' mean stages";
        }
      }
    }
    char within_text[32] = "", ratio_text[32] = "";
    if (std::isfinite(within)) std::snprintf(within_text, sizeof within_text, "%11.4g", within);
    if (q.contains("spread_ratio"))
      std::snprintf(ratio_text, sizeof ratio_text, "%7.2f", q["spread_ratio"].get<double>());
    std::snprintf(line, sizeof line, "%-14s %5zu %s %11.4g %11s %7s\n", shown(name).c_str(), v.size(),
                  format_interval(q).c_str(), m.sd, within_text, ratio_text);
    table += line;
    quantities[name] = q;
  }
  return quantities;
}

/// Whether the point's runs were in equilibrium, by the virial balance (virial_balance.h):
/// which runs are too short to claim it (their own balance fails within their own error), and
/// whether the runs' mean imbalance is distinguishable from 0 (the ensemble's intervals are
/// sqrt(runs) narrower than a run's, so a memory of the start that one run's error hides can
/// still lie outside the ensemble's interval). Empty where the balance does not apply.
json point_equilibrium(const PointRuns& p, std::string& table) {
  const auto holds = p.values.find("virial.holds");
  const auto relative = p.values.find("virial.relative_imbalance");
  if (holds == p.values.end() || relative == p.values.end()) return json();
  json too_short = json::array();
  std::vector<double> offsets;
  double worst = 0;
  for (std::size_t i = 0; i < p.indices.size(); ++i) {
    const double x = relative->second[i];
    if (!std::isfinite(x)) continue;
    offsets.push_back(x);
    if (holds->second[i] == 0) {
      too_short.push_back({{"index", p.indices[i]}, {"relative_imbalance", x}});
      if (std::abs(x) > std::abs(worst)) worst = x;
    }
  }
  const swarm::MeanInterval m = swarm::mean_interval(offsets);
  const bool ensemble_balances = !m.lo || (*m.lo <= 0 && 0 <= *m.hi);
  json out = {{"judged_by", "the virial balance: mean(3PV) - mean(2KE - 2U) = -(G(t1) - G(t0)) / "
                            "(t1 - t0) over each run's averaging window"},
              {"runs_judged", offsets.size()},
              {"runs_too_short", too_short},
              {"relative_imbalance", interval_json(m, "virial.relative_imbalance")},
              {"ensemble_balances", ensemble_balances}};
  char line[400];
  if (!too_short.empty()) {
    std::snprintf(line, sizeof line,
                  "equilibrium: %zu of %zu runs too short to claim it (the virial balance is off "
                  "by up to %.2g %% of 3PV, beyond their errors)\n",
                  too_short.size(), offsets.size(), 100 * worst);
    table += line;
  }
  if (!ensemble_balances) {
    std::snprintf(line, sizeof line,
                  "equilibrium: not shown at this ensemble's precision: the runs' mean virial "
                  "imbalance is %.2g %% of 3PV [%.2g, %.2g] (95 %%), so P's interval carries the "
                  "runs' memory of their start; run longer\n",
                  100 * m.mean, 100 * *m.lo, 100 * *m.hi);
    table += line;
  }
  out["message"] = too_short.empty() && ensemble_balances
                       ? "in equilibrium: the virial balance holds in every run and over the runs"
                       : "too short to claim equilibrium: see runs_too_short and relative_imbalance";
  return out;
}

json point_bands(const PointRuns& p) {
  json bands = json::object();
  if (p.bands_agree && !p.P_t.x.empty())
    bands["time"] = {{"t", p.P_t.x},
                     {"P", p.P_t.to_json("bands.time.P")},
                     {"T", p.T_t.to_json("bands.time.T")},
                     {"T_kinetic", p.T_kinetic_t.to_json("bands.time.T_kinetic")}};
  if (!p.stage_V.front().empty()) {
    Band sP, sT, sTk;
    sP.x = p.stage_V.front();
    sP.values.assign(sP.x.size(), {});
    sT.values.assign(sP.x.size(), {});
    sTk.values.assign(sP.x.size(), {});
    bool agree = true;
    for (std::size_t r = 0; r < p.stage_V.size(); ++r) {
      if (p.stage_P[r].size() != sP.x.size()) agree = false;
      for (std::size_t s = 0; agree && s < sP.x.size(); ++s)
        sP.values[s].push_back(p.stage_P[r][s]), sT.values[s].push_back(p.stage_T[r][s]),
            sTk.values[s].push_back(p.stage_T_kinetic[r][s]);
    }
    if (agree)
      bands["stages"] = {{"V", sP.x},
                         {"P", sP.to_json("bands.stages.P")},
                         {"T", sT.to_json("bands.stages.T")},
                         {"T_kinetic", sTk.to_json("bands.stages.T_kinetic")}};
  }
  return bands;
}

std::vector<long> of_point(const std::vector<long>& runs, const EnsemblePlan& plan, long point) {
  std::vector<long> out;
  for (long i : runs)
    if (plan.point_of(i) == point) out.push_back(i);
  return out;
}

}  // namespace

namespace {

MergeReport merge_runs(const std::string& dir, double relative_half_width) {
  MergeReport out;
  const TextFile file = read_regular_file(plan_path(dir));
  if (file.missing) {
    out.error = plan_path(dir) +
                ": missing: not an ensemble folder (swarmlab plan or swarmlab ensemble makes one)";
    return out;
  }
  if (!file.error.empty()) {
    out.error = plan_path(dir) + ": " + file.error;
    return out;
  }
  const PlanRead read = parse_plan(file.text);
  if (!read.plan) {
    out.error = plan_path(dir) + ": " + read.error;
    return out;
  }
  const EnsemblePlan& plan = *read.plan;
  std::vector<PointRuns> points(plan.points.size());
  std::size_t merged = 0;
  const RunScan scan = scan_runs(dir, plan, [&](const RunRecord& r) {
    points[std::size_t(plan.point_of(r.id.index))].add(r);
    ++merged;
  });
  if (!scan.mixed.empty()) {
    out.error = "runs of different presets, versions or plans cannot be merged as one: " + scan.mixed;
    return out;
  }
  if (merged == 0) {
    out.error = dir + ": no run has finished yet (" + std::to_string(scan.missing.size()) +
                " missing, " + std::to_string(scan.corrupted.size()) + " corrupted, " +
                std::to_string(scan.failed.size()) + " failed)";
    return out;
  }
  json corrupted = json::array(), failed = json::array();
  for (const auto& [k, why] : scan.corrupted) corrupted.push_back({{"index", k}, {"error", why}});
  for (const auto& [k, why] : scan.failed) failed.push_back({{"index", k}, {"failure", why}});
  json report = {{"format", report::kEnsembleReportFormat},
                 {"swarmlab", plan.version},
                 {"seed", plan.seed},
                 {"seeds", plan.seeds},
                 {"planned", plan.runs()},
                 {"runs", merged},
                 {"confidence", 0.95},
                 {"missing", scan.missing},
                 {"corrupted", corrupted},
                 {"failed", failed}};
  // What made the merge; each run's own provenance stays in its record.
  const report::Provenance made_by =
      report::provenance_now({std::nullopt, plan.seed, plan.seeds});
  report["provenance"] = report::provenance_json(made_by);
  char line[320];
  std::snprintf(line, sizeof line, "%zu of %ld runs merged (%zu missing, %zu corrupted, %zu failed)\n",
                merged, plan.runs(), scan.missing.size(), scan.corrupted.size(), scan.failed.size());
  out.table = line;
  std::snprintf(line, sizeof line, "%-14s %5s %13s  %-29s %11s %11s %7s\n", "quantity", "runs",
                "mean", "95 % interval", "sd", "within se", "ratio");
  const std::string header = line;

  // The per-run table: the point's values, then every quantity any run has.
  std::set<std::string> names, keys;
  for (const PointRuns& p : points)
    for (const auto& [name, column] : p.values) names.insert(name);
  for (const PlanPoint& pp : plan.points) {
    const json values = json::parse(pp.values);
    for (const auto& [key, v] : values.items()) keys.insert(key);
  }
  // Keys and names come from files (plan.json, the records): text fields, formula-safe.
  out.csv = report::csv_comment_lines(report::provenance_lines(made_by)) +
            report::csv_text("index") + "," + report::csv_text("seed");
  for (const std::string& key : keys) out.csv += "," + report::csv_text(key);
  for (const std::string& name : names) out.csv += "," + report::csv_text(name);
  out.csv += "\n";

  json point_reports = json::array();
  for (std::size_t p = 0; p < points.size(); ++p) {
    const PointRuns& runs = points[p];
    const json values = json::parse(plan.points[p].values);
    out.table += "\n";
    if (plan.points.size() > 1)
      out.table += "point " + std::to_string(p) + ": " + shown(values.dump()) + "\n";
    json r = {{"values", values},
              {"preset_hash", plan.points[p].preset_hash},
              {"runs", runs.indices.size()},
              {"missing", of_point(scan.missing, plan, long(p))}};
    if (runs.indices.empty()) {
      out.table += "no run finished\n";
      point_reports.push_back(r);
      continue;
    }
    out.table += header;
    r["equilibration_start"] =
        interval_json(swarm::mean_interval(runs.starts), "equilibration_start");
    r["quantities"] = point_quantities(runs, relative_half_width, out.table);
    if (json e = point_equilibrium(runs, out.table); !e.is_null()) r["equilibrium"] = e;
    r["bands"] = point_bands(runs);
    point_reports.push_back(r);
    for (std::size_t i = 0; i < runs.indices.size(); ++i) {
      out.csv += report::csv_number_text(std::to_string(runs.indices[i])) + "," +
                 report::csv_number_text(std::to_string(runs.seeds[i]));
      for (const std::string& key : keys) {
        // A swept value: a JSON number is a number; text (a method's name) is text.
        const json v = values.contains(key) ? values[key] : json();
        out.csv += "," + (v.is_number()   ? report::csv_number_text(v.dump())
                          : v.is_string() ? report::csv_text(v.get<std::string>())
                          : v.is_null()   ? report::csv_text("")
                                          : report::csv_text(v.dump()));
      }
      for (const std::string& name : names) {
        const auto c = runs.values.find(name);
        const bool has = c != runs.values.end() && std::isfinite(c->second[i]);
        out.csv += "," + (has ? report::csv_number(c->second[i]) : report::csv_text(""));
      }
      out.csv += "\n";
    }
  }
  if (points.size() == 1) {
    // A plain ensemble: its one point's numbers at the top level.
    const json& only = point_reports[0];
    report["preset_hash"] = only["preset_hash"];
    for (const char* key : {"equilibration_start", "quantities", "equilibrium", "bands"})
      if (only.contains(key)) report[key] = only[key];
    // The same seeds at dt / 2, when `ensemble --dt-check` ran them: the time step's systematic.
    const DtCheck check = dt_check(dir, plan, only.value("quantities", json::object()));
    if (!check.error.empty()) {
      out.error = check.error;
      return out;
    }
    if (!check.report.is_null()) {
      report["dt_check"] = check.report;
      out.table += "\n" + check.table;
    }
  } else {
    report["points"] = point_reports;
  }
  out.json = report.dump(1) + "\n";
  return out;
}

}  // namespace

MergeReport merge_ensemble(const std::string& dir, double relative_half_width) {
  try {
    return merge_runs(dir, relative_half_width);
  } catch (const Overflow& overflow) {
    MergeReport out;
    out.error = overflow.message;
    return out;
  }
}

}  // namespace swarmlab::ensemble
