// A stability analysis (springlab/stability.hpp) made on a worker thread, so that the app's frame
// loop never waits for one (a 64 x 64 cloth's takes seconds): started on a copy of a lane's model
// and state, collected when done. The thread is detached and owns what it works on: a job left
// behind (the scene changed again, the app closed) finishes on its own and is dropped. Without
// threads (util/worker.hpp) the analysis is made at once and is ready on the next take().
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

  void start(const Model& model, const State& state, std::uint64_t version);
  bool running() const;
  // The finished result, once; nothing while running or when none was started.
  std::optional<Result> take();

 private:
  struct Shared;
  std::shared_ptr<Shared> shared_;
};

}  // namespace springlab::app
