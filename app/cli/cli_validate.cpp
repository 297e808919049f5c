#include <cstdio>

#include "cli.h"
#include "files/preset_file.h"

namespace swarmlab {

int validate_command(const std::string& preset_path) {
  const swarm::PresetParse parsed = read_preset_file(preset_path);
  if (!parsed.preset) {
    std::fprintf(stderr, "error: %s\n", parsed.error.c_str());
    return 1;
  }
  const swarm::Preset& p = *parsed.preset;
  const swarm::RunPlan plan = swarm::run_plan(p);
  std::printf("%s: valid (%s, %ld steps of dt = %g, %s)\n", preset_path.c_str(),
              std::string(swarm::name_of(p.method)).c_str(), plan.steps, p.dt,
              p.container_radius ? "in a container" : "isolated");
  return 0;
}

}  // namespace swarmlab
