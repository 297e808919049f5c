#pragma once
/// The wall tallies of consecutive steps, kept so that a meter can be read over a stretch
/// chosen later: a stage by hand ("Expand now") learns its length, and so where its averaging
/// window begins, only when it ends. Full blocks are shared between copies (the timeline's
/// snapshots), so copying a log costs at most one block.

#include <cstdint>
#include <memory>
#include <vector>

#include "swarm/measure/thermometry.h"
#include "swarm/physics/wall.h"

namespace swarm {

class WallTallyLog {
 public:
  /// Appends one step's tally (what WallMeter::add reads of it: hits, impulse, energy).
  void push(const WallTally& step_tally);
  void clear();
  long size() const { return long(full_.size()) * kBlock + long(tail_.size()); }
  /// What one WallMeter would read fed with the steps [first, size()) in order, each of
  /// length dt (time) on a wall of this area (length^2).
  WallReading reading(long first, double dt, double area) const;

 private:
  struct Entry {
    std::int64_t hits;
    double radial_impulse, hit_kinetic_energy;
  };
  static constexpr long kBlock = 4096;  // 96 kB

  std::vector<std::shared_ptr<const std::vector<Entry>>> full_;
  std::vector<Entry> tail_;
};

}  // namespace swarm
