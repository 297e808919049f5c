#pragma once
// A two-level timing wheel of particle ids: the fast engine's schedule of which particles to
// check in which step.

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace swarm::fast {

/// A step of the run, counted from the engine's first.
using StepIndex = std::int64_t;
/// The step of a particle that waits for nothing (until something else reschedules it).
inline constexpr StepIndex kParked = std::numeric_limits<StepIndex>::max();

/// Frees an emptied vector that once held far more than its share: bursts (a new wall, an
/// expired anchor) would otherwise leave every bucket holding memory for a large part of N.
template <class Bucket>
void release_if_large(Bucket& bucket, std::size_t share) {
  if (bucket.capacity() > share / 16 + 4096) Bucket().swap(bucket);
}

/// One bucket per step for the current and the next block of kBlock steps, and one bucket per
/// block for the kFarBlocks blocks after that, moved into the step buckets a block ahead.
/// Pushes then land in a few hundred hot bucket tails rather than in thousands of cold ones.
/// A particle due later than kHorizon steps ahead waits at the horizon and is looked at again
/// then.
///
/// Removal is lazy: a particle rescheduled before its step keeps its old entry, and the
/// caller, who knows each particle's current step, skips it when that step's ids are taken
/// (and weeds the far entries with compact()).
class TimingWheel {
 public:
  static constexpr int kBlockBits = 6;
  static constexpr StepIndex kBlock = StepIndex(1) << kBlockBits;
  static constexpr StepIndex kFarBlocks = 64;
  static constexpr StepIndex kHorizon = (kFarBlocks - 1) * kBlock;
  /// Ids are packed with a step within a block into 32 bits.
  static constexpr std::size_t kMaxIds = std::size_t(1) << (32 - kBlockBits);

  /// share: about how many ids the wheel holds; it sizes the memory kept after bursts.
  explicit TimingWheel(std::size_t share = 0) : share_(share) {}

  /// Puts id in the bucket of step `due`, now <= due <= now + kHorizon, now being the step
  /// whose ids are taken next. Returns true when the block buckets hold so many stale entries
  /// that the caller should compact().
  bool push(std::uint32_t id, StepIndex due, StepIndex now) {
    if (due / kBlock <= now / kBlock + 1) {
      near_[near_slot(due)].push_back(id);
      return false;
    }
    far_[far_slot(due / kBlock)].push_back(far_entry(id, due));
    return ++far_entries_ > share_ + share_ / 2 + 4096;
  }

  /// How many entries (stale ones included) wait in the bucket of step `now`.
  std::size_t waiting(StepIndex now) const { return near_[near_slot(now)].size(); }

  /// Swaps the entries of step `now` into `ids` (which must be empty) and, at the start of a
  /// block, brings the next block's entries into its step buckets. Steps are taken in order.
  void take(StepIndex now, std::vector<std::uint32_t>& ids) {
    if ((now & (kBlock - 1)) == 0) bring_near(now / kBlock + 1);
    ids.swap(near_[near_slot(now)]);
  }

  /// Drops the entries of the block buckets whose id is no longer due in that step:
  /// due_of(id) gives the id's current step (or kParked).
  template <class DueOf>
  void compact(DueOf due_of) {
    far_entries_ = 0;
    for (std::size_t b = 0; b < far_.size(); ++b) {
      auto& bucket = far_[b];
      std::size_t kept = 0;
      for (const FarEntry e : bucket) {
        const StepIndex due = due_of(e >> kBlockBits);
        if (due != kParked && far_slot(due / kBlock) == b && far_entry(e >> kBlockBits, due) == e)
          bucket[kept++] = e;
      }
      bucket.resize(kept);
      far_entries_ += bucket.size();
      if (bucket.capacity() > 2 * bucket.size() + 4096) bucket.shrink_to_fit();
    }
  }

  /// Empties every bucket.
  void clear();

  std::size_t share() const { return share_; }

 private:
  /// An id waiting in a block bucket with its step within the block, packed into 32 bits so
  /// that moving it to its step bucket does not touch the particle's record.
  using FarEntry = std::uint32_t;
  static constexpr FarEntry far_entry(std::uint32_t id, StepIndex due) {
    return (id << kBlockBits) | FarEntry(due & (kBlock - 1));
  }
  static std::size_t near_slot(StepIndex s) { return std::size_t(s & (2 * kBlock - 1)); }
  static std::size_t far_slot(StepIndex block) { return std::size_t(block % kFarBlocks); }

  /// Moves the entries of `block` from its block bucket to the step buckets.
  void bring_near(StepIndex block);

  std::array<std::vector<std::uint32_t>, 2 * kBlock> near_;
  std::array<std::vector<FarEntry>, kFarBlocks> far_;
  std::size_t far_entries_ = 0;  // in all block buckets, stale ones included
  std::size_t share_ = 0;
};

}  // namespace swarm::fast
