#include <cstdio>
#include <nlohmann/json.hpp>

#include "cli/cli.h"
#include "files/text_file.h"
#include "report/ensemble_figures.h"
#include "report/plot_files.h"
#include "report/provenance.h"
#include "report/report.h"
#include "report/run_record.h"

namespace swarmlab {

namespace {

/// The file's text when it is an ensemble report (swarmlab merge), else "".
std::string ensemble_report_text(const std::string& path) {
  std::string unreadable;  // read_result_file says what is wrong with the file
  const std::string text = read_text_file(path, unreadable, report::kResultFileLimit);
  return text.find(report::kEnsembleReportFormat) != std::string::npos &&
                 text.find("\"format\"") != std::string::npos
             ? text
             : std::string();
}

/// The seeds of an ensemble's report: its master seed and runs per point.
report::Seeds ensemble_seeds(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  report::Seeds s;
  if (j.is_object() && j.contains("seed") && j["seed"].is_number_unsigned() &&
      j.contains("seeds") && j["seeds"].is_number_integer())
    s.base = j["seed"].get<std::uint64_t>(), s.runs = j["seeds"].get<long>();
  return s;
}

/// The seeds of a saved run: as its RESULT.json recorded them, else its preset's.
report::Seeds run_seeds(const report::RunRecord& run) {
  return run.made_by ? run.made_by->seeds : report::seeds_of(run.preset);
}

/// What made the figures: this report (with the seeds of what it draws), and then, behind
/// "run: " (one run) or "run K: " (several), each run's own provenance where it recorded one
/// (else, of several, its seeds).
std::vector<std::string> figures_made_by(const std::vector<report::RunRecord>& runs,
                                         const report::Seeds& ensemble) {
  const report::Seeds seeds = runs.size() == 1 ? run_seeds(runs.front()) : ensemble;
  std::vector<std::string> lines = report::provenance_lines(report::provenance_now(seeds));
  if (runs.size() > 1) lines.pop_back();  // the seeds are each run's, below
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const std::string who = runs.size() == 1 ? "run: " : "run " + std::to_string(k + 1) + ": ";
    if (runs[k].made_by) {
      for (const std::string& line : report::provenance_lines(*runs[k].made_by))
        lines.push_back(who + line);
    } else if (runs.size() > 1) {  // only its seeds are known
      report::Provenance seeds_only;
      seeds_only.seeds = run_seeds(runs[k]);
      lines.push_back(who + report::provenance_lines(seeds_only).back());
    }
  }
  return lines;
}

}  // namespace

int report_command(const ReportOptions& options) {
  std::vector<report::NamedFigure> ensemble;
  report::Seeds ensemble_seed;
  if (options.result_paths.size() == 1)
    if (const std::string text = ensemble_report_text(options.result_paths.front()); !text.empty()) {
      report::EnsembleFigures e = report::ensemble_figures(text);
      if (!e.error.empty()) {
        std::fprintf(stderr, "error: %s: %s\n", options.result_paths.front().c_str(), e.error.c_str());
        return 1;
      }
      ensemble = std::move(e.figures);
      ensemble_seed = ensemble_seeds(text);
    }
  std::vector<report::RunRecord> runs;
  for (const std::string& path : options.result_paths) {
    if (!ensemble.empty()) break;
    report::RecordRead read = report::read_result_file(path);
    if (!read.record) {
      std::fprintf(stderr, "error: %s\n", read.error.c_str());
      return 1;
    }
    runs.push_back(std::move(*read.record));
  }
  std::string err = options.png ? report::png_unavailable_reason() : "";
  if (err.empty()) err = report::prepare_plot_dir(options.plots_dir);
  if (!err.empty()) {
    std::fprintf(stderr, "error: %s\n", err.c_str());
    return 1;
  }
  // One run: everything it has. Several: their stages overlaid, the paper's Fig. 5.
  const std::vector<report::NamedFigure> figures =
      !ensemble.empty()   ? ensemble
      : runs.size() == 1 ? report::run_figures(runs.front())
                         : report::overlay_figures(runs);
  if (figures.empty()) {
    std::fprintf(stderr, "error: nothing to overlay: fewer than one of these runs has stages\n");
    return 1;
  }
  OutputFiles files;
  std::string e = report::stage_figures(files, options.plots_dir, figures, options.png,
                                       figures_made_by(runs, ensemble_seed));
  if (e.empty()) e = files.commit();
  if (!e.empty()) {
    std::fprintf(stderr, "error: %s\n", e.c_str());
    return 1;
  }
  if (!options.quiet)
    std::printf("wrote %zu figures to %s\n", figures.size(), options.plots_dir.c_str());
  return 0;
}

}  // namespace swarmlab
