// The team (threads.hpp): helpers that join a job only while it is open, so that none is ever
// waited for unless it holds work.
#include "dynamics/threads.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace springlab::threads {

#if SPRINGLAB_OPENMP

namespace {

inline void pause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

// The calling thread's time waiting for a processor so far, in nanoseconds: runnable, its core
// given to another thread (the second figure of /proc/thread-self/schedstat); -1 where the kernel
// does not say (then no core is ever judged shared).
long long waited_for_a_core() {
  const int fd = ::open("/proc/thread-self/schedstat", O_RDONLY | O_CLOEXEC);
  if (fd < 0) return -1;
  char text[96];
  const ssize_t n = ::read(fd, text, sizeof text - 1);
  ::close(fd);
  if (n <= 0) return -1;
  text[n] = '\0';
  unsigned long long ran = 0, waited = 0;
  return std::sscanf(text, "%llu %llu", &ran, &waited) == 2 ? static_cast<long long>(waited) : -1;
}

// Whether the kernel says how long a thread waited for a processor (read once).
bool schedstat_readable() {
  static const bool readable = waited_for_a_core() >= 0;
  return readable;
}

// Whether the calling thread's own core is shared: in the last window of 20 ms it waited for a
// processor a tenth of the time or more. A caller that finds its own core shared runs its jobs
// alone until a window passes without; a helper says it in its slot, and the caller that waited
// for it goes alone for a while (Team::run). A team's threads that share their cores with other
// programs run in turns with them: each waits, spinning on its own share of the core, for the
// other's piece, and beside two busy processes on 2 cores local-global's team ran at half its
// speed, its waits too short to yield (docs/performance.md). Measured on 2 cores: a busy thread
// beside two busy processes waited 38 % of the time, alone 0.1 %. One read of the kernel's figure
// a window, not a job.
bool core_shared() {
  using Clock = std::chrono::steady_clock;
  constexpr auto kWindow = std::chrono::milliseconds(20);
  thread_local Clock::time_point window_start;
  thread_local long long window_waited = -1;
  thread_local bool shared = false;
  const Clock::time_point now = Clock::now();
  if (window_waited >= 0 && now - window_start < kWindow) return shared;
  const long long waited = waited_for_a_core();
  const auto wall = std::chrono::duration_cast<std::chrono::nanoseconds>(now - window_start);
  shared = window_waited >= 0 && waited >= 0 && 10 * (waited - window_waited) >= wall.count();
  window_start = now;
  window_waited = waited;
  return shared;
}

// Whether OMP_WAIT_POLICY asks waiting threads not to spin (read once).
bool passive_wait() {
  static const bool passive = [] {
    const char* policy = std::getenv("OMP_WAIT_POLICY");
    return policy && (std::strcmp(policy, "passive") == 0 || std::strcmp(policy, "PASSIVE") == 0);
  }();
  return passive;
}

// Jobs are numbered (generation); the caller hands a job (its number, the job, the team's size)
// to the helpers of this job's team alone, each in its own slot, and wakes those that sleep; runs
// its own share, then closes it (closed = its number) and waits until no helper is inside. A helper
// enters by counting itself inside and then checking that the job is still open: either it
// counted itself before the caller looked (the caller waits for it) or it sees the job closed and
// leaves (sequentially consistent order on `inside` and `closed`).
// A helper outside a job's team is not told of it: the pool keeps the helpers the largest team
// needed (16 for a pass at 16 threads), and a pass with a smaller team (local-global's local
// step, a small VBD colour, a later run at fewer threads) must not wake the others to spin for
// nothing on cores the team wants (on 2 cores, after a pass at 16 threads, the default's steps
// ran at a quarter of their speed while 14 idle helpers woke and spun at every pass).
// The words the caller writes and the helpers poll each on a cache line of its own: a helper's
// spin on its slot does not slow the caller's writes to `inside`'s line, nor the reverse.
struct Pool {
  // A helper's slot: the number of the last job handed to it (its low 32 bits: consecutive jobs
  // differ), the job and its team's size, and whether it sleeps (waits on `job`), so that the
  // caller wakes only a sleeper. All that a helper reads to begin is on this one line (from
  // another core's caches, a line is 40 to 200 ns away: the fewer lines a job's start waits
  // for in turn, the sooner the helper begins).
  struct alignas(64) Slot {
    std::atomic<std::uint32_t> job{0};
    std::atomic<bool> asleep{false};
    std::atomic<int> threads{1};
    std::atomic<const Team::Job*> what{nullptr};
    std::atomic<bool> shared{false};  // the helper's own core shared (core_shared), last it looked
  };
  static constexpr int kMostHelpers = 255;  // (a team of 256 threads)

  std::mutex growing;  // helpers are started under it
  std::vector<std::thread> helpers;
  std::atomic<int> started{0};  // helpers.size(), read without the lock
  alignas(64) std::atomic<bool> busy{false};
  std::uint64_t generation = 0;  // the last job's number (the caller's alone: `busy` is held)
  alignas(64) std::atomic<std::uint64_t> closed{0};
  alignas(64) std::atomic<int> inside{0};
  std::atomic<long> strays{0};   // Team::strays()
  std::atomic<long> sleeps{0};   // Team::Counts::sleeps
  Slot slots[kMostHelpers + 1];  // slots[i]: helper i (1 to kMostHelpers)

  // Hands job `g` to helpers 1 to team - 1, waking those that sleep. Sequentially consistent
  // with the helper's side (serve): either the caller sees a helper asleep and notifies it after
  // the store, or the helper, which marks itself asleep before it waits, sees the new number.
  // The job and team size are written before the number; a helper that reads them with a later
  // job's number is told so by `closed` (serve).
  void hand_out(std::uint64_t g, const Team::Job& job, int team) {
    for (int i = 1; i < team; ++i) {
      Slot& slot = slots[i];
      slot.what.store(&job, std::memory_order_relaxed);
      slot.threads.store(team, std::memory_order_relaxed);
      slot.job.store(static_cast<std::uint32_t>(g));
      if (slot.asleep.load()) slot.job.notify_one();
    }
  }

  // `seen`: the job number the helper's slot held when it was started.
  void serve(int index, std::uint32_t seen) {
    using Clock = std::chrono::steady_clock;
    Slot& slot = slots[index];
    for (;;) {
      // A new job soon (a step's next pass): spin; none for a while: sleep until one.
      const auto since = Clock::now();
      const auto window =
          Team::spin_window(slot.threads.load(std::memory_order_relaxed),
                            slot.shared.load(std::memory_order_relaxed), passive_wait());
      std::uint32_t g;
      for (int spins = 0; (g = slot.job.load(std::memory_order_acquire)) == seen; ++spins) {
        if (spins < 64 || (spins & 63) || Clock::now() - since < window) {
          pause();
          continue;
        }
        slot.asleep.store(true);
        sleeps.fetch_add(1, std::memory_order_relaxed);
        slot.job.wait(seen);  // (returns at once if the number has changed since)
        slot.asleep.store(false);
      }
      seen = g;
      // Job g, unless it is closed: then this helper came so late that the job and team read
      // here may be a later one's (written once g had closed and no helper was inside), unused.
      const Team::Job* job = slot.what.load(std::memory_order_relaxed);
      const int threads = slot.threads.load(std::memory_order_relaxed);
      inside.fetch_add(1);
      if (static_cast<std::int32_t>(static_cast<std::uint32_t>(closed.load()) - g) <
          0) {  // closed < g
        if (index < threads)
          (*job)(threads, index);
        else
          strays.fetch_add(1, std::memory_order_relaxed);
      }
      inside.fetch_sub(1);
      slot.shared.store(core_shared(), std::memory_order_relaxed);
    }
  }

  // Whether a helper of a team of `team` said last that its core was shared.
  bool helper_shared(int team) const {
    for (int i = 1; i < team; ++i)
      if (slots[i].shared.load(std::memory_order_relaxed)) return true;
    return false;
  }
};

// Never destroyed: a thread that still runs a job while the program's statics are destroyed (a
// worker the app has not joined) finds the pool as it was; the helpers end with the process.
Pool& pool() {
  static Pool* p = new Pool;
  return *p;
}

// The calling thread's waits that had to yield, during its current job.
thread_local int g_yields = 0;
// The caller's jobs still to run alone, and how many the next time (the caller's own: each thread
// that runs jobs judges the load by its own waits).
thread_local long g_alone = 0, g_backoff = 0;
thread_local Team::Counts g_counts;
constexpr long kFirstBackoff = 128, kLongestBackoff = 65536;

std::atomic<bool> g_judge_shared{true};  // Team::judge_shared_cores

}  // namespace

void Team::yielded() {
  ++g_yields;
  ++g_counts.yields;
}

bool Team::stalled(const std::atomic<std::uint64_t>& run, std::chrono::nanoseconds patience) {
  using Clock = std::chrono::steady_clock;
  std::uint64_t seen = run.load(std::memory_order_relaxed);
  auto since = Clock::now();
  for (int spins = 1;; ++spins) {
    const std::uint64_t word = run.load(std::memory_order_relaxed);
    if ((word >> 32) >= (word & 0xFFFFFFFFu)) return false;  // every piece claimed
    if (spins % 16 == 0) {  // (a clock read costs as much as 20 pauses)
      const auto now = Clock::now();
      if (word != seen) {
        seen = word;
        since = now;
      } else if (now - since >= patience) {
        ++g_counts.stalls;
        return true;
      }
    }
    pause();
  }
}
std::chrono::microseconds Team::spin_window(int team, bool shared, bool passive) {
  const bool spare = !passive && !shared && team <= processors();
  return std::chrono::microseconds(spare ? 1000 : 50);
}
Team::Counts Team::counts() {
  Counts c = g_counts;
  c.sleeps = pool().sleeps.load(std::memory_order_relaxed);
  return c;
}
long Team::strays() {
  return pool().strays.load();
}
void Team::judge_shared_cores(bool on) {
  g_judge_shared.store(on, std::memory_order_relaxed);
}

void Team::run(int threads, const Job& job) {
  Pool& p = pool();
  if (threads > 1 && g_alone > 0) {
    --g_alone;
    threads = 1;
  }
  if (threads > 1 && g_judge_shared.load(std::memory_order_relaxed) && core_shared()) {
    ++g_counts.shared;
    threads = 1;
  }
  if (threads <= 1 || p.busy.exchange(true, std::memory_order_acquire)) {
    ++g_counts.alone;
    job(1, 0);
    return;
  }
  ++g_counts.team;
  g_yields = 0;
  threads = std::min(threads, Pool::kMostHelpers + 1);
  if (p.started.load(std::memory_order_acquire) < threads - 1) {  // (the lock only to grow)
    std::lock_guard lock(p.growing);
    while (static_cast<int>(p.helpers.size()) < threads - 1) {
      const int index = static_cast<int>(p.helpers.size()) + 1;
      const std::uint32_t seen = p.slots[index].job.load();
      p.helpers.emplace_back([&p, index, seen] { p.serve(index, seen); });
    }
    p.started.store(static_cast<int>(p.helpers.size()), std::memory_order_release);
  }
  const std::uint64_t g = ++p.generation;
  p.hand_out(g, job, threads);
  const auto started = std::chrono::steady_clock::now();
  job(threads, 0);
  p.closed.store(g);
  // A helper still inside holds a piece: as long as the caller's own share took (twice, and at
  // least 20 us) it is working, not parked.
  const auto own = std::chrono::steady_clock::now() - started;
  wait([&] { return p.inside.load() == 0; },
       std::max<std::chrono::nanoseconds>(2 * own, std::chrono::microseconds(20)));
  p.busy.store(false, std::memory_order_release);
  // A helper that held work was late: alone for a while if another program has its core (the
  // helper waited for a processor, core_shared). Late for another reason (woken from sleep, a
  // slower core or its sibling thread busy), it is no reason to go alone: on a quiet 16-core
  // machine VBD's default ran at 0.66 of 16 threads' speed for its 128 jobs alone after such
  // waits. Where the kernel does not say, any late helper counts; where a test turns judging
  // off, none.
  if (g_yields > 0 && g_judge_shared.load(std::memory_order_relaxed) &&
      (!schedstat_readable() || p.helper_shared(threads))) {
    g_backoff =
        g_backoff < kFirstBackoff ? kFirstBackoff : std::min(2 * g_backoff, kLongestBackoff);
    g_alone = g_backoff;
  } else {
    g_backoff /= 2;
  }
}

#else

void Team::run(int, const Job& job) {
  job(1, 0);
}
std::chrono::microseconds Team::spin_window(int, bool, bool) {
  return std::chrono::microseconds(0);  // (no helpers)
}
void Team::judge_shared_cores(bool) {}
void Team::yielded() {}
bool Team::stalled(const std::atomic<std::uint64_t>&, std::chrono::nanoseconds) {
  return true;
}
Team::Counts Team::counts() {
  return {};
}
long Team::strays() {
  return 0;
}

#endif

void each(int jobs, int workers, const std::function<void(int)>& job) {
  if (jobs <= 0) return;
  workers = kAvailable ? std::clamp(workers, 1, jobs) : 1;
  std::atomic<int> next{0};
  std::exception_ptr failure;
  std::mutex failed;
  // Each worker's loops on one thread; the caller's own setting back however this ends.
  struct Restore {
    int team;
    ~Restore() { set_max_team(team); }
  } restore{max_team()};
  const auto work = [&] {
    set_max_team(1);
    for (int j; (j = next.fetch_add(1)) < jobs;) {
      try {
        job(j);
      } catch (...) {
        const std::lock_guard lock(failed);
        if (!failure) failure = std::current_exception();
        next.store(jobs);
      }
    }
  };
  std::vector<std::thread> helpers;
  helpers.reserve(static_cast<std::size_t>(workers - 1));
  for (int w = 1; w < workers; ++w) {
    try {
      helpers.emplace_back(work);
    } catch (const std::system_error&) {
      break;  // no more threads to be had: the ones running (and the caller) do the jobs
    }
  }
  work();
  for (std::thread& t : helpers) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace springlab::threads
