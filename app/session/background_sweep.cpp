#include "session/background_sweep.hpp"

namespace springlab::app {

BackgroundSweep::~BackgroundSweep() {
  cancel_ = true;
  join();
}

void BackgroundSweep::join() { worker_.join(); }

void BackgroundSweep::cancel() {
  cancel_ = true;
  join();
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
  worker_.start([this, model, state, settings] {
    SweepResult result = run_sweep(model, state, settings, [this](const SweepRun& run, int done, int total) {
      std::lock_guard lock(mutex_);
      if (run.h > 0) partial_.runs.push_back(run);
      done_ = done;
      total_ = total;
    }, &cancel_);
    {
      std::lock_guard lock(mutex_);
      partial_ = std::move(result);
    }
    running_ = false;
  });
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
