#include "report/run_record.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "files/text_file.h"
#include "swarm/preset/strict_json.h"

namespace swarmlab::report {
namespace {

using json = nlohmann::json;

/// A number of a RESULT.json: runs written before non-finite numbers stopped a run wrote them
/// as null, which reads back as NaN (a gap in the figures) rather than refusing the file.
double number(const json& v) { return v.is_null() ? std::nan("") : v.get<double>(); }

/// T_kinetic, which files written before it was recorded lack: NaN there, and the figures
/// leave the series out (report.cpp's recorded).
double kinetic_temperature(const json& x) {
  return x.contains("T_kinetic") ? number(x.at("T_kinetic")) : std::nan("");
}

swarm::RunSummary summary_from(const json& j) {
  swarm::RunSummary s;
  s.M = number(j.at("M")), s.omega = number(j.at("omega")), s.E0 = number(j.at("E0")),
  s.E_end = number(j.at("E_end"));
  s.energy_drift = number(j.at("energy_drift")), s.wall_hits = j.at("wall_hits"),
  s.steps = j.at("steps");
  s.t_end = number(j.at("t_end"));
  s.books.wall_work = number(j.at("work")), s.books.wall_heat = number(j.at("heat"));
  s.books.drag_loss = number(j.at("drag_loss"));
  s.floor_hits = j.at("floor_hits");
  return s;
}

/// The speeds are worth a figure where something drives them towards the Maxwellian.
bool checks_speeds(const swarm::Preset& p) { return p.wall_temperature || p.sphere_radius; }

}  // namespace

RunRecord record_of(const swarm::Preset& preset, swarm::SideBySide& runs) {
  swarm::Run& run = runs.primary();
  RunRecord r{preset, run.summary(), run.samples(), run.stages(), {}, {}};
  for (const auto& track : runs.tracks())
    r.comparisons.push_back({std::string(swarm::name_of(track.method)),
                             track.run->summary().energy_drift, track.samples});
  if (checks_speeds(preset)) r.final_speeds = swarm::check_speeds(run.engine().system());
  return r;
}

RecordRead read_result_file(const std::string& path) {
  std::string unreadable;
  const std::string text = read_text_file(path, unreadable, kResultFileLimit);
  if (!unreadable.empty()) return {std::nullopt, unreadable};
  try {
    const json j = json::parse(text);
    swarm::PresetParse parsed = swarm::parse_preset(j.at("preset").dump());
    if (!parsed.preset) return {std::nullopt, path + ": preset: " + parsed.error};
    RunRecord r;
    r.preset = *parsed.preset;
    r.summary = summary_from(j.at("summary"));
    for (const json& x : j.at("samples")) {
      swarm::Sample sample;
      sample.t = number(x.at("t")), sample.P = number(x.at("P")), sample.T = number(x.at("T"));
      sample.KE = number(x.at("KE")), sample.PE = number(x.at("PE")), sample.E = number(x.at("E"));
      sample.T_kinetic = kinetic_temperature(x);
      sample.hits = x.at("hits"), sample.R = number(x.at("R"));
      sample.books.wall_work = number(x.at("work")), sample.books.wall_heat = number(x.at("heat"));
      sample.books.drag_loss = number(x.at("drag_loss"));
      sample.cm_height = number(x.at("cm_height")), sample.size = number(x.at("size"));
      r.samples.push_back(sample);
    }
    for (const json& x : j.at("stages")) {
      swarm::Stage stage{number(x.at("R")), number(x.at("V")), number(x.at("P")),
                         number(x.at("T")), number(x.at("E")), x.at("hits")};
      stage.T_kinetic = kinetic_temperature(x);
      r.stages.push_back(stage);
    }
    if (j.contains("comparisons"))
      for (const json& c : j.at("comparisons")) {
        ComparisonTrack track{c.at("method"), number(c.at("summary").at("energy_drift")), {}};
        for (const json& x : c.at("samples"))
          track.samples.push_back(
              {number(x.at("t")), number(x.at("E")), number(x.at("position_error"))});
        r.comparisons.push_back(std::move(track));
      }
    if (checks_speeds(r.preset) && j.contains("final")) {
      swarm::System final_state;
      for (const json& x : j.at("final").at("particles"))
        final_state.particles.push_back(
            {number(x.at("m")),
             {number(x.at("r")[0]), number(x.at("r")[1]), number(x.at("r")[2])},
             {number(x.at("v")[0]), number(x.at("v")[1]), number(x.at("v")[2])}});
      r.final_speeds = swarm::check_speeds(final_state);
    }
    if (j.contains("provenance")) {
      std::string error;
      r.made_by = provenance_from_json(j.at("provenance"), error);
      if (!r.made_by) return {std::nullopt, path + ": " + error};
    }
    return {std::move(r), {}};
  } catch (const json::parse_error& e) {
    return {std::nullopt, path + ": not valid JSON at " + swarm::json_syntax_error(e, text)};
  } catch (const json::exception& e) {
    return {std::nullopt, path + ": not a RESULT.json from swarmlab run --out (" +
                              swarm::json_error_text(e) + ")"};
  }
}

}  // namespace swarmlab::report
