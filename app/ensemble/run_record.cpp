#include "ensemble/run_record.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <type_traits>

#include "files/sha256.h"
#include "swarm/measure/wall_time_average.h"
#include "swarm/preset/printable_text.h"

namespace swarmlab::ensemble {
namespace {

using json = nlohmann::json;

void put(RunRecord& r, const std::string& name, double value, std::optional<double> se = {}) {
  if (std::isfinite(value)) r.values[name] = {value, se};
}

/// The mean T kinetic of the samples that end intervals [first, last): interval i runs from
/// sample i to sample i + 1. A plain mean: samples are evenly spaced but for a shorter last one.
double mean_T_kinetic(const std::vector<swarm::Sample>& samples, std::size_t first,
                      std::size_t last) {
  double sum = 0;
  for (std::size_t i = first; i < last; ++i) sum += samples[i + 1].T_kinetic;
  return sum / double(last - first);
}

/// The wall intervals in at most kSeriesPoints stretches, each read as one meter would.
void fill_series(RunRecord& r, const std::vector<swarm::Sample>& samples) {
  const std::vector<swarm::WallInterval> intervals = swarm::wall_intervals(samples);
  const std::size_t n = intervals.size();
  const std::size_t points = std::min(n, kSeriesPoints);
  for (std::size_t k = 0; k < points; ++k) {
    const std::size_t first = n * k / points, last = n * (k + 1) / points;
    const swarm::WallReading w = swarm::wall_average(intervals, first, last);
    r.t.push_back(intervals[last - 1].t_end);
    r.P.push_back(w.P);
    r.T.push_back(w.hits > 0 ? w.T : NAN);  // no hits: no temperature (null in the file)
    r.R.push_back(samples[last].R);
    r.T_kinetic.push_back(mean_T_kinetic(samples, first, last));
  }
}

/// The virial balance over the averaging window (virial_balance.h), as "virial.*" values.
void put_virial_balance(RunRecord& r, const swarm::VirialBalance& b) {
  put(r, "virial.3PV", b.wall);
  put(r, "virial.2KE-2U", b.kinetic);
  put(r, "virial.G_start", b.G_start);
  put(r, "virial.G_end", b.G_end);
  put(r, "virial.imbalance", b.imbalance, b.error);
  put(r, "virial.residual", b.residual);
  put(r, "virial.relative_imbalance", b.relative());
  put(r, "virial.holds", b.holds ? 1.0 : 0.0);
}

/// A number at j[key]; `where` prefixes the key in the message ("values.P.").
template <class T>
bool read_number(const json& j, const char* key, T& out, std::string& error,
                 const std::string& where = "") {
  const auto it = j.find(key);
  const bool whole = std::is_integral<T>::value;
  if (it == j.end() || !it->is_number() || (whole && !it->is_number_integer())) {
    error = where + key + (whole ? ": missing or not a whole number" : ": missing or not a number");
    return false;
  }
  out = it->get<T>();
  return true;
}

bool read_array(const json& j, const char* key, std::vector<double>& out, std::string& error,
                const std::string& where) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_array()) {
    error = where + key + ": missing or not an array";
    return false;
  }
  for (const json& x : *it) {
    if (x.is_null()) {  // a point without a value (a stretch without hits has no T)
      out.push_back(NAN);
      continue;
    }
    if (!x.is_number()) {
      error = where + key + ": holds something other than a number";
      return false;
    }
    out.push_back(x.get<double>());
  }
  return true;
}

std::string canonical_number(double x) {
  if (!std::isfinite(x)) return "null";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string canonical_text_item(const std::string& s) { return std::to_string(s.size()) + ":" + s; }

std::string canonical_list(const char* name, const std::vector<double>& xs) {
  std::string line = std::string(name) + " " + std::to_string(xs.size());
  for (double x : xs) line += " " + canonical_number(x);
  return line + "\n";
}

}  // namespace

RunRecord record_of(const RunIdentity& id, swarm::Run& run) {
  RunRecord r;
  r.id = id;
  r.made_by = report::provenance_now({id.seed});
  r.failure = run.failure();
  const swarm::RunSummary s = run.summary();
  put(r, "energy_drift", s.energy_drift);
  put(r, "wall_hits", double(s.wall_hits));
  const std::vector<swarm::Sample>& samples = run.samples();
  if (run.plan().engine.exchanges_energy()) {
    put(r, "work", s.books.wall_work);
    put(r, "heat", s.books.wall_heat);
    put(r, "KE_start", samples.front().KE);
    put(r, "KE_end", samples.back().KE);
  }
  if (run.plan().engine.container_radius && run.stages().empty()) {
    const bool judged = swarm::virial_balance_applies(run.plan().engine);
    const swarm::WallTimeAverages a = swarm::wall_time_averages(
        swarm::wall_intervals(samples),
        judged ? swarm::virial_intervals(samples) : std::vector<swarm::VirialInterval>{});
    r.equilibration_start = a.start;
    if (a.virial) put_virial_balance(r, *a.virial);
    // The errors as the read-outs give them for a window without history before it: from the
    // window's own parts (thermometry.h, wall_estimate), about this run's long-run value.
    // Blocking overstated regular motion's 3.5x. A window too short for its parts gives none:
    // the value goes without one rather than with a wrong one.
    const std::vector<swarm::WallInterval> all = swarm::wall_intervals(samples);
    const swarm::WallEstimate e =
        swarm::wall_estimate({all.end() - a.intervals, all.end()}, 0);
    if (a.P) put(r, "P", a.P->mean, e.P_stderr);
    if (a.T) put(r, "T", a.T->mean, e.T_stderr);
    if (a.intervals > 0)  // the window is the last a.intervals of the samples.size() - 1
      put(r, "T_kinetic", mean_T_kinetic(samples, samples.size() - 1 - std::size_t(a.intervals),
                                         samples.size() - 1));
  }
  if (samples.size() > 1) fill_series(r, samples);
  for (std::size_t k = 0; k < run.stages().size(); ++k) {
    const swarm::Stage& st = run.stages()[k];
    const std::string stage = "stage" + std::to_string(k + 1);
    // A stage without hits has a pressure (0) but no temperature.
    const double T = st.hits > 0 ? st.T : NAN;
    put(r, stage + ".P", st.P);
    put(r, stage + ".T", T);
    r.stage_V.push_back(st.V);
    r.stage_P.push_back(st.P);
    r.stage_T.push_back(T);
    r.stage_T_kinetic.push_back(st.T_kinetic);
  }
  if (!run.stages().empty()) {
    const swarm::StageFits f = run.fits();
    const std::pair<const char*, const swarm::PowerLawFit*> fits[] = {
        {"P_V", &f.P_V}, {"T_V", &f.T_V}, {"P_T", &f.P_T}};
    for (const auto& [name, fit] : fits)
      if (fit->valid) {
        put(r, std::string("fit.") + name, fit->slope);
        put(r, std::string("r2.") + name, fit->r_squared);
      }
  }
  return r;
}

std::string canonical_text(const RunRecord& r) {
  std::string out = std::string(kRunFormat) + " " + std::to_string(kRunFormatVersion) + "\n";
  out += "swarmlab " + canonical_text_item(r.id.version) + "\n";
  out += "preset_hash " + canonical_text_item(r.id.preset_hash) + "\n";
  out += "index " + std::to_string(r.id.index) + "\n";
  out += "seed " + std::to_string(r.id.seed) + "\n";
  out += "perturbation " + canonical_number(r.id.perturbation) + "\n";
  out += "failure " + canonical_text_item(r.failure) + "\n";
  out += "equilibration_start " + canonical_number(r.equilibration_start) + "\n";
  const report::Provenance& p = r.made_by;
  out += "provenance " + canonical_text_item(p.version) + " " + canonical_text_item(p.commit) +
         " " + (p.clean ? (*p.clean ? "true" : "false") : "null") + " " +
         canonical_text_item(p.compiler) + " " + canonical_text_item(p.os) + " " +
         canonical_text_item(p.machine) + " " + canonical_text_item(p.date) + "\n";
  out += "provenance.seeds " + (p.seeds.seed ? std::to_string(*p.seeds.seed) : "-") + " " +
         (p.seeds.base ? std::to_string(*p.seeds.base) : "-") + " " +
         std::to_string(p.seeds.runs) + "\n";
  for (const auto& [name, v] : r.values)
    out += "value " + canonical_text_item(name) + " " + canonical_number(v.value) + " " +
           (v.se ? canonical_number(*v.se) : std::string("-")) + "\n";
  out += canonical_list("series.t", r.t) + canonical_list("series.P", r.P) +
         canonical_list("series.T", r.T) + canonical_list("series.R", r.R) +
         canonical_list("series.T_kinetic", r.T_kinetic);
  out += canonical_list("stages.V", r.stage_V) + canonical_list("stages.P", r.stage_P) +
         canonical_list("stages.T", r.stage_T) +
         canonical_list("stages.T_kinetic", r.stage_T_kinetic);
  return out;
}

std::string record_digest(const RunRecord& r) { return "sha256:" + sha256_hex(canonical_text(r)); }

std::string record_json(const RunRecord& r) {
  json values = json::object();
  for (const auto& [name, v] : r.values) {
    json x = {{"value", v.value}};
    if (v.se) x["se"] = *v.se;
    values[name] = x;
  }
  json j = {{"format", kRunFormat},
            {"format_version", kRunFormatVersion},
            {"swarmlab", r.id.version},
            {"preset_hash", r.id.preset_hash},
            {"index", r.id.index},
            {"seed", r.id.seed},
            {"perturbation", r.id.perturbation},
            {"failure", r.failure},
            {"equilibration_start", r.equilibration_start},
            {"provenance", report::provenance_json(r.made_by)},
            {"values", values},
            {"series", {{"t", r.t}, {"P", r.P}, {"T", r.T}, {"R", r.R}, {"T_kinetic", r.T_kinetic}}},
            {"stages",
             {{"V", r.stage_V}, {"P", r.stage_P}, {"T", r.stage_T}, {"T_kinetic", r.stage_T_kinetic}}},
            {"digest", record_digest(r)}};
  return j.dump() + "\n";
}

RecordRead parse_record(const std::string& text) {
  RecordRead out;
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    out.error = "not a complete JSON object (cut short or corrupted)";
    return out;
  }
  if (j.value("format", std::string()) != kRunFormat) {
    out.error = std::string("format: not \"") + kRunFormat + "\"";
    return out;
  }
  RunRecord r;
  std::string& e = out.error;
  int format_version = 0;
  if (!read_number(j, "format_version", format_version, e)) return out;
  if (format_version != kRunFormatVersion) {
    e = "format_version: " + std::to_string(format_version) + ", this swarmlab reads " +
        std::to_string(kRunFormatVersion);
    return out;
  }
  if (!j.contains("swarmlab") || !j["swarmlab"].is_string() || !j.contains("preset_hash") ||
      !j["preset_hash"].is_string() || !j.contains("failure") || !j["failure"].is_string()) {
    e = "swarmlab, preset_hash, failure: missing or not text";
    return out;
  }
  r.id.version = j["swarmlab"];
  r.id.preset_hash = j["preset_hash"];
  r.failure = j["failure"];
  if (!j.contains("seed") || !j["seed"].is_number_unsigned()) {
    e = "seed: missing or not a whole number >= 0";
    return out;
  }
  r.id.seed = j["seed"].get<std::uint64_t>();
  if (!read_number(j, "index", r.id.index, e) || !read_number(j, "perturbation", r.id.perturbation, e) ||
      !read_number(j, "equilibration_start", r.equilibration_start, e))
    return out;
  const auto made_by = j.find("provenance");
  const std::optional<report::Provenance> p =
      report::provenance_from_json(made_by == j.end() ? json() : *made_by, e);
  if (!p) return out;
  r.made_by = *p;
  const auto values = j.find("values");
  if (values == j.end() || !values->is_object()) {
    e = "values: missing or not an object";
    return out;
  }
  for (const auto& [name, v] : values->items()) {
    RunValue x;
    // The name is the file's: shown escaped, so a message stays one line of plain text.
    const std::string where = "values." + swarm::printable(name) + ".";
    if (!v.is_object()) {
      e = "values." + swarm::printable(name) + ": not an object";
      return out;
    }
    if (!read_number(v, "value", x.value, e, where)) return out;
    if (v.contains("se")) {
      double se = 0;
      if (!read_number(v, "se", se, e, where)) return out;
      x.se = se;
    }
    r.values[name] = x;
  }
  const auto series = j.find("series");
  const auto stages = j.find("stages");
  if (series == j.end() || !series->is_object() || stages == j.end() || !stages->is_object()) {
    e = "series, stages: missing or not objects";
    return out;
  }
  if (!read_array(*series, "t", r.t, e, "series.") || !read_array(*series, "P", r.P, e, "series.") ||
      !read_array(*series, "T", r.T, e, "series.") || !read_array(*series, "R", r.R, e, "series.") ||
      !read_array(*stages, "V", r.stage_V, e, "stages.") ||
      !read_array(*stages, "P", r.stage_P, e, "stages.") ||
      !read_array(*stages, "T", r.stage_T, e, "stages.") ||
      !read_array(*series, "T_kinetic", r.T_kinetic, e, "series.") ||
      !read_array(*stages, "T_kinetic", r.stage_T_kinetic, e, "stages."))
    return out;
  if (r.P.size() != r.t.size() || r.T.size() != r.t.size() || r.R.size() != r.t.size() ||
      r.T_kinetic.size() != r.t.size() || r.stage_P.size() != r.stage_V.size() ||
      r.stage_T.size() != r.stage_V.size() || r.stage_T_kinetic.size() != r.stage_V.size()) {
    e = "series, stages: arrays of different lengths";
    return out;
  }
  const auto digest = j.find("digest");
  if (digest == j.end() || !digest->is_string()) {
    e = "digest: missing or not text";
    return out;
  }
  if (*digest != record_digest(r)) {
    e = "digest: does not match the record's contents (edited by hand or damaged)";
    return out;
  }
  out.record = std::move(r);
  return out;
}

}  // namespace swarmlab::ensemble
