#include "engine/lane_pool.h"

namespace swarm::fast {

#ifndef __EMSCRIPTEN__
namespace {

// A waiting thread first polls this many times without giving up the core (another thread's
// lane of a step takes microseconds), ...
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

constexpr std::uint64_t kLaneMask = 0xffff;

}  // namespace

LanePool::LanePool(int threads)
    : threads_(std::clamp(threads, 1, kMaxThreads)), chunks_(new Chunk[std::size_t(threads_)]) {}

LanePool::~LanePool() {
  if (workers_.empty()) return;
  stop_.store(true, std::memory_order_release);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    cv_.notify_all();
  }
  for (std::thread& worker : workers_) worker.join();
}

bool LanePool::start() {
  if (threads_ < 2) return false;
  if (workers_.empty())
    for (int w = 1; w < threads_; ++w) workers_.emplace_back([this, w] { worker_loop(w); });
  return true;
}

void LanePool::worker_loop(int thread) {
  std::uint32_t seen = 0;
  for (;;) {
    wait_until([&] {
      return go_.load(std::memory_order_acquire) != seen || stop_.load(std::memory_order_acquire);
    });
    if (stop_.load(std::memory_order_acquire)) return;
    seen = go_.load(std::memory_order_acquire);
    drain(seen, thread);
  }
}

void LanePool::wait_for(const std::atomic<std::uint64_t>& word, std::uint64_t value) {
  for (int i = 0; word.load(std::memory_order_acquire) != value; ++i) {
    if (i < kBusySpins)
      cpu_relax();
    else
      std::this_thread::yield();
  }
}

template <class Ready>
void LanePool::wait_until(Ready ready) {
  for (int i = 0; i < kBusySpins && !ready(); ++i) cpu_relax();
  for (int i = 0; i < kSpins && !ready(); ++i) std::this_thread::yield();
  if (!ready()) {
    std::unique_lock<std::mutex> lock(mutex_);
    cv_.wait(lock, ready);
  }
}

void LanePool::run_on_pool(std::size_t count, void* task, Call call) {
  task_ = task;
  call_ = call;
  count_ = count;
  finished_.store(0, std::memory_order_relaxed);
  ++generation_;
  // Thread t's chunk: lanes ceil(t count / threads) up to ceil((t + 1) count / threads), so
  // that the caller has lane 0 whatever the count.
  const std::uint64_t threads = std::uint64_t(threads_);
  const auto chunk_begin = [&](std::uint64_t t) { return (t * count + threads - 1) / threads; };
  for (std::uint64_t t = 0; t < threads; ++t)
    chunks_[t].word.store(
        std::uint64_t(generation_) << 32 | chunk_begin(t + 1) << 16 | chunk_begin(t),
        std::memory_order_release);
  go_.store(generation_, std::memory_order_release);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    cv_.notify_all();
  }
  drain(generation_, 0);
  wait_until([&] { return finished_.load(std::memory_order_acquire) == count; });
}

// A lane is claimed by moving its chunk's next-lane field on by one, in the word that also
// names the generation: each lane of each call runs exactly once, and the call's task and count
// are those of the claimed generation, which cannot end before the claimed lane has run.
void LanePool::drain(std::uint32_t generation, int thread) {
  for (int k = 0; k < threads_; ++k) {
    std::atomic<std::uint64_t>& word = chunks_[std::size_t((thread + k) % threads_)].word;
    for (;;) {
      std::uint64_t s = word.load(std::memory_order_acquire);
      if (std::uint32_t(s >> 32) != generation) return;  // that call is over
      const std::size_t end = (s >> 16) & kLaneMask, lane = s & kLaneMask;
      if (lane >= end) break;
      if (!word.compare_exchange_weak(s, s + 1, std::memory_order_acq_rel)) continue;
      const std::size_t count = count_;  // read before the last lane lets the next call begin
      call_(task_, lane);
      if (finished_.fetch_add(1, std::memory_order_acq_rel) + 1 == count) {
        std::lock_guard<std::mutex> lock(mutex_);
        cv_.notify_all();
      }
    }
  }
}

#else  // no threads in the browser

LanePool::LanePool(int threads) : threads_(std::clamp(threads, 1, kMaxThreads)) {}
LanePool::~LanePool() = default;
void LanePool::wait_for(const std::atomic<std::uint64_t>&, std::uint64_t) {}
bool LanePool::start() { return false; }
void LanePool::run_on_pool(std::size_t count, void* task, Call call) {
  for (std::size_t lane = 0; lane < count; ++lane) call(task, lane);
}

#endif

}  // namespace swarm::fast
