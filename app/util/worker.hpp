// The one place the app starts threads (the core's own go through core/src/dynamics/threads.*):
// work done beside the frame loop (stability analyses, the accuracy sweep), the frame writer's
// queue and the interrupt's signal waiter (native builds only). tests/house/threads_seam_test.sh
// fails on a thread started anywhere else. Where the platform has no threads (the browser build,
// SPRINGLAB_APP_THREADS=0: WebAssembly threads need cross-origin isolation that a static host
// cannot promise) the work runs to completion at once, in the caller: the app does the same, only
// without a worker.
#pragma once

#include <functional>
#include <thread>

namespace springlab::app {

inline constexpr bool kWorkerThreads = SPRINGLAB_APP_THREADS;

class Worker {
 public:
  Worker() = default;
  ~Worker() { join(); }
  Worker(const Worker&) = delete;
  Worker& operator=(const Worker&) = delete;

  // Runs `work` on a thread (join() waits for it), or at once.
  void start(std::function<void()> work) {
    join();
    if constexpr (kWorkerThreads)
      thread_ = std::thread(std::move(work));
    else
      work();
  }
  void join() {
    if (thread_.joinable()) thread_.join();
  }

  // Runs `work` on a thread nobody waits for (it must own what it uses), or at once.
  static void detach(std::function<void()> work) {
    if constexpr (kWorkerThreads)
      std::thread(std::move(work)).detach();
    else
      work();
  }

 private:
  std::thread thread_;
};

}  // namespace springlab::app
