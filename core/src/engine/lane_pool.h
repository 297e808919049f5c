#pragma once
// Runs the lanes of a task (items 0 .. count - 1, each independent of the others) on the
// calling thread and on threads - 1 worker threads that stay alive between calls. The hand-over
// busy-polls, so that a step of a few dozen checks costs no more on several threads than on
// one. Each thread first runs a chunk of lanes of its own (thread t, the caller being 0: about
// lanes t count / threads up to (t + 1) count / threads), so that a lane, and the data it works
// on, stays on one core from call to call; then it helps with the others' chunks, so a worker
// that is slow to wake (or whose core the host has taken away) costs one thread's time, never a
// wait for it.
//
// The pool says nothing about which thread runs which lane: callers keep each lane's results
// apart and combine them in lane order, and choose lanes that do not depend on the thread
// count, so that every number is the same for any count. A lane may wait for a result of an
// earlier lane of the same call (wait_for): the caller runs lane 0 first and then always claims
// the lowest lane left, so every lane below one it waits in has been claimed, and the lowest
// unfinished lane always has a thread running it.
//
// In the browser there are no threads: the WebAssembly build would need SharedArrayBuffer,
// which needs the COOP/COEP headers that static hosting cannot send. There the lanes run on the
// caller, one after the other.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#ifndef __EMSCRIPTEN__
#include <condition_variable>
#include <memory>
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
  explicit LanePool(int threads);
  /// A copy (of a cloned engine) is a new pool with the same thread count: its threads are the
  /// copy's own, started when first needed.
  LanePool(const LanePool& other) : LanePool(other.threads_) {}
  LanePool& operator=(const LanePool&) = delete;
  ~LanePool();

  int threads() const { return threads_; }

  /// Waits, in a lane, until `word` holds `value`, which an earlier lane of the same call
  /// stores (with release). Polls, then yields; in the browser the earlier lanes have run.
  static void wait_for(const std::atomic<std::uint64_t>& word, std::uint64_t value);

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
  void worker_loop(int thread);
  /// Runs unclaimed lanes of generation `generation`, from thread `thread`'s chunk on, until
  /// none is left.
  void drain(std::uint32_t generation, int thread);
  template <class Ready>
  void wait_until(Ready ready);

  // One word per thread's chunk says which generation (call) is current, where the chunk ends
  // and its next lane to claim: a worker that wakes late can then never claim a lane of a later
  // call by mistake. Bits 32-63: generation, 16-31: the chunk's end, 0-15: its next lane. A
  // cache line each: the threads claim from their own.
  struct alignas(64) Chunk {
    std::atomic<std::uint64_t> word{0};
  };

  std::vector<std::thread> workers_;
  std::unique_ptr<Chunk[]> chunks_;   // threads_ of them
  std::atomic<std::uint32_t> go_{0};  // the generation the workers are called to
  std::atomic<std::size_t> finished_{0};
  std::atomic<bool> stop_{false};
  std::uint32_t generation_ = 0;
  std::size_t count_ = 0;  // lanes of the current call
  void* task_ = nullptr;
  Call call_ = nullptr;
  std::mutex mutex_;
  std::condition_variable cv_;
#endif
};

}  // namespace swarm::fast
