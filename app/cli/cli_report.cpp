#include <cstdio>

#include "cli/cli.h"
#include "files/text_file.h"
#include "report/ensemble_figures.h"
#include "report/plot_files.h"
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

}  // namespace

int report_command(const ReportOptions& options) {
  std::vector<report::NamedFigure> ensemble;
  if (options.result_paths.size() == 1)
    if (const std::string text = ensemble_report_text(options.result_paths.front()); !text.empty()) {
      report::EnsembleFigures e = report::ensemble_figures(text);
      if (!e.error.empty()) {
        std::fprintf(stderr, "error: %s: %s\n", options.result_paths.front().c_str(), e.error.c_str());
        return 1;
      }
      ensemble = std::move(e.figures);
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
  std::string e = report::stage_figures(files, options.plots_dir, figures, options.png);
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
