// The core's one seam to threads: every question about them (how many a parallel loop may use,
// which one this is), the team of helpers that runs the force pass and the energy's sums
// (Team, below), and every worker thread a sweep starts go through here.
//
// Built with OpenMP (SPRINGLAB_OPENMP, the default) these are OpenMP's answers. Without it (the
// browser build: WebAssembly without threads) the core runs on one thread: the functions below
// answer as a team of one would, and the parallel loops are plain loops (their SPRINGLAB_VECTORISE
// hints still vectorise under -fopenmp-simd). Results are the same bits either way: the force
// pass sums in the same order for any thread count (force_pass.hpp).
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <thread>
#include <type_traits>
#include <vector>

#if SPRINGLAB_OPENMP
#include <omp.h>

#include <thread>
#endif

// A loop's hint that its iterations are independent, to vectorise (OpenMP's `simd`, which
// -fopenmp-simd honours without the runtime): the one place the core names OpenMP for it.
#define SPRINGLAB_VECTORISE _Pragma("omp simd")

namespace springlab::threads {

// std::atomic_ref, or, where the standard library has none yet (emscripten 3.1.6's libc++), the
// same operations on the compiler's atomic builtins (GCC and Clang).
#if defined(__cpp_lib_atomic_ref)
template <typename T>
using atomic_ref = std::atomic_ref<T>;
#else
template <typename T>
class atomic_ref {
 public:
  explicit atomic_ref(T& object) : p_(&object) {}
  T load(std::memory_order order = std::memory_order_seq_cst) const {
    return __atomic_load_n(p_, builtin(order));
  }
  void store(T value, std::memory_order order = std::memory_order_seq_cst) const {
    __atomic_store_n(p_, value, builtin(order));
  }
  T fetch_add(T value, std::memory_order order = std::memory_order_seq_cst) const {
    return __atomic_fetch_add(p_, value, builtin(order));
  }
  bool compare_exchange_weak(T& expected, T desired,
                             std::memory_order order = std::memory_order_seq_cst) const {
    return __atomic_compare_exchange_n(p_, &expected, desired, true, builtin(order),
                                       builtin(failure(order)));
  }

 private:
  static constexpr int builtin(std::memory_order order) {
    switch (order) {
      case std::memory_order_relaxed:
        return __ATOMIC_RELAXED;
      case std::memory_order_consume:
        return __ATOMIC_CONSUME;
      case std::memory_order_acquire:
        return __ATOMIC_ACQUIRE;
      case std::memory_order_release:
        return __ATOMIC_RELEASE;
      case std::memory_order_acq_rel:
        return __ATOMIC_ACQ_REL;
      default:
        return __ATOMIC_SEQ_CST;
    }
  }
  // A failed exchange only loads: no release in its order.
  static constexpr std::memory_order failure(std::memory_order order) {
    return order == std::memory_order_acq_rel   ? std::memory_order_acquire
           : order == std::memory_order_release ? std::memory_order_relaxed
                                                : order;
  }
  T* p_;
};
#endif

#if SPRINGLAB_OPENMP
inline constexpr bool kAvailable = true;
// Threads a parallel loop started now would have (omp_get_max_threads).
inline int max_team() {
  return omp_get_max_threads();
}
inline void set_max_team(int threads) {
  omp_set_num_threads(threads);
}
inline int processors() {
  return omp_get_num_procs();
}
// Worker threads a sweep may run its runs on at once.
inline int hardware_workers() {
  return static_cast<int>(std::thread::hardware_concurrency());
}
#else
inline constexpr bool kAvailable = false;
inline int max_team() {
  return 1;
}
inline void set_max_team(int) {}
inline int processors() {
  return 1;
}
inline int hardware_workers() {
  return 1;
}
#endif

// ---- The team
// ------------------------------------------------------------------------------------
//
// Helper threads for the core's parallel passes. An OpenMP parallel region ends when every thread
// of its team has arrived at its barrier: when another program takes a core, a helper waits a
// whole scheduler tick to run and the step waits with it (a 64 x 64 cloth beside two busy
// processes: 22 to 48 ns a spring-step instead of 8 to 10 on one thread). Here a job is done when
// its work is: a helper joins only while the job is open, the work is claimed piece by piece by
// whoever is running (the job's own claims), and the caller takes every piece a helper has not
// claimed. The caller waits only for a helper that joined and holds a piece (a window of a few
// microseconds). Between jobs a helper spins, about a millisecond on a quiet machine (a step's
// next pass, after a solver's serial part, comes sooner) and 50 us where its core is wanted
// elsewhere (spin_window, below), then sleeps until the next one. A job is handed only to
// the helpers of its own team (a pass that asks for fewer threads than the pool has leaves the
// others asleep).
class Team {
 public:
  // Waits until `done()`: spins briefly (the wait is usually a few microseconds), then yields the
  // core. A job whose wait yielded, for a helper that says its own core was shared (it waited for
  // a processor a tenth of its last 20 ms, threads.cpp's core_shared: another program has the
  // core), is followed by jobs on the caller alone for a while: 128 of them, doubling up to about
  // a second of them each time it happens again, and halving with each job run as a team without
  // it. A helper late for another reason (woken from sleep, on a slower core) is waited for
  // without going alone. Where the kernel does not say, any yield counts. And a caller that
  // waited for a processor a tenth of the last 20 ms itself runs its jobs alone until a window
  // passes without: its waits may be too short to yield while its team runs in turns with other
  // programs on shared cores.
  // `patience`: how long a running thread may take to finish what it holds (the caller's own share
  // of the job took about that long): a wait shorter than it is a piece still being worked on,
  // not a thread another program parked (a 128 x 128 cloth's product pieces take 100 us and more,
  // where the spins alone, 4096 pauses, last 20 to 200 us by the processor).
  template <typename Done>
  static void wait(const Done& done,
                   std::chrono::nanoseconds patience = std::chrono::nanoseconds(0)) {
    // Spins: 4096 pauses, then for `patience` more (the clock read only from then on, every 256
    // spins: most waits end within the pauses, and a clock read costs as much as 20 of them).
    std::chrono::steady_clock::time_point since;
    for (int spins = 0; !done(); ++spins) {
      if (spins == 4096) since = std::chrono::steady_clock::now();
      if (spins >= 4096 && (spins & 255) == 0 &&
          std::chrono::steady_clock::now() - since >= patience) {
        while (!done()) {
          yielded();
          std::this_thread::yield();
        }
        return;
      }
#if defined(__x86_64__) || defined(__i386__)
      __builtin_ia32_pause();
#endif
    }
  }
  // A reference to the caller's callable (no copy, no allocation: a job runs thousands of times a
  // step); it must outlive run(), which it does, run() returning only when the job is done.
  class Job {
   public:
    template <typename F, typename = std::enable_if_t<!std::is_same_v<std::decay_t<F>, Job>>>
    Job(const F& f)
        : object_(&f), call_([](const void* o, int threads, int thread) {
            (*static_cast<const F*>(o))(threads, thread);
          }) {}
    void operator()(int threads, int thread) const { call_(object_, threads, thread); }

   private:
    const void* object_;
    void (*call_)(const void*, int, int);
  };
  // Runs job(threads, thread) on the caller as thread 0 and on each of helpers 1 to threads - 1
  // that joins before the caller's job(threads, 0) returns; returns once that has returned and no
  // helper is inside the job. The job must finish alone whatever the helpers leave (it may never
  // wait for a thread to arrive, only for a piece of work a thread has claimed). A second run()
  // while one is under way (another thread's) runs job(1, 0) at once.
  static void run(int threads, const Job& job);
  // The calling thread's jobs so far: run as a team, run alone (its own choice, after a wait that
  // had to yield, or the team busy with another thread's), and the waits that yielded.
  // `stalls`: runs of pieces taken from a thread that had stopped claiming (for_each_piece).
  // `shared`: jobs run alone because the caller's own core was shared (it waited for a processor
  // a tenth of the last 20 ms), counted among `alone` too. `sleeps`: the times a helper found no
  // job within its spin and slept, in this process (the next job wakes it, tens of microseconds
  // late).
  struct Counts {
    long team = 0, alone = 0, yields = 0, stalls = 0, shared = 0, sleeps = 0;
  };
  static Counts counts();
  // How long a helper spins for its next job before it sleeps: `team` the size of its last job's
  // team, `shared` whether its own core was shared then (core_shared, threads.cpp), `passive`
  // whether OMP_WAIT_POLICY=passive. A solver's serial parts between its passes (local-global's top
  // solves, 200 to 500 us on the 128 x 128 cloth) are short against what a sleep costs the pass
  // after them: woken, a helper came 34 to 55 us late to a pass after a 150 us pause (10th to
  // 90th percentile, 2 cores), and for a team of 16 the caller wakes each sleeper in turn. So a
  // helper whose core is spare spins about a millisecond (OpenMP's runtimes spin as long or
  // longer); one whose spin takes a core something else needs spins 50 us: its core shared with
  // other programs (beside two busy loops a millisecond's spin made XPBD's default 1.30 times
  // slower than one thread, against 0.86 times with 50 us), a team larger than the processors, or
  // a passive wait asked for (scripts/test.sh runs two tests at once so).
  static std::chrono::microseconds spin_window(int team, bool shared, bool passive);
  // Jobs a helper came to that its team did not include, in this process: none, as each job is
  // handed only to its own team's helpers (a regression would have idle helpers spin on the
  // team's cores).
  static long strays();
  // Whether a caller judges the load at all (its own core shared, a late helper's): on unless a
  // test of the team's own workings, which needs its jobs run as a team on a machine busy with
  // other tests, turns it off; then no job runs alone for the load. Process-wide.
  static void judge_shared_cores(bool on);

  // Waits while a run of pieces (front << 32 | back, as for_each_piece keeps them) has pieces
  // left and its owner claims one at least every `patience`. Returns whether it stopped claiming
  // with pieces left (its owner is not running: counted in `stalls`). Not a sign for the team to
  // go alone: the owner, still parked at the next job, does not begin its run there, which is
  // then taken at once.
  static bool stalled(const std::atomic<std::uint64_t>& run, std::chrono::nanoseconds patience);

 private:
  static void yielded();
};

// ---- Parallel loops
// ------------------------------------------------------------------------------
//
// The one place that decides when a loop is worth a second thread: below kParallelWork
// particle- and spring-visits a pass, one thread is taken to be faster than waking another. The
// figure is the force pass's threshold carried over to every pass. A solver's pass (implicit
// Euler's products, local-global's local step, a VBD colour, an XPBD colour) states its work in
// the same units: what one force pass over the same particles and springs would visit, times
// what a visit of its own costs against one of the force pass's where that is measured (XPBD's
// projections and VBD's descents: five each).
inline constexpr double kParallelWork = 4096;
inline bool worth_threads(double work) {
  return work >= kParallelWork && max_team() > 1;
}

// Runs piece(p) for each p in [0, pieces), on the team when `work` (worth_threads) says so, and
// returns once every piece is done. Each thread of the team has a run of consecutive pieces, the
// same run every call (its caches keep that run's data from one pass to the next: a CG on a
// 64 x 64 cloth reads 1.5 MB a pass, more than one core's L2), taken from the front. A thread
// that has finished its own leaves another's run to its owner while the owner keeps claiming
// pieces (at least one every two of the thread's own pieces' time), and takes the rest from its
// back once it stops, or at once if its owner has not begun it: one another program has parked
// does nothing, and its run is done by the others. Taken sooner, a piece moves its data to the
// taker's caches and back to its owner's for the next pass (docs/decisions.md, "Taking a piece
// from a helper's run"). The caller takes whatever the helpers leave. What a piece computes must
// not depend on which thread runs it (each writes its own results), so that results are the same
// bits for any number of threads. `per_thread`, if given: the least work a thread is given (a pass
// that does not scale past a few threads, as local-global's local step beside its serial solves,
// asks for fewer).
template <typename Piece>
void for_each_piece(int pieces, double work, const Piece& piece, double per_thread = 0.0) {
  if (pieces <= 1 || !worth_threads(work)) {
    for (int p = 0; p < pieces; ++p) piece(p);
    return;
  }
  const int most = per_thread > 0.0 ? std::max(1, static_cast<int>(work / per_thread)) : pieces;
  const int team = std::min({max_team(), pieces, most});
  // A run's unclaimed pieces, front << 32 | back, each run's word on a cache line of its own.
  struct alignas(64) Run {
    std::atomic<std::uint64_t> word;
  };
  constexpr int kOnStack = 16;  // (a larger team's words allocated)
  Run on_stack[kOnStack];
  std::vector<Run> allocated(team > kOnStack ? static_cast<std::size_t>(team) : 0);
  Run* runs = team > kOnStack ? allocated.data() : on_stack;
  const auto first_of = [&](int t) {
    return static_cast<std::uint64_t>(static_cast<long>(pieces) * t / team);
  };
  for (int t = 0; t < team; ++t)
    runs[t].word.store(first_of(t) << 32 | first_of(t + 1), std::memory_order_relaxed);
  const auto claim = [&](int t, bool front) -> int {
    std::atomic<std::uint64_t>& word = runs[t].word;
    std::uint64_t old = word.load(std::memory_order_relaxed);
    for (;;) {
      const std::uint64_t f = old >> 32, b = old & 0xFFFFFFFFu;
      if (f >= b) return -1;
      const std::uint64_t taken = front ? (f + 1) << 32 | b : f << 32 | (b - 1);
      if (word.compare_exchange_weak(old, taken, std::memory_order_relaxed))
        return static_cast<int>(front ? f : b - 1);
    }
  };
  Team::run(team, [&](int threads,
                      int thread) {  // (threads 1: the caller alone, taking every run at once)
    const auto start = std::chrono::steady_clock::now();
    int own = 0;
    for (int p; (p = claim(thread, true)) >= 0; ++own) piece(p);
    const std::chrono::nanoseconds patience = std::max<std::chrono::nanoseconds>(
        2 * (std::chrono::steady_clock::now() - start) / std::max(own, 1),
        std::chrono::microseconds(2));
    for (int other = 1; other < team; ++other) {
      const int run = (thread + other) % team;
      // A run its owner has not begun is taken at once (the owner asleep, or not come), one it
      // has begun once it stops claiming.
      const bool begun = runs[run].word.load(std::memory_order_relaxed) >> 32 != first_of(run);
      if (threads > 1 && begun && !Team::stalled(runs[run].word, patience)) continue;
      for (int p; (p = claim(run, false)) >= 0;) piece(p);
    }
  });
}

// Runs job(i) for each i in [0, jobs) on `workers` threads, the caller one of them (without
// threads, the caller alone), each taking the next job when it has finished one: independent
// jobs of uneven length, such as a sweep's runs or a stability analysis's searches. Each worker's
// own parallel loops run on one thread. The first exception a job throws is rethrown here once
// every worker has stopped; the jobs not yet started are then skipped.
void each(int jobs, int workers, const std::function<void(int)>& job);

}  // namespace springlab::threads
