#include "cli/result_json.h"

#include <nlohmann/json.hpp>

#include "swarm/measure/speed_distribution.h"
#include "swarm/measure/wall_time_average.h"

namespace swarmlab {
namespace {

using json = nlohmann::json;

json fit_json(const swarm::PowerLawFit& f) {
  if (!f.valid) return nullptr;
  return {{"slope", f.slope},         {"slope_stderr", f.slope_stderr}, {"intercept", f.intercept},
          {"r_squared", f.r_squared}, {"residuals", f.residuals},       {"points_used", f.used}};
}

json vec(const swarm::Vec3& v) { return {v.x(), v.y(), v.z()}; }

/// The final speeds against the Maxwellian: T_kinetic = (2/3) KE / N in the CM frame, and
/// the p-value of the Kolmogorov-Smirnov test of the speeds against the Maxwellian at that T
/// (docs/physics.md, "Wall thermometry": the wall's T is the kinetic T only for a Maxwellian gas).
json speeds_json(const swarm::System& final_state) {
  const swarm::SpeedCheck c = swarm::check_speeds(final_state);
  return {{"T_kinetic", c.T},
          {"maxwellian_p", c.maxwellian_p},
          {"maxwellian_test",
           "Kolmogorov-Smirnov of the final speeds against the Maxwellian at T_kinetic "
           "(T estimated from the same speeds: conservative)"}};
}

/// The virial balance over the window wall_time_averages picks (swarm/measure/virial_balance.h):
/// whether the run's P is the equilibrium's, or the run is too short to claim it.
json virial_json(const swarm::Run& run) {
  if (!swarm::virial_balance_applies(run.plan().engine) || !run.stages().empty())
    return "not applicable: outside forces, a floor, a moving or hot wall, hard spheres, an "
           "expansion or no container add terms of their own";
  const auto& samples = run.samples();
  const swarm::WallTimeAverages a =
      swarm::wall_time_averages(swarm::wall_intervals(samples), swarm::virial_intervals(samples));
  if (!a.virial) return "too few samples";
  const swarm::VirialBalance& b = *a.virial;
  return {{"equilibration_start", a.start},
          {"from", b.start},
          {"to", b.end},
          {"3PV", b.wall},
          {"2KE-2U", b.kinetic},
          {"G_start", b.G_start},
          {"G_end", b.G_end},
          {"imbalance", b.imbalance},
          {"imbalance_se", b.error},
          {"residual", b.residual},
          {"relative_imbalance", b.relative()},
          {"holds", b.holds},
          {"verdict", b.holds ? "in equilibrium: the balance holds within 2 standard errors"
                              : "too short to claim equilibrium: P is off by relative_imbalance"}};
}

json summary_json(const swarm::RunSummary& s) {
  return {{"M", s.M},
          {"omega", s.omega},
          {"E0", s.E0},
          {"E_end", s.E_end},
          {"energy_drift", s.energy_drift},
          {"wall_hits", s.wall_hits},
          {"steps", s.steps},
          {"t_end", s.t_end},
          {"work", s.books.wall_work},
          {"heat", s.books.wall_heat},
          {"drag_loss", s.books.drag_loss},
          {"floor_hits", s.floor_hits}};
}

}  // namespace

std::string result_json(const swarm::Preset& preset, swarm::SideBySide& runs,
                        const report::Provenance& made_by) {
  swarm::Run& run = runs.primary();
  json j;
  j["provenance"] = report::provenance_json(made_by);
  j["preset"] = json::parse(swarm::preset_to_json(preset));
  j["summary"] = summary_json(run.summary());
  j["summary"].update(speeds_json(run.engine().system()));
  j["summary"]["virial"] = virial_json(run);
  json samples = json::array();
  for (const swarm::Sample& x : run.samples())
    samples.push_back({{"t", x.t},
                       {"P", x.P},
                       {"T", x.T},
                       {"KE", x.KE},
                       {"PE", x.PE},
                       {"E", x.E},
                       {"T_kinetic", x.T_kinetic},
                       {"hits", x.hits},
                       {"R", x.R},
                       {"work", x.books.wall_work},
                       {"heat", x.books.wall_heat},
                       {"drag_loss", x.books.drag_loss},
                       {"cm_height", x.cm_height},
                       {"size", x.size}});
  j["samples"] = samples;
  json stages = json::array();
  for (const swarm::Stage& x : run.stages())
    stages.push_back({{"R", x.R},
                      {"V", x.V},
                      {"P", x.P},
                      {"T", x.T},
                      {"T_kinetic", x.T_kinetic},
                      {"E", x.E},
                      {"hits", x.hits}});
  j["stages"] = stages;
  if (!run.stages().empty()) {
    const swarm::StageFits f = run.fits();
    j["fits"] = {{"P_V", fit_json(f.P_V)}, {"T_V", fit_json(f.T_V)}, {"P_T", fit_json(f.P_T)}};
  }
  if (!runs.tracks().empty()) {
    json comparisons = json::array();
    for (const auto& track : runs.tracks()) {
      json samples = json::array();
      for (const swarm::ComparisonSample& c : track.samples)
        samples.push_back({{"t", c.t}, {"E", c.E}, {"position_error", c.position_error}});
      comparisons.push_back({{"method", std::string(swarm::name_of(track.method))},
                             {"summary", summary_json(track.run->summary())},
                             {"samples", samples}});
    }
    j["comparisons"] = comparisons;
  }
  const swarm::System& sys = run.engine().system();
  json particles = json::array();
  for (const swarm::Particle& p : sys.particles)
    particles.push_back({{"m", p.m}, {"r", vec(p.r)}, {"v", vec(p.v)}});
  j["final"] = {{"t", sys.t}, {"particles", particles}};
  return j.dump(1) + "\n";
}

}  // namespace swarmlab
