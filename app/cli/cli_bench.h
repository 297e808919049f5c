#pragma once
// `swarmlab bench`: the paper's headline workloads, timed, with their figures.

#include <string>

namespace CLI {
class App;
}

namespace swarmlab {

struct BenchOptions {
  std::string workload = "headline";  // headline | fireball | scale
  long particles = 0;                 // 0: 40,000 (headline, fireball) or 1,000,000 (scale)
  long steps = 10000;                 // scale only
  bool repulsive = false;             // scale only: J < 0
  std::string engine = "fast";        // fast | reference
  std::string preset_path;            // headline, fireball: this preset instead of the built-in
  long compare_steps = 0;             // also check the first steps against the reference engine
  int threads = 0;                    // 0: the default (every hardware thread)
};

/// Registers `bench` on app; the options are filled when it runs.
CLI::App* add_bench_subcommand(CLI::App& app, BenchOptions& options);
int bench_command(const BenchOptions& options);

}  // namespace swarmlab
