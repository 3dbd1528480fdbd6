// A stability analysis (springlab/stability.hpp) made on a worker thread, so that the app's frame
// loop never waits for one (a 64 x 64 cloth's takes seconds): started on a copy of a lane's model
// and state, collected when done. A job left behind (the scene changed again, the lane went) is
// cancelled and finishes on its own within milliseconds; its thread is joined later, never by the
// frame loop while it runs, and every one still running when the app closes is cancelled and
// joined by shutdown() before main returns (a thread still analysing while the program's
// statics are destroyed would use freed memory). Without threads (util/worker.hpp) the analysis
// is made at once and is ready on the next take().
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "springlab/stability.hpp"

namespace springlab::app {

class StabilityJob {
 public:
  struct Result {
    std::uint64_t version = 0;  // the Simulation::model_version() it was made for
    std::shared_ptr<const StabilityAnalysis> analysis;
  };

  StabilityJob() = default;
  ~StabilityJob();  // cancels one still running
  StabilityJob(StabilityJob&&) noexcept = default;
  StabilityJob& operator=(StabilityJob&& other) noexcept;
  StabilityJob(const StabilityJob&) = delete;
  StabilityJob& operator=(const StabilityJob&) = delete;

  // Starts one; one still running is cancelled.
  void start(const Model& model, const State& state, std::uint64_t version);
  bool running() const;
  // The finished result, once; nothing while running or when none was started.
  std::optional<Result> take();

  // Cancels every job still running and joins every thread jobs have started. Called once the
  // app is done (before main returns); further jobs may be started after it.
  static void shutdown();
  // Threads started and not yet joined (for the tests).
  static int threads_alive();
  // Of those, the ones still analysing (not cancelled in time, or not cancelled at all).
  static int analyses_running();
  // How many jobs' shared states were freed while their mutex was held (0, or a bug).
  static int freed_while_locked();

  struct Shared;  // (the threads' registry holds it too)

 private:
  void cancel();
  std::shared_ptr<Shared> shared_;
};

}  // namespace springlab::app
