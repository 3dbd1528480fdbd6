#include "session/stability_job.hpp"

#include <algorithm>
#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

#include "springlab/forces.hpp"
#include "util/worker.hpp"

namespace springlab::app {

namespace {
std::atomic<int> g_freed_while_locked{0};
}  // namespace

// What a job shares with its thread. Its mutex says whether it is held, so that freeing it while
// held (the bug take() once had: a later unlock wrote into freed memory, which no sanitizer sees
// alone) is counted where it happens (freed_while_locked(), for the tests).
struct StabilityJob::Shared {
  struct Mutex {
    std::mutex m;
    std::atomic<bool> held{false};
    void lock() { m.lock(), held = true; }
    void unlock() { held = false, m.unlock(); }
  } mutex;
  std::atomic<bool> done{false}, cancel{false};
  Result result;
  ~Shared() {
    if (mutex.held) ++g_freed_while_locked;
  }
};

namespace {

// Every job's thread, until joined: finished ones when the next starts, all of them at shutdown().
struct Threads {
  std::mutex mutex;
  struct Entry {
    std::unique_ptr<Worker> thread;
    std::shared_ptr<StabilityJob::Shared> shared;
  };
  std::vector<Entry> entries;

  // Joins the finished ones (never waits for one still running).
  void reap() {
    std::vector<std::unique_ptr<Worker>> finished;
    {
      std::lock_guard lock(mutex);
      for (auto it = entries.begin(); it != entries.end();) {
        if (it->shared->done) {
          finished.push_back(std::move(it->thread));
          it = entries.erase(it);
        } else {
          ++it;
        }
      }
    }
    for (auto& t : finished) t->join();
  }

  // Cancels every job and joins every thread.
  void join_all() {
    std::vector<Entry> all;
    {
      std::lock_guard lock(mutex);
      all.swap(entries);
    }
    for (Entry& e : all) e.shared->cancel = true;
    for (Entry& e : all) e.thread->join();
  }
  // At exit, after main (a test's process, or a main that did not call shutdown()).
  ~Threads() { join_all(); }
};

Threads& threads() {
  static Threads t;
  return t;
}

}  // namespace

StabilityJob::~StabilityJob() {
  cancel();
}

StabilityJob& StabilityJob::operator=(StabilityJob&& other) noexcept {
  if (this != &other) {
    cancel();
    shared_ = std::move(other.shared_);
  }
  return *this;
}

void StabilityJob::cancel() {
  if (shared_ && !shared_->done) shared_->cancel = true;
  shared_.reset();
}

void StabilityJob::start(const Model& model, const State& state, std::uint64_t version) {
  cancel();
  auto shared = std::make_shared<Shared>();
  shared->result.version = version;
  shared_ = shared;
  // The frame loop keeps a core: the analysis's searches run side by side on the others (none
  // on two cores, where a second search would take the frame loop's).
  const int analysis_threads = std::max(1, thread_count() - 1);
  auto work = [shared, model, state, analysis_threads] {
    if constexpr (kWorkerThreads)
      set_thread_count(analysis_threads);  // (this thread's own setting)
    else
      (void)analysis_threads;  // (no worker threads in the browser: the caller's one thread)
    auto analysis =
        std::make_shared<const StabilityAnalysis>(model, state, kDenseDofs, &shared->cancel);
    std::lock_guard lock(shared->mutex);
    if (!analysis->cancelled()) shared->result.analysis = std::move(analysis);
    shared->done = true;
  };
  if constexpr (kWorkerThreads) {
    Threads& all = threads();
    all.reap();
    auto worker = std::make_unique<Worker>();
    worker->start(std::move(work));
    std::lock_guard lock(all.mutex);
    all.entries.push_back({std::move(worker), shared});
  } else {
    work();
  }
}

bool StabilityJob::running() const {
  return shared_ && !shared_->done;
}

std::optional<StabilityJob::Result> StabilityJob::take() {
  if (!shared_ || !shared_->done) return std::nullopt;
  // The last owner may be this one (the thread finished and was reaped): it must outlive the
  // lock on its mutex. (Reset under the lock, it freed the mutex the lock then unlocked: a
  // write into freed memory, found by ThreadSanitizer in the stress test.)
  const std::shared_ptr<Shared> shared = std::move(shared_);
  Result result;
  {
    std::lock_guard lock(shared->mutex);
    result = std::move(shared->result);
  }
  if (!result.analysis) return std::nullopt;  // cancelled
  return result;
}

void StabilityJob::shutdown() {
  threads().join_all();
}

int StabilityJob::analyses_running() {
  Threads& all = threads();
  std::lock_guard lock(all.mutex);
  return static_cast<int>(std::count_if(all.entries.begin(), all.entries.end(),
                                        [](const auto& e) { return !e.shared->done; }));
}

int StabilityJob::freed_while_locked() {
  return g_freed_while_locked.load();
}

int StabilityJob::threads_alive() {
  Threads& all = threads();
  std::lock_guard lock(all.mutex);
  return static_cast<int>(all.entries.size());
}

}  // namespace springlab::app
