// swarmlab: the desktop window by default, headless subcommands for scripts and CI.

#include <CLI/CLI.hpp>
#include <cstdio>

#include "cli/cli.h"
#include "cli/cli_bench.h"
#include "ensemble/ensemble_plan.h"
#include "i18n/language.h"
#include "swarm/engine/engine.h"
#include "ui/state/plot_tab.h"
#ifdef SWARMLAB_HAS_DESKTOP
#include "desktop/desktop.h"
#endif

int main(int argc, char** argv) {
  CLI::App app{
      "Swarm Lab: N particles coupled pairwise by F = -J m1 m2 r, solved exactly.\n"
      "Without a subcommand it opens the desktop window (optionally with PRESET.json)."};
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", swarmlab::ensemble::program_version(),
                       "The build's version: its commit, and a hash of uncommitted changes");

  std::string window_preset;
  int frames = 0;
  std::string screenshot;
  app.add_option("preset", window_preset, "Preset to open in the window")->check(CLI::ExistingFile);
  app.add_option("--frames", frames, "Run this many frames, then exit (0: run until closed)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--screenshot", screenshot, "After the last frame, save the window as PNG");
  int select = 0;
  app.add_option("--select", select,
                 "Select particle N (numbered from 1, as in the particle table): its card and "
                 "x(t) plot")
      ->check(CLI::PositiveNumber);
  int plot_tab = 0;
  app.add_option("--plot-tab", plot_tab,
                 "Open plot tab N (numbered from 1, left to right: 1 Wall P, T; 2 Energy; "
                 "3 Expansion; 4 Compare; 5 Particle; 6 Projects)")
      ->check(CLI::Range(1, swarmlab::kPlotTabCount));
  bool presentation = false;
  app.add_flag("--presentation", presentation,
               "Start in presentation mode: light theme, large text, the view and one plot");
  bool sound = false;
  app.add_flag("--sound", sound, "Start with a click at each wall hit (M turns it off)");
  bool lesson_summary = false;
  app.add_flag("--lesson-summary", lesson_summary,
               "With a lesson file: open its summary, as after Finish (the screenshot test)");

  std::string lang;
  app.add_option("--lang", lang,
                 "Speak this language: " + swarmlab::language_codes() +
                     " (default: the one chosen last in View > Language, else the system's; "
                     "English with --frames)");

  int window_threads = 0;
  app.add_option("--threads", window_threads,
                 "Engine threads for the window's runs: any count (default: every hardware "
                 "thread; the results are the same)")
      ->check(CLI::Range(1, swarm::kMaxThreads));

  std::string items;
  app.add_option("--items", items,
                 "After every frame, write its items (role, name, rectangle) to this JSON "
                 "file: how the window tests find what to press");

  swarmlab::RunOptions run;
  CLI::App* run_cmd = app.add_subcommand("run", "Run a preset headless and report the results");
  run_cmd->add_option("preset", run.preset_path, "Preset file (JSON)")->required();
  run_cmd->add_option("--out", run.out_path,
                      "Write RESULT.json: summary, samples, stages, fits and the final state");
  run_cmd->add_option("--csv", run.csv_path, "Write the samples as CSV (t,P,T,KE,PE,E,hits,R,work,heat,drag_loss,cm_height,size,T_kinetic)");
  CLI::Option* plots = run_cmd->add_option(
      "--plots", run.plots_dir,
      "Write the run's figures into this directory: SVG, and the CSV behind each");
  run_cmd->add_flag("--png", run.png, "With --plots: a PNG of each figure too (needs rsvg-convert)")
      ->needs(plots);
  run_cmd->add_flag("--quiet,-q", run.quiet, "No progress bar and no table on the terminal");
  run_cmd->add_option("--threads", run.threads,
                      "Engine threads: any count (default: every hardware thread; the results "
                      "are the same to the last bit)")
      ->check(CLI::Range(1, swarm::kMaxThreads));
  CLI::Option* run_seed = run_cmd->add_option(
      "--seed", run.seed,
      "Draw the generated swarm from this seed instead of particles.seed (an ensemble's run)");
  run_cmd->add_option("--perturb", run.perturb,
                      "With --seed and listed particles: move each start by up to this fraction "
                      "of the swarm's size and speed, drawn from the seed")
      ->check(CLI::Range(0.0, 1.0))
      ->needs(run_seed);
  CLI::Option* run_index =
      run_cmd->add_option("--run-index", run.run_index, "This run's index in its ensemble")
          ->check(CLI::NonNegativeNumber);
  run_cmd->add_option("--preset-hash", run.preset_hash,
                      "Refuse to run unless the preset has this hash (the plan's)");
  run_cmd
      ->add_option("--record", run.record_path,
                   "Write the ensemble record of this run (what swarmlab merge reads) instead "
                   "of the usual outputs")
      ->needs(run_seed)
      ->needs(run_index)
      ->excludes("--out")
      ->excludes("--csv")
      ->excludes(plots);

  swarmlab::EnsembleOptions ensemble;
  CLI::App* ensemble_cmd = app.add_subcommand(
      "ensemble",
      "Run a preset N times from independent seeds on every core, then merge the runs into "
      "means with 95 % intervals (resumes where a killed ensemble stopped)");
  swarmlab::EnsembleOptions plan;
  CLI::App* plan_cmd = app.add_subcommand(
      "plan",
      "Write the runs of an ensemble as a manifest of swarmlab run commands for GNU parallel or "
      "a Slurm array, without running them");
  for (auto [cmd, o] : {std::pair{ensemble_cmd, &ensemble}, std::pair{plan_cmd, &plan}}) {
    cmd->add_option("preset", o->preset_path,
                    "Preset file (JSON), or a sweep over some of a preset's keys (docs/command-line.md)")
        ->required();
    cmd->add_option("--seeds", o->seeds,
                    "How many independent runs (per sweep point; a sweep may give its own)")
        ->check(CLI::Range(1L, 1000000L));
    cmd->add_option("--out", o->dir, "The ensemble's folder (plan.json, preset.json, runs/)")
        ->required();
    cmd->add_option("--seed", o->seed, "Master seed: run k starts from a seed derived from it and k");
    cmd->add_option("--perturb", o->perturb,
                    "Listed particles: move each run's start by up to this fraction of the "
                    "swarm's size and speed")
        ->check(CLI::Range(0.0, 1.0));
    cmd->add_flag("--quiet,-q", o->quiet, "No progress bar and no table");
  }
  ensemble_cmd->add_option("--jobs,-j", ensemble.jobs, "Runs at once (default: every core)")
      ->check(CLI::Range(1, 4096));
  ensemble_cmd
      ->add_option("--threads", ensemble.threads,
                   "Engine threads per run: any count (default: 1 when runs share the cores, "
                   "else every hardware thread; the results are the same)")
      ->check(CLI::Range(1, swarm::kMaxThreads));
  ensemble_cmd->add_flag("--dt-check", ensemble.dt_check,
                         "Run the same seeds again at dt / 2 (into OUT/dt-half) and report each "
                         "quantity's shift with its 95 % interval beside the statistical one");
  plan_cmd->add_flag("--slurm", plan.slurm, "Also write DIR/array.sbatch, a Slurm job array");
  plan_cmd->add_option("--at-once", plan.slurm_at_once, "With --slurm: at most this many tasks at once")
      ->check(CLI::NonNegativeNumber);
  plan_cmd->add_option("--swarmlab", plan.swarmlab,
                       "The program each manifest line calls (default: this swarmlab's path)");

  swarmlab::MergeOptions merge;
  CLI::App* merge_cmd = app.add_subcommand(
      "merge", "Merge an ensemble's runs: per quantity the runs' values, mean, spread and 95 % interval");
  merge_cmd->add_option("dir", merge.dir, "The ensemble's folder")->required();
  merge_cmd->add_option("--out", merge.out_path, "REPORT.json (default DIR/report.json)");
  merge_cmd->add_option("--csv", merge.csv_path, "The per-run table (default DIR/runs.csv)");
  merge_cmd->add_option("--half-width", merge.half_width,
                        "Say how many runs make each 95 % interval this narrow, relative to the "
                        "mean (default 0.01)")
      ->check(CLI::Range(1e-9, 1e9));
  merge_cmd->add_flag("--quiet,-q", merge.quiet, "Say nothing on success");

  swarmlab::ReportOptions report;
  CLI::App* report_cmd = app.add_subcommand(
      "report",
      "Draw saved runs (RESULT.json from run --out): one run gives its figures, several are "
      "overlaid stage by stage (T-V, P-V, P-T); an ensemble's REPORT.json (merge) gives its "
      "bands");
  report_cmd->add_option("results", report.result_paths, "RESULT.json files")->required();
  report_cmd->add_option("--plots", report.plots_dir, "Directory for the figures (SVG + CSV)")
      ->required();
  report_cmd->add_flag("--png", report.png, "A PNG of each figure too (needs rsvg-convert)");
  report_cmd->add_flag("--quiet,-q", report.quiet, "Say nothing on success");

  std::string validate_path;
  CLI::App* validate_cmd =
      app.add_subcommand("validate", "Check a preset or a lesson and say what is wrong");
  validate_cmd->add_option("file", validate_path, "Preset or lesson file (JSON)")->required();

  swarmlab::CheckLessonOptions check_lesson;
  CLI::App* check_lesson_cmd = app.add_subcommand(
      "check-lesson",
      "Run the claims of each lesson's steps (an ensemble of seeds each) and fail, naming the "
      "lesson, the step and the numbers, where the physics contradicts the marked answer or the text");
  check_lesson_cmd->add_option("lessons", check_lesson.lesson_paths, "Lesson files (JSON)")->required();
  check_lesson_cmd->add_option("--jobs,-j", check_lesson.jobs, "Runs at once (default: every core)")
      ->check(CLI::Range(1, 4096));
  check_lesson_cmd->add_flag("--quiet,-q", check_lesson.quiet, "No table: only the errors");

  swarmlab::BenchOptions bench;
  CLI::App* bench_cmd = swarmlab::add_bench_subcommand(app, bench);

  CLI11_PARSE(app, argc, argv);

  if (*run_cmd) return swarmlab::run_command(run);
  if (*validate_cmd) return swarmlab::validate_command(validate_path);
  if (*bench_cmd) return swarmlab::bench_command(bench);
  if (*report_cmd) return swarmlab::report_command(report);
  if (*ensemble_cmd) return swarmlab::ensemble_command(ensemble);
  if (*plan_cmd) return swarmlab::plan_command(plan);
  if (*merge_cmd) return swarmlab::merge_command(merge);
  if (*check_lesson_cmd) return swarmlab::check_lesson_command(check_lesson);
#ifdef SWARMLAB_HAS_DESKTOP
  return swarmlab::run_desktop(
      {window_preset, frames, screenshot, select, presentation, plot_tab, sound, lesson_summary,
       items, lang, window_threads});
#else
  std::fprintf(stderr, "swarmlab: this build has no desktop window; see swarmlab --help\n");
  return 2;
#endif
}
