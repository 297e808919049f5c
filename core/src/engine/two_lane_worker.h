#pragma once
// Runs a task's two lanes at once: lane 0 on the calling thread, lane 1 on a worker thread
// that stays alive between calls, with a busy-polling hand-over so that even a task of a few
// microseconds gains from the second core. In the browser there are no threads: both lanes
// run on the caller, one after the other.

#include <cstdint>
#include <functional>
#ifndef __EMSCRIPTEN__
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#endif

namespace swarm::fast {

class TwoLaneWorker {
 public:
  /// threads: 2 to use a worker thread (where the platform has threads), 1 not to.
  explicit TwoLaneWorker(int threads) : threads_(threads) {}
  /// A copy (of a cloned engine) is a new worker with the same thread count: the thread is
  /// the copy's own, started when first needed.
  TwoLaneWorker(const TwoLaneWorker& other) : threads_(other.threads_) {}
  TwoLaneWorker& operator=(const TwoLaneWorker&) = delete;
  ~TwoLaneWorker();

  /// Runs task(0) and task(1), on two threads when `parallel` and possible. Says whether it
  /// used two. Callers that combine the lanes' results in lane order get the same numbers
  /// either way.
  template <class Task>
  bool run(Task&& task, bool parallel = true) {
    if (parallel && start()) {
#ifndef __EMSCRIPTEN__
      task_ = [&task](int lane) { task(lane); };
#endif
      hand_over();
      task(0);
      // Whichever thread claims lane 1 first runs it: a worker that is slow to wake (or whose
      // core the host has taken away) then costs one thread's time, not a wait.
      if (claim_current())
        task(1);
      else
        wait_for_worker();
      return true;
    }
    task(0);
    task(1);
    return false;
  }

 private:
  /// Starts the worker thread if needed; false when there is none to be had.
  bool start();
  /// Wakes the worker for the next generation of the task.
  void hand_over();
  /// Claims lane 1 of the current generation for the calling thread.
  bool claim_current();
  void wait_for_worker();

  int threads_;
#ifndef __EMSCRIPTEN__
  void worker_loop();
  bool claim(std::uint64_t generation);
  template <class Ready>
  void wait_until(Ready ready);

  std::thread worker_;
  std::atomic<std::uint64_t> go_{0}, done_{0}, claimed_{0};
  std::atomic<bool> stop_{false};
  std::uint64_t generation_ = 0;
  std::function<void(int)> task_;
  std::mutex mutex_;
  std::condition_variable cv_;
#endif
};

}  // namespace swarm::fast
