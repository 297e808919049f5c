#include "ensemble/ensemble_member.h"

#include "files/atomic_file.h"

namespace swarmlab::ensemble {

std::string run_member(const swarm::Preset& preset, const RunIdentity& id,
                       const std::string& record_path, int threads) {
  swarm::RunPlan plan = swarm::run_plan(preset);
  plan.engine.threads = threads;
  swarm::Run run(swarm::initial_system(preset), plan);
  run.finish();
  return write_file_atomically(record_path, record_json(record_of(id, run)));
}

}  // namespace swarmlab::ensemble
