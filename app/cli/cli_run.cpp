#include <cmath>
#include <cstdio>
#include <new>
#include <stdexcept>

#include "cli/cli.h"
#include "cli/progress_bar.h"
#include "cli/result_json.h"
#include "ensemble/ensemble_member.h"
#include "ensemble/ensemble_plan.h"
#include "files/atomic_file.h"
#include "files/preset_file.h"
#include "files/text_file.h"
#include "lessons/lesson.h"
#include "report/plot_files.h"
#include "report/provenance.h"
#include "report/report.h"
#include "report/run_csv.h"
#include "swarm/measure/speed_distribution.h"
#include "swarm/preset/ensemble_seed.h"
#include "swarm/preset/printable_text.h"
#include "swarm/preset/resource_budget.h"
#include "swarm/run/side_by_side.h"

namespace swarmlab {
namespace {

/// "" when every number of the summaries is finite, else the first that is not.
std::string non_finite_summary(swarm::SideBySide& runs) {
  auto check = [](const swarm::RunSummary& s, const std::string& who) -> std::string {
    const std::pair<const char*, double> values[] = {{"M", s.M},
                                                     {"omega", s.omega},
                                                     {"E0", s.E0},
                                                     {"E_end", s.E_end},
                                                     {"energy_drift", s.energy_drift},
                                                     {"t_end", s.t_end}};
    for (const auto& [name, x] : values)
      if (!std::isfinite(x)) return who + "summary: " + name + " is not finite";
    return {};
  };
  std::string err = check(runs.primary().summary(), "");
  for (const auto& track : runs.tracks())
    if (err.empty())
      err = check(track.run->summary(), std::string(swarm::name_of(track.method)) + ": ");
  return err;
}

void print_table(const swarm::RunSummary& s, swarm::SideBySide& runs) {
  const swarm::Run& run = runs.primary();
  std::printf(
      "%-14s %.6g\n%-14s %.6g\n%-14s %.10g\n%-14s %.10g\n%-14s %.3e\n%-14s %lld\n"
      "%-14s %ld\n%-14s %.6g\n",
      "M", s.M, "omega", s.omega, "E0", s.E0, "E_end", s.E_end, "energy_drift", s.energy_drift,
      "wall_hits", (long long)s.wall_hits, "steps", s.steps, "t_end", s.t_end);
  // The kinetic T beside the wall's: they agree only for Maxwellian speeds (docs/physics.md,
  // "Wall thermometry"), which the KS test's p-value says.
  const swarm::SpeedCheck speeds = swarm::check_speeds(runs.primary().engine().system());
  std::printf("%-14s %.6g\n%-14s %.3g\n", "T_kinetic", speeds.T, "maxwellian_p", speeds.maxwellian_p);
  // Appendix B: the energy books and the floor, when energy comes or goes from outside.
  const swarm::EngineConfig& engine = run.plan().engine;
  const bool forced = engine.forces.any() || engine.floor;  // the CM's height and the size
  if (engine.exchanges_energy())
    std::printf("%-14s %.10g\n%-14s %.10g\n%-14s %.10g\n%-14s %.3e\n%-14s %lld\n", "work",
                s.books.wall_work, "heat", s.books.wall_heat, "drag_loss", s.books.drag_loss,
                "E_end-E0-books", s.E_end - s.E0 - s.books.net(), "floor_hits",
                (long long)s.floor_hits);
  if (!run.stages().empty()) {
    std::printf("\n%6s %12s %12s %12s %12s %14s\n", "stage", "R", "V", "P", "T", "E");
    for (std::size_t i = 0; i < run.stages().size(); ++i) {
      const swarm::Stage& st = run.stages()[i];
      std::printf("%6zu %12.5g %12.5g %12.5g %12.5g %14.8g\n", i, st.R, st.V, st.P, st.T, st.E);
    }
    const swarm::StageFits f = run.fits();
    auto line = [](const char* name, const swarm::PowerLawFit& fit) {
      if (fit.valid)
        std::printf("fit %-4s exponent %+.4f +- %.4f   R^2 = %.4f\n", name, fit.slope,
                    fit.slope_stderr, fit.r_squared);
      else
        std::printf("fit %-4s (fewer than 3 stages with P, T > 0)\n", name);
    };
    std::printf("\n");
    line("P-V", f.P_V);
    line("T-V", f.T_V);
    line("P-T", f.P_T);
  } else {
    const auto& samples = run.samples();
    const std::size_t rows = std::min<std::size_t>(samples.size(), 11);
    // Without a container there is no wall, so no pressure or temperature to show.
    const bool walled = run.plan().engine.container_radius.has_value();
    std::printf("\n%12s", "t");
    if (walled) std::printf(" %12s %12s", "P", "T");
    std::printf(" %14s %14s %14s", "KE", "PE", "E");
    if (forced) std::printf(" %12s %12s", "cm_height", "size");
    std::printf("\n");
    for (std::size_t r = 0; r < rows; ++r) {
      const swarm::Sample& x =
          samples[r * (samples.size() - 1) / std::max<std::size_t>(1, rows - 1)];
      std::printf("%12.5g", x.t);
      if (walled) std::printf(" %12.5g %12.5g", x.P, x.T);
      std::printf(" %14.8g %14.8g %14.10g", x.KE, x.PE, x.E);
      if (forced) std::printf(" %12.5g %12.5g", x.cm_height, x.size);
      std::printf("\n");
    }
  }
  for (const auto& track : runs.tracks()) {
    const swarm::RunSummary o = track.run->summary();
    std::printf("\nside by side: %-13s E_end %.10g  energy_drift %.3e  max |r - r_%s| %.3e\n",
                std::string(swarm::name_of(track.method)).c_str(), o.E_end, o.energy_drift,
                std::string(swarm::name_of(runs.primary().plan().engine.method)).c_str(),
                track.samples.back().position_error);
  }
}

}  // namespace

int run_command(const RunOptions& options) {
  const swarm::PresetParse parsed = read_preset_file(options.preset_path);
  if (!parsed.preset) {
    // A lesson where a preset belongs fails the preset's rules at its first key ("lesson:
    // unknown key"): say what the file is and what opens it instead.
    std::string unreadable;
    const std::string text = read_text_file(options.preset_path, unreadable);
    if (unreadable.empty() && looks_like_lesson(text))
      std::fprintf(stderr,
                   "error: %s: a lesson, not a preset: open it in the app (Open preset..., or drop "
                   "it on the window) or check it with swarmlab validate and swarmlab "
                   "check-lesson\n",
                   options.preset_path.c_str());
    else
      std::fprintf(stderr, "error: %s\n", parsed.error.c_str());
    return 1;
  }
  // Every output path is checked before the run: a device, a FIFO, a directory, a missing
  // folder or the same file twice is refused now, not after a long run.
  if (const std::string err = check_output_paths({options.out_path, options.csv_path, options.record_path});
      !err.empty()) {
    std::fprintf(stderr, "error: %s\n", err.c_str());
    return 1;
  }
  if (!options.plots_dir.empty()) {
    std::string err = options.png ? report::png_unavailable_reason() : "";
    if (err.empty()) err = report::prepare_plot_dir(options.plots_dir);
    if (!err.empty()) {
      std::fprintf(stderr, "error: %s\n", err.c_str());
      return 1;
    }
  }
  if (!options.preset_hash.empty() &&
      options.preset_hash != ensemble::preset_hash(*parsed.preset)) {
    std::fprintf(stderr,
                 "error: %s: --preset-hash: the preset has changed since the plan (its hash is "
                 "%s, the plan's %s)\n",
                 options.preset_path.c_str(), ensemble::preset_hash(*parsed.preset).c_str(),
                 options.preset_hash.c_str());
    return 1;
  }
  swarm::Preset preset = *parsed.preset;
  if (options.seed) {
    const swarm::SeededPreset seeded = swarm::with_seed(preset, *options.seed, options.perturb);
    if (!seeded.preset) {
      std::fprintf(stderr, "error: %s: %s\n", options.preset_path.c_str(), seeded.error.c_str());
      return 1;
    }
    preset = *seeded.preset;
  }
  // The files are built whole in memory before they are written: count them in the budget.
  const bool files =
      !options.out_path.empty() || !options.csv_path.empty() || !options.plots_dir.empty();
  if (const std::string err = swarm::resource_error(preset, swarm::ResourceLimits{}, files);
      !err.empty()) {
    std::fprintf(stderr, "error: %s: %s\n", options.preset_path.c_str(), err.c_str());
    return 1;
  }
  try {
    if (!options.record_path.empty()) {
      const std::string err = ensemble::run_member(
          preset,
          {options.run_index, *options.seed, ensemble::preset_hash(*parsed.preset),
           ensemble::program_version(), options.perturb},
          options.record_path, options.threads > 0 ? options.threads : swarm::default_threads());
      if (!err.empty()) {
        std::fprintf(stderr, "error: %s\n", err.c_str());
        return 1;
      }
      return 0;
    }
    swarm::RunPlan plan = swarm::run_plan(preset);
    if (options.threads > 0) plan.engine.threads = options.threads;
    swarm::SideBySide runs(swarm::initial_system(preset), plan, preset.compare);
    swarm::Run& run = runs.primary();
    ProgressBar bar("running", !options.quiet);
    runs.finish([&bar](double done) { bar.update(done); });
    bar.finish();
    std::string failure = runs.failure();
    if (failure.empty()) failure = non_finite_summary(runs);
    if (!failure.empty()) {
      std::fprintf(stderr, "error: %s: the run stopped: %s; nothing was written\n",
                   options.preset_path.c_str(), failure.c_str());
      return 1;
    }

    // All outputs are staged, then committed together: a failure leaves every old file as it
    // was, and Ctrl-C leaves no temporary behind.
    std::vector<report::NamedFigure> figures;
    if (!options.plots_dir.empty()) figures = report::run_figures(report::record_of(preset, runs));
    // One provenance for all of this run's files. A seed given on the command line is the
    // run's even for listed particles, which it perturbs.
    const report::Provenance made_by = report::provenance_now(
        options.seed ? report::Seeds{*options.seed} : report::seeds_of(preset));
    OutputFiles files;
    std::string err;
    if (!options.plots_dir.empty())
      err = report::stage_figures(files, options.plots_dir, figures, options.png,
                                  report::provenance_lines(made_by));
    if (err.empty() && !options.out_path.empty())
      err = files.stage(options.out_path, result_json(preset, runs, made_by));
    if (err.empty() && !options.csv_path.empty())
      err = files.stage(options.csv_path, report::samples_csv(run.samples()));
    if (err.empty()) err = files.commit();
    if (!err.empty()) {
      std::fprintf(stderr, "error: %s\n", err.c_str());
      return 1;
    }
    if (!options.quiet) {
      // A name is the preset author's text: escaped, so it cannot drive the terminal.
      std::printf("%s\n\n", preset.name.empty() ? options.preset_path.c_str()
                                                : swarm::printable(preset.name, 200).c_str());
      print_table(run.summary(), runs);
      if (!options.plots_dir.empty())
        std::printf("\nwrote %zu figures to %s\n", figures.size(), options.plots_dir.c_str());
    }
    return 0;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "error: not enough memory for this preset\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
  }
  return 1;
}

}  // namespace swarmlab
