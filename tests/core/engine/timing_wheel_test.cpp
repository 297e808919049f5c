#include "engine/timing_wheel.h"

#include <doctest/doctest.h>

#include <cstdint>
#include <random>
#include <vector>

using swarm::fast::kParked;
using swarm::fast::StepIndex;
using swarm::fast::TimingWheel;

namespace {

/// The ids the wheel gives for step `now` that are still due then (the others are stale
/// entries of ids rescheduled since, which the engine skips in the same way).
std::vector<std::uint32_t> take_due(TimingWheel& wheel, StepIndex now,
                                    const std::vector<StepIndex>& due) {
  std::vector<std::uint32_t> ids, valid;
  wheel.take(now, ids);
  for (const std::uint32_t id : ids)
    if (due[id] == now) valid.push_back(id);
  return valid;
}

}  // namespace

TEST_CASE("the timing wheel gives each id back in the step it was scheduled for") {
  TimingWheel wheel(100);
  // Near steps (this block and the next) and far ones (later blocks), pushed out of order.
  const std::vector<StepIndex> due = {5,
                                      0,
                                      3 * TimingWheel::kBlock + 7,
                                      1,
                                      5,
                                      TimingWheel::kHorizon,
                                      2 * TimingWheel::kBlock,
                                      TimingWheel::kBlock + 1};
  for (std::uint32_t id = 0; id < due.size(); ++id) wheel.push(id, due[id], 0);
  CHECK(wheel.waiting(0) == 1);
  std::vector<StepIndex> seen(due.size(), -1);
  for (StepIndex now = 0; now <= TimingWheel::kHorizon; ++now)
    for (const std::uint32_t id : take_due(wheel, now, due)) {
      CHECK(seen[id] == -1);  // once only
      seen[id] = now;
    }
  CHECK(seen == due);
}

TEST_CASE("the timing wheel keeps the order of pushes within a step") {
  TimingWheel wheel(100);
  const std::vector<StepIndex> due(5, 3);
  for (const std::uint32_t id : {4u, 0u, 3u, 1u, 2u}) wheel.push(id, 3, 0);
  for (StepIndex now = 0; now < 3; ++now) CHECK(take_due(wheel, now, due).empty());
  CHECK(take_due(wheel, 3, due) == std::vector<std::uint32_t>{4, 0, 3, 1, 2});
}

TEST_CASE("the timing wheel wraps around its buckets over a long run") {
  // 1,000 ids, each rescheduled at a random step within the horizon whenever it comes up,
  // for 30 times the horizon: the step buckets and the block buckets wrap many times.
  constexpr std::uint32_t kIds = 1000;
  TimingWheel wheel(kIds);
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<StepIndex> ahead(0, TimingWheel::kHorizon);
  std::vector<StepIndex> due(kIds);
  for (std::uint32_t id = 0; id < kIds; ++id) {
    due[id] = ahead(rng);
    wheel.push(id, due[id], 0);
  }
  long taken = 0, far = 0;
  for (StepIndex now = 0; now < 30 * TimingWheel::kHorizon; ++now) {
    long expected = 0;
    for (const StepIndex d : due) expected += d == now;
    const std::vector<std::uint32_t> ids = take_due(wheel, now, due);
    // Every id due now came out: none is lost, none comes early or late.
    CHECK(long(ids.size()) == expected);
    for (const std::uint32_t id : ids) {
      ++taken;
      due[id] = now + 1 + ahead(rng) % TimingWheel::kHorizon;
      far += due[id] / TimingWheel::kBlock > now / TimingWheel::kBlock + 1;
      wheel.push(id, due[id], now + 1);
    }
  }
  CHECK(taken > 30 * kIds);
  CHECK(far > taken / 2);  // most went through the block buckets
}

TEST_CASE("rescheduling removes an id from its old step, and compact() drops the old entry") {
  TimingWheel wheel(10);
  std::vector<StepIndex> due = {1000, 10, 500};
  for (std::uint32_t id = 0; id < due.size(); ++id) wheel.push(id, due[id], 0);
  due[0] = 2000;  // id 0 rescheduled: its entry for step 1000 is stale
  wheel.push(0, due[0], 0);
  due[2] = kParked;  // id 2 waits for nothing now
  wheel.compact([&](std::uint32_t id) { return due[id]; });
  std::vector<std::uint32_t> ids;
  for (StepIndex now = 0; now < 2000; ++now) {
    ids.clear();
    wheel.take(now, ids);
    // After compact() the wheel itself no longer holds the stale entries of ids 0 and 2.
    if (now == 1000 || now == 500) CHECK(ids.empty());
    if (now == 10) CHECK(ids == std::vector<std::uint32_t>{1});
  }
  ids.clear();
  wheel.take(2000, ids);
  CHECK(ids == std::vector<std::uint32_t>{0});
}

TEST_CASE("the timing wheel asks for compaction when stale far entries pile up") {
  constexpr std::size_t kShare = 100;
  TimingWheel wheel(kShare);
  std::vector<StepIndex> due(1, 0);
  bool asked = false;
  long pushes = 0;
  // One id rescheduled again and again to far steps: all but its last entry are stale.
  while (!asked && pushes < 100000) {
    due[0] = 3 * TimingWheel::kBlock + pushes % TimingWheel::kBlock;
    asked = wheel.push(0, due[0], 0);
    ++pushes;
  }
  CHECK(asked);
  CHECK(pushes == long(kShare + kShare / 2 + 4096 + 1));
  wheel.compact([&](std::uint32_t) { return due[0]; });
  // Only the current entry is left: the next pushes do not ask again for a long while.
  for (int i = 0; i < 4000; ++i) CHECK_FALSE(wheel.push(0, due[0], 0));
}

TEST_CASE("clear() empties every bucket") {
  TimingWheel wheel(10);
  const std::vector<StepIndex> due = {3, 400};
  wheel.push(0, 3, 0);
  wheel.push(1, 400, 0);
  wheel.clear();
  std::vector<std::uint32_t> ids;
  for (StepIndex now = 0; now <= 400; ++now) {
    wheel.take(now, ids);
    CHECK(ids.empty());
  }
}
