#include "engine/two_lane_worker.h"

namespace swarm::fast {

#ifndef __EMSCRIPTEN__
namespace {

// A waiting thread first polls this many times without giving up the core (the other
// thread's half of a step takes microseconds), ...
constexpr int kBusySpins = 4000;
// ... then yields this many times before it sleeps on a condition variable.
constexpr int kSpins = 20000;

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

}  // namespace

TwoLaneWorker::~TwoLaneWorker() {
  if (!worker_.joinable()) return;
  stop_.store(true, std::memory_order_release);
  hand_over();
  worker_.join();
}

bool TwoLaneWorker::start() {
  if (threads_ < 2) return false;
  if (worker_.joinable()) return true;
  worker_ = std::thread([this] { worker_loop(); });
  return true;
}

void TwoLaneWorker::worker_loop() {
  std::uint64_t seen = 0;
  for (;;) {
    wait_until([&] { return go_.load(std::memory_order_acquire) != seen; });
    seen = go_.load(std::memory_order_acquire);
    if (stop_.load(std::memory_order_acquire)) return;
    if (!claim(seen)) continue;
    task_(1);
    done_.store(seen, std::memory_order_release);
    std::lock_guard<std::mutex> lock(mutex_);
    cv_.notify_all();
  }
}

template <class Ready>
void TwoLaneWorker::wait_until(Ready ready) {
  for (int i = 0; i < kBusySpins && !ready(); ++i) cpu_relax();
  for (int i = 0; i < kSpins && !ready(); ++i) std::this_thread::yield();
  if (!ready()) {
    std::unique_lock<std::mutex> lock(mutex_);
    cv_.wait(lock, ready);
  }
}

void TwoLaneWorker::hand_over() {
  go_.store(++generation_, std::memory_order_release);
  std::lock_guard<std::mutex> lock(mutex_);
  cv_.notify_all();
}

// Each generation is claimed exactly once, before the next starts, so the claims go 1, 2, 3...
bool TwoLaneWorker::claim(std::uint64_t generation) {
  std::uint64_t expected = generation - 1;
  return claimed_.compare_exchange_strong(expected, generation, std::memory_order_acq_rel);
}

bool TwoLaneWorker::claim_current() { return claim(generation_); }

void TwoLaneWorker::wait_for_worker() {
  wait_until([&] { return done_.load(std::memory_order_acquire) == generation_; });
}

#else  // no threads in the browser

TwoLaneWorker::~TwoLaneWorker() = default;
bool TwoLaneWorker::start() {
  (void)threads_;  // one thread whatever was asked
  return false;
}
void TwoLaneWorker::hand_over() {}
bool TwoLaneWorker::claim_current() { return true; }
void TwoLaneWorker::wait_for_worker() {}

#endif

}  // namespace swarm::fast
