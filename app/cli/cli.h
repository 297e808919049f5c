#pragma once
// The headless subcommands of swarmlab. Each returns the process exit code.

#include <string>
#include <vector>

namespace swarmlab {

struct RunOptions {
  std::string preset_path;
  std::string out_path;   // RESULT.json, empty: none
  std::string csv_path;   // SAMPLES.csv, empty: none
  std::string plots_dir;  // figures (SVG + CSV) go here, empty: none
  bool png = false;       // also render each figure as PNG
  bool quiet = false;
};

struct ReportOptions {
  std::vector<std::string> result_paths;  // RESULT.json files from `run --out`
  std::string plots_dir;
  bool png = false;
  bool quiet = false;
};

int run_command(const RunOptions& options);
int validate_command(const std::string& preset_path);
int report_command(const ReportOptions& options);

}  // namespace swarmlab
