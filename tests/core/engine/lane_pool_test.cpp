#include "engine/lane_pool.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <numeric>
#include <set>
#include <thread>
#include <vector>

using swarm::fast::LanePool;

namespace {

// Only the native build has worker threads; in the browser every lane runs on the caller.
#ifdef __EMSCRIPTEN__
constexpr bool kHasThreads = false;
#else
constexpr bool kHasThreads = true;
#endif

/// How often each lane of one call ran. Lanes out of range are counted, not asserted on: an
/// assertion on a worker thread could not stop the test.
struct LaneRecord {
  explicit LaneRecord(std::size_t count) : runs(count) {}
  std::vector<std::atomic<int>> runs;
  std::atomic<int> out_of_range{0};

  void record(std::size_t lane) {
    if (lane >= runs.size())
      out_of_range.fetch_add(1);
    else
      runs[lane].fetch_add(1);
  }
  bool each_once() const {
    return out_of_range.load() == 0 &&
           std::all_of(runs.begin(), runs.end(), [](const auto& n) { return n.load() == 1; });
  }
};

}  // namespace

TEST_CASE("lane pool: each lane runs exactly once per call, for any thread and lane count") {
  for (const int threads : {1, 2, 3, 4, 7}) {
    for (const std::size_t count : {0, 1, 2, 3, 5, 100}) {
      for (const bool parallel : {true, false}) {
        CAPTURE(threads);
        CAPTURE(count);
        CAPTURE(parallel);
        LanePool pool(threads);
        LaneRecord record(count);
        const bool used_pool = pool.run(count, [&](std::size_t lane) { record.record(lane); },
                                        parallel);
        CHECK(record.each_once());
        // Other threads are asked only when there are some, there is more than one lane and
        // the caller allows it.
        CHECK(used_pool == (threads > 1 && count > 1 && parallel && kHasThreads));
      }
    }
  }
}

TEST_CASE("lane pool: on one thread the lanes run in order on the caller") {
  for (const int threads : {1, 4}) {
    CAPTURE(threads);
    LanePool pool(threads);
    std::vector<std::size_t> order;
    std::vector<std::thread::id> who;
    // threads = 4 with parallel = false must also keep to the caller.
    CHECK_FALSE(pool.run(
        5,
        [&](std::size_t lane) {
          order.push_back(lane);
          who.push_back(std::this_thread::get_id());
        },
        threads == 4 ? false : true));
    CHECK(order == std::vector<std::size_t>{0, 1, 2, 3, 4});
    for (const std::thread::id id : who) CHECK(bool(id == std::this_thread::get_id()));
  }
}

TEST_CASE("lane pool: many calls in a row, every lane's writes visible when run returns") {
  // Each call has the lanes fill their part of a plain (non-atomic) array with numbers that
  // depend on the call; the caller reads all of it right after run() returns, so every lane's
  // writes must have been published by then. A lane run twice, skipped, or still running late
  // would show in the counts or the sums. Lane counts above and below the thread count.
  for (const int threads : {2, 3, 7}) {
    CAPTURE(threads);
    LanePool pool(threads);
    constexpr std::size_t kCells = 64;
    for (int call = 1; call <= 1000; ++call) {
      const std::size_t lanes = std::size_t(1 + call % 9);
      std::vector<std::uint64_t> cells(lanes * kCells);
      LaneRecord record(lanes);
      pool.run(lanes, [&](std::size_t lane) {
        for (std::size_t i = 0; i < kCells; ++i)
          cells[lane * kCells + i] = std::uint64_t(call) * 1000 + lane * kCells + i;
        record.record(lane);
      });
      REQUIRE(record.each_once());
      const std::uint64_t n = lanes * kCells;
      REQUIRE(std::accumulate(cells.begin(), cells.end(), std::uint64_t(0)) ==
              n * std::uint64_t(call) * 1000 + n * (n - 1) / 2);
    }
  }
}

TEST_CASE("lane pool: the workers run lanes at once, call after call, and are waited for") {
  // Each lane here waits until all four have begun, so the four can only run on four threads
  // at once: the caller and the three workers. That makes the hand-over happen every time,
  // whatever the scheduler does (the machine may have fewer cores: the waiting lanes yield).
  // Lanes then linger and fill a plain array, so a run() that returned before a lane ended
  // would show in the sums. The same threads serve every call, and since a thread claims a
  // lane of its own chunk first (with four lanes, one each) and cannot take another before all
  // four have begun, lane 0 runs on the caller and each other lane on the same worker every
  // time: what keeps the engine's lanes on one core.
  if (!kHasThreads) return;  // one thread in the browser: the first lane would wait for ever
  constexpr std::size_t kLanes = 4, kCells = 1024;
  LanePool pool{int(kLanes)};
  std::set<std::thread::id> first_threads;
  std::vector<std::thread::id> first_by_lane;
  for (int call = 1; call <= 20; ++call) {
    std::atomic<std::size_t> began{0};
    std::atomic<int> stuck{0};
    std::vector<std::uint64_t> cells(kLanes * kCells);
    std::mutex who_mutex;
    std::set<std::thread::id> who;
    std::vector<std::thread::id> by_lane(kLanes);
    pool.run(kLanes, [&](std::size_t lane) {
      {
        std::lock_guard<std::mutex> lock(who_mutex);
        who.insert(std::this_thread::get_id());
        by_lane[lane] = std::this_thread::get_id();
      }
      began.fetch_add(1);
      // A deadline so that a broken hand-over fails the test rather than hanging it.
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
      while (began.load() < kLanes) {
        if (std::chrono::steady_clock::now() > give_up) {
          stuck.fetch_add(1);
          return;
        }
        std::this_thread::yield();
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200 * lane));
      for (std::size_t i = 0; i < kCells; ++i)
        cells[lane * kCells + i] = std::uint64_t(call) * 10000 + lane * kCells + i;
    });
    REQUIRE(stuck.load() == 0);
    const std::uint64_t n = kLanes * kCells;
    REQUIRE(std::accumulate(cells.begin(), cells.end(), std::uint64_t(0)) ==
            n * std::uint64_t(call) * 10000 + n * (n - 1) / 2);
    REQUIRE(who.size() == kLanes);
    REQUIRE(who.count(std::this_thread::get_id()) == 1);
    REQUIRE(bool(by_lane[0] == std::this_thread::get_id()));
    if (call == 1) {
      first_threads = who;
      first_by_lane = by_lane;
    }
    REQUIRE(who == first_threads);  // the workers stay alive between calls
    REQUIRE(by_lane == first_by_lane);
  }
}

TEST_CASE("lane pool: a lane may wait for an earlier lane of the same call") {
  // Each lane waits for the one before it to publish, then publishes its own: a chain through
  // every lane of the call, as the fast engine's lanes carry the sums of their hits on. It must
  // end for any thread and lane count (more threads than cores included), with the lanes'
  // values in lane order, call after call.
  for (const int threads : {1, 2, 3, 7}) {
    for (const std::size_t lanes : {1, 2, 3, 7, 20}) {
      CAPTURE(threads);
      CAPTURE(lanes);
      LanePool pool(threads);
      std::vector<std::atomic<std::uint64_t>> published(lanes);
      std::vector<std::uint64_t> chain(lanes);
      for (std::uint64_t call = 1; call <= 200; ++call) {
        pool.run(lanes, [&](std::size_t lane) {
          std::uint64_t before = 0;
          if (lane > 0) {
            LanePool::wait_for(published[lane - 1], call);
            before = chain[lane - 1];
          }
          chain[lane] = before * 3 + lane + call;
          published[lane].store(call, std::memory_order_release);
        });
        std::uint64_t expected = 0;
        for (std::size_t lane = 0; lane < lanes; ++lane) expected = expected * 3 + lane + call;
        REQUIRE(chain.back() == expected);
      }
    }
  }
}

TEST_CASE("lane pool: a copy is a new pool with the same thread count") {
  LanePool three(3), one(1);
  LaneRecord warm(3);
  three.run(3, [&](std::size_t lane) { warm.record(lane); });  // the original's threads run
  LanePool three_copy(three), one_copy(one);
  CHECK(three_copy.threads() == 3);
  CHECK(one_copy.threads() == 1);
  for (int call = 0; call < 100; ++call) {
    LaneRecord a(5), b(5), c(5);
    CHECK(three_copy.run(5, [&](std::size_t lane) { a.record(lane); }) == kHasThreads);
    CHECK(three.run(5, [&](std::size_t lane) { b.record(lane); }) == kHasThreads);
    CHECK_FALSE(one_copy.run(5, [&](std::size_t lane) { c.record(lane); }));
    CHECK(a.each_once());
    CHECK(b.each_once());
    CHECK(c.each_once());
  }
}

TEST_CASE("lane pool: destroyed with its threads running, or never started, it returns") {
  // The destructor must stop and join running workers; a hang here fails the suite.
  for (int pools = 0; pools < 20; ++pools) {
    LanePool started(4);
    std::atomic<int> runs{0};
    started.run(4, [&](std::size_t) { runs.fetch_add(1); });
    CHECK(runs.load() == 4);
    LanePool never_used(4);
  }
  CHECK(LanePool(0).threads() == 1);  // fewer than one thread counts as one
}
