#include "swarm/measure/wall_tally_log.h"

namespace swarm {

void WallTallyLog::push(const WallTally& step_tally) {
  tail_.push_back({step_tally.hits, step_tally.radial_impulse, step_tally.hit_kinetic_energy});
  if (long(tail_.size()) == kBlock) {
    full_.push_back(std::make_shared<const std::vector<Entry>>(std::move(tail_)));
    tail_ = {};
  }
}

void WallTallyLog::clear() {
  full_.clear();
  tail_.clear();
}

WallReading WallTallyLog::reading(long first, double dt, double area) const {
  WallMeter meter;
  auto add = [&](const Entry& e) {
    WallTally t;
    t.hits = e.hits;
    t.radial_impulse = e.radial_impulse;
    t.hit_kinetic_energy = e.hit_kinetic_energy;
    meter.add(t, dt, area);
  };
  for (long i = first; i < size(); ++i) {
    const long block = i / kBlock;
    add(block < long(full_.size()) ? (*full_[std::size_t(block)])[std::size_t(i % kBlock)]
                                   : tail_[std::size_t(i - long(full_.size()) * kBlock)]);
  }
  return meter.reading();
}

}  // namespace swarm
