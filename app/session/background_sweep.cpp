#include "session/background_sweep.hpp"

#include <chrono>

namespace springlab::app {

BackgroundSweep::~BackgroundSweep() {
  cancel_ = true;
  join();
}

void BackgroundSweep::join() {
  worker_.join();
}

void BackgroundSweep::cancel() {
  cancel_ = true;
  join();
  if (steps_) {
    steps_.reset();
    std::lock_guard lock(mutex_);
    partial_.cancelled = true;
    running_ = false;
  }
}

void BackgroundSweep::wait() {
  join();
  while (steps_) advance(1e9);
}

void BackgroundSweep::record(const SweepRun& run, int done, int total) {
  std::lock_guard lock(mutex_);
  if (run.h > 0) partial_.runs.push_back(run);
  done_ = done;
  total_ = total;
}

void BackgroundSweep::start(const Model& model, const State& state, const SweepSettings& settings) {
  cancel();
  {
    std::lock_guard lock(mutex_);
    partial_ = SweepResult();
    done_ = total_ = 0;
  }
  cancel_ = false;
  running_ = true;
  if constexpr (!kWorkerThreads) {
    steps_.emplace(model, state, settings);
    return;
  }
  worker_.start([this, model, state, settings] {
    SweepResult result = run_sweep(
        model, state, settings,
        [this](const SweepRun& run, int done, int total) { record(run, done, total); }, &cancel_);
    {
      std::lock_guard lock(mutex_);
      partial_ = std::move(result);
    }
    running_ = false;
  });
}

void BackgroundSweep::advance(double budget_ms) {
  if (!steps_) return;
  const auto start = std::chrono::steady_clock::now();
  const auto on_run = [this](const SweepRun& run, int done, int total) {
    record(run, done, total);
  };
  while (steps_->step(on_run))
    if (std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count() > budget_ms)
      return;
  std::lock_guard lock(mutex_);
  partial_ = steps_->result();
  steps_.reset();
  running_ = false;
}

SweepResult BackgroundSweep::snapshot() const {
  std::lock_guard lock(mutex_);
  return partial_;
}

std::pair<int, int> BackgroundSweep::progress() const {
  std::lock_guard lock(mutex_);
  return {done_, total_};
}

}  // namespace springlab::app
