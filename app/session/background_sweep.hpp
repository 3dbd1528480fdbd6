// A sweep (springlab/sweep.hpp) run on a worker thread while the app goes on drawing: started on a
// copy of the scene as it is now, it reports progress and its runs as they finish (so the charts
// fill in while a class watches), and can be cancelled at any moment. Without threads
// (util/worker.hpp: the browser) the frame loop runs it instead, a few pieces a frame through
// advance(): the same runs, filling in the same way.
#pragma once

#include <atomic>
#include <mutex>
#include <optional>

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
  // Waits for the sweep to finish (without threads: runs the rest of it now).
  void wait();
  bool running() const { return running_; }
  // Without threads: the sweep's next pieces, for about `budget_ms` (at least one). Called every
  // frame; with threads it does nothing.
  void advance(double budget_ms = 8.0);

  // A copy of what is known so far: the runs finished, and at the end the summaries.
  SweepResult snapshot() const;
  // Jobs done and in all (0 and 0 before any).
  std::pair<int, int> progress() const;

 private:
  void join();
  void record(const SweepRun& run, int done, int total);
  Worker worker_;
  std::optional<SweepInSteps> steps_;  // without threads
  std::atomic<bool> cancel_{false}, running_{false};
  mutable std::mutex mutex_;
  SweepResult partial_;
  int done_ = 0, total_ = 0;
};

}  // namespace springlab::app
