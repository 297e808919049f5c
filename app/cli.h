#pragma once
// The headless subcommands of swarmlab. Each returns the process exit code.

#include <string>

namespace swarmlab {

struct RunOptions {
  std::string preset_path;
  std::string out_path;  // RESULT.json, empty: none
  std::string csv_path;  // SAMPLES.csv, empty: none
  bool quiet = false;
};

int run_command(const RunOptions& options);
int validate_command(const std::string& preset_path);

}  // namespace swarmlab
