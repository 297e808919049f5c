#include "engine/two_lane_worker.h"

#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <numeric>
#include <thread>
#include <vector>

using swarm::fast::TwoLaneWorker;

namespace {

// Only the native build has a worker thread; in the browser both lanes run on the caller.
#ifdef __EMSCRIPTEN__
constexpr bool kHasThreads = false;
#else
constexpr bool kHasThreads = true;
#endif

/// How often each lane ran and which thread ran lane 0, for one call of run(). Lanes outside
/// {0, 1} are counted, not asserted on: an assertion on the worker thread could not stop the test.
struct LaneRecord {
  std::atomic<int> runs[2] = {{0}, {0}};
  std::atomic<int> other_lanes{0};
  std::thread::id lane0_thread;

  void record(int lane) {
    if (lane != 0 && lane != 1) {
      other_lanes.fetch_add(1);
      return;
    }
    runs[lane].fetch_add(1);
    if (lane == 0) lane0_thread = std::this_thread::get_id();
  }
};

}  // namespace

TEST_CASE("two-lane worker: each lane runs exactly once per task, lane 0 on the calling thread") {
  for (int threads : {1, 2}) {
    for (bool parallel : {true, false}) {
      CAPTURE(threads);
      CAPTURE(parallel);
      TwoLaneWorker worker(threads);
      LaneRecord record;
      const bool used_two = worker.run([&](int lane) { record.record(lane); }, parallel);
      CHECK(record.other_lanes.load() == 0);
      CHECK(record.runs[0].load() == 1);
      CHECK(record.runs[1].load() == 1);
      CHECK(bool(record.lane0_thread == std::this_thread::get_id()));
      // It says whether it used two threads: only when asked for both and the platform has them.
      CHECK(used_two == (threads == 2 && parallel && kHasThreads));
    }
  }
}

TEST_CASE("two-lane worker: on one thread the lanes run in order, 0 then 1, on the caller") {
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    TwoLaneWorker worker(threads);
    std::vector<int> order;
    std::vector<std::thread::id> who;
    // threads = 2 with parallel = false must also keep to the caller.
    CHECK_FALSE(worker.run(
        [&](int lane) {
          order.push_back(lane);
          who.push_back(std::this_thread::get_id());
        },
        false));
    CHECK(order == std::vector<int>{0, 1});
    REQUIRE(who.size() == 2);
    CHECK(bool(who[0] == std::this_thread::get_id()));
    CHECK(bool(who[1] == std::this_thread::get_id()));
  }
}

TEST_CASE("two-lane worker: many tasks in a row, each lane's writes visible when run returns") {
  // Each task has the lanes fill their halves of a plain (non-atomic) array with numbers that
  // depend on the task; the caller reads all of it right after run() returns, so lane 1's
  // writes must have been published by then. Each lane also counts its runs: any lane run
  // twice, skipped, or still running late would show in the counts or the sums.
  TwoLaneWorker worker(2);
  constexpr int kHalf = 64, kTasks = 2000;
  std::vector<std::uint64_t> cells(2 * kHalf);
  std::atomic<int> runs[2] = {{0}, {0}};
  for (int task = 1; task <= kTasks; ++task) {
    worker.run([&](int lane) {
      for (int i = 0; i < kHalf; ++i)
        cells[std::size_t(lane * kHalf + i)] =
            std::uint64_t(task) * 1000 + std::uint64_t(lane * kHalf + i);
      runs[lane].fetch_add(1);
    });
    REQUIRE(runs[0].load() == task);
    REQUIRE(runs[1].load() == task);
    // sum over j of (task * 1000 + j), j = 0 .. 2 kHalf - 1.
    const std::uint64_t expected = std::uint64_t(2 * kHalf) * std::uint64_t(task) * 1000 +
                                   std::uint64_t(2 * kHalf) * (2 * kHalf - 1) / 2;
    REQUIRE(std::accumulate(cells.begin(), cells.end(), std::uint64_t(0)) == expected);
  }
}

TEST_CASE("two-lane worker: lane 1 runs on one worker thread, call after call, and is waited for") {
  // Lane 0 here does not return until lane 1 has begun, so lane 1 can only be run by another
  // thread: the worker. That makes the hand-over happen every time instead of when the
  // scheduler allows, without asserting anything about time. Lane 1 then fills a plain array
  // after saying it began, from its far end, and last marks itself finished, so a run() that
  // returned before lane 1 ended would show in the mark and the sums.
  if (!kHasThreads) return;  // one thread in the browser: lane 0 would wait for ever
  TwoLaneWorker worker(2);
  constexpr int kTasks = 20, kCells = 4096;
  std::vector<std::uint64_t> cells(kCells);
  std::atomic<int> lane1_began{0};
  int stuck = 0;  // a lane 0 that gave up waiting: only a broken worker gets here
  std::thread::id first_worker;
  for (int task = 1; task <= kTasks; ++task) {
    std::thread::id lane1_thread;
    int lane1_finished = 0;
    worker.run([&](int lane) {
      if (lane == 1) {
        lane1_thread = std::this_thread::get_id();
        lane1_began.store(task, std::memory_order_release);
        // Lingering lets a caller that does not wait return first, whatever the scheduler
        // does; a correct run() just waits half a millisecond longer.
        std::this_thread::sleep_for(std::chrono::microseconds(500));
        for (int i = kCells - 1; i >= 0; --i)
          cells[std::size_t(i)] = std::uint64_t(task) * kCells + std::uint64_t(i);
        lane1_finished = task;
        return;
      }
      // A deadline so that a broken hand-over fails the test rather than hanging it.
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
      while (lane1_began.load(std::memory_order_acquire) != task) {
        if (std::chrono::steady_clock::now() > give_up) {
          ++stuck;
          return;
        }
        std::this_thread::yield();
      }
    });
    REQUIRE(stuck == 0);
    REQUIRE(lane1_finished == task);
    const std::uint64_t expected = std::uint64_t(kCells) * std::uint64_t(task) * kCells +
                                   std::uint64_t(kCells) * (kCells - 1) / 2;
    REQUIRE(std::accumulate(cells.begin(), cells.end(), std::uint64_t(0)) == expected);
    REQUIRE(bool(lane1_thread != std::this_thread::get_id()));
    if (task == 1) first_worker = lane1_thread;
    REQUIRE(bool(lane1_thread == first_worker));  // the worker stays alive between calls
  }
}

TEST_CASE("two-lane worker: lanes combined in lane order give the same numbers either way") {
  // The promise behind the fast engine's determinism: two threads or one, a caller that keeps
  // each lane's partial sum apart and adds them 0 then 1 gets the same bits.
  std::vector<double> values(10000);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = 1.0 / double(i + 1);
  auto sum_in_lanes = [&](TwoLaneWorker& worker, bool parallel) {
    double partial[2] = {0, 0};
    worker.run(
        [&](int lane) {
          const std::size_t half = values.size() / 2;
          for (std::size_t i = lane * half; i < (lane + 1) * half; ++i) partial[lane] += values[i];
        },
        parallel);
    return partial[0] + partial[1];
  };
  TwoLaneWorker two(2), one(1);
  const double serial = sum_in_lanes(one, true);
  for (int repeat = 0; repeat < 50; ++repeat) {
    CHECK(sum_in_lanes(two, true) == serial);
    CHECK(sum_in_lanes(two, false) == serial);
  }
}

TEST_CASE("two-lane worker: a copy is a new worker with the same thread count") {
  TwoLaneWorker two(2), one(1);
  LaneRecord warm;
  two.run([&](int lane) { warm.record(lane); });  // the original's thread is running
  TwoLaneWorker two_copy(two), one_copy(one);
  for (int task = 0; task < 100; ++task) {
    LaneRecord a, b, c;
    CHECK(two_copy.run([&](int lane) { a.record(lane); }) == kHasThreads);
    CHECK(two.run([&](int lane) { b.record(lane); }) == kHasThreads);
    CHECK_FALSE(one_copy.run([&](int lane) { c.record(lane); }));
    for (const LaneRecord* r : {&a, &b, &c}) {
      CHECK(r->other_lanes.load() == 0);
      CHECK(r->runs[0].load() == 1);
      CHECK(r->runs[1].load() == 1);
    }
  }
}

TEST_CASE("two-lane worker: destroyed with its thread running, or never started, it returns") {
  // The destructor must stop and join a running worker thread; a hang here fails the suite.
  for (int workers = 0; workers < 20; ++workers) {
    TwoLaneWorker started(2);
    std::atomic<int> runs{0};
    started.run([&](int) { runs.fetch_add(1); });
    CHECK(runs.load() == 2);
    TwoLaneWorker never_used(2);
  }
}
