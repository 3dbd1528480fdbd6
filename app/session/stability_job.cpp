#include "session/stability_job.hpp"

#include <atomic>
#include <mutex>

#include "util/worker.hpp"

namespace springlab::app {

struct StabilityJob::Shared {
  std::mutex mutex;
  std::atomic<bool> done{false};
  Result result;
};

void StabilityJob::start(const Model& model, const State& state, std::uint64_t version) {
  auto shared = std::make_shared<Shared>();
  shared->result.version = version;
  shared_ = shared;
  Worker::detach([shared, model, state] {
    auto analysis = std::make_shared<const StabilityAnalysis>(model, state);
    std::lock_guard lock(shared->mutex);
    shared->result.analysis = std::move(analysis);
    shared->done = true;
  });
}

bool StabilityJob::running() const { return shared_ && !shared_->done; }

std::optional<StabilityJob::Result> StabilityJob::take() {
  if (!shared_ || !shared_->done) return std::nullopt;
  std::lock_guard lock(shared_->mutex);
  Result result = std::move(shared_->result);
  shared_.reset();
  return result;
}

}  // namespace springlab::app
