#pragma once
// Runs the lanes of a task (items 0 .. count - 1, each independent of the others) on the
// calling thread and on threads - 1 worker threads that stay alive between calls. The hand-over
// busy-polls, so that a step of a few dozen checks costs no more on several threads than on
// one; whichever thread gets to a lane first runs it, so a worker that is slow to wake (or
// whose core the host has taken away) costs one thread's time, never a wait for it.
//
// The pool says nothing about which thread runs which lane: callers keep each lane's results
// apart and combine them in lane order, and choose lanes that do not depend on the thread
// count, so that every number is the same for any count.
//
// In the browser there are no threads: the WebAssembly build would need SharedArrayBuffer,
// which needs the COOP/COEP headers that static hosting cannot send. There the lanes run on the
// caller, one after the other.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#ifndef __EMSCRIPTEN__
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>
#endif

#include "swarm/engine/engine.h"

namespace swarm::fast {

class LanePool {
 public:
  /// The most lanes one call can have.
  static constexpr std::size_t kMaxLanes = 0xffff;

  /// threads: how many threads may run lanes at once, the caller's included (>= 1; in the
  /// browser always one).
  explicit LanePool(int threads) : threads_(std::clamp(threads, 1, kMaxThreads)) {}
  /// A copy (of a cloned engine) is a new pool with the same thread count: its threads are the
  /// copy's own, started when first needed.
  LanePool(const LanePool& other) : threads_(other.threads_) {}
  LanePool& operator=(const LanePool&) = delete;
  ~LanePool();

  int threads() const { return threads_; }

  /// Runs task(lane) once for each lane in [0, count) (count <= kMaxLanes), on several threads
  /// when `parallel` and possible, and returns when all have run. Says whether other threads
  /// were asked to help.
  template <class Task>
  bool run(std::size_t count, Task&& task, bool parallel = true) {
    if (parallel && count > 1 && start()) {
      using Plain = std::remove_reference_t<Task>;
      run_on_pool(count, &task, [](void* t, std::size_t lane) { (*static_cast<Plain*>(t))(lane); });
      return true;
    }
    for (std::size_t lane = 0; lane < count; ++lane) task(lane);
    return false;
  }

 private:
  using Call = void (*)(void* task, std::size_t lane);
  /// Starts the worker threads if needed; false when there are none to be had.
  bool start();
  void run_on_pool(std::size_t count, void* task, Call call);

  int threads_;
#ifndef __EMSCRIPTEN__
  void worker_loop();
  /// Runs unclaimed lanes of generation `generation` until none is left.
  void drain(std::uint32_t generation);
  template <class Ready>
  void wait_until(Ready ready);

  std::vector<std::thread> workers_;
  // One word says which generation (call) is current, how many lanes it has and the next lane
  // to claim: a worker that wakes late can then never claim a lane of a later call by mistake.
  // Bits 32-63: generation, 16-31: count, 0-15: the next lane.
  std::atomic<std::uint64_t> state_{0};
  std::atomic<std::uint32_t> go_{0};  // the generation the workers are called to
  std::atomic<std::size_t> finished_{0};
  std::atomic<bool> stop_{false};
  std::uint32_t generation_ = 0;
  void* task_ = nullptr;
  Call call_ = nullptr;
  std::mutex mutex_;
  std::condition_variable cv_;
#endif
};

}  // namespace swarm::fast
