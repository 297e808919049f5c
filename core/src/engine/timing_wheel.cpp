#include "engine/timing_wheel.h"

namespace swarm::fast {

void TimingWheel::clear() {
  for (auto& bucket : near_) bucket.clear();
  for (auto& bucket : far_) bucket.clear();
  far_entries_ = 0;
}

void TimingWheel::bring_near(StepIndex block) {
  auto& bucket = far_[far_slot(block)];
  const StepIndex first = block * kBlock;
  for (const FarEntry e : bucket)
    near_[near_slot(first + StepIndex(e & (kBlock - 1)))].push_back(e >> kBlockBits);
  far_entries_ -= bucket.size();
  bucket.clear();
  release_if_large(bucket, share_);
}

}  // namespace swarm::fast
