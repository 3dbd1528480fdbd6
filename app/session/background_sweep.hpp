// A sweep (core/sweep.hpp) run on a worker thread while the app goes on drawing: started on a
// copy of the scene as it is now, it reports progress and its runs as they finish (so the charts
// fill in while a class watches), and can be cancelled at any moment. Without threads
// (util/worker.hpp) start() returns when the sweep is done.
#pragma once

#include <atomic>
#include <mutex>

#include "springlab/sweep.hpp"
#include "util/worker.hpp"

namespace springlab::app {

class BackgroundSweep {
 public:
  BackgroundSweep() = default;
  ~BackgroundSweep();  // cancels and waits
  BackgroundSweep(const BackgroundSweep&) = delete;
  BackgroundSweep& operator=(const BackgroundSweep&) = delete;

  // Starts a sweep of (model, state); a sweep already running is cancelled first.
  void start(const Model& model, const State& state, const SweepSettings& settings);
  void cancel();
  bool running() const { return running_; }

  // A copy of what is known so far: the runs finished, and at the end the summaries.
  SweepResult snapshot() const;
  // Jobs done and in all (0 and 0 before any).
  std::pair<int, int> progress() const;

 private:
  void join();
  Worker worker_;
  std::atomic<bool> cancel_{false}, running_{false};
  mutable std::mutex mutex_;
  SweepResult partial_;
  int done_ = 0, total_ = 0;
};

}  // namespace springlab::app
