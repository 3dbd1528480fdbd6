// The core's one seam to threads: every question about them (how many a parallel loop may use,
// which one this is) and every worker thread a sweep starts go through here.
//
// Built with OpenMP (SPRINGLAB_OPENMP, the default) these are OpenMP's answers. Without it (the
// browser build: WebAssembly without threads) the core runs on one thread: the functions below
// answer as a team of one would, and the `#pragma omp` loops are plain loops (their `omp simd`
// hints still vectorise under -fopenmp-simd). Results are the same bits either way: the force
// pass sums in the same order for any thread count (force_pass.hpp).
#pragma once

#if SPRINGLAB_OPENMP
#include <omp.h>

#include <thread>
#endif

namespace springlab::threads {

#if SPRINGLAB_OPENMP
inline constexpr bool kAvailable = true;
// Threads a parallel loop started now would have (omp_get_max_threads).
inline int max_team() { return omp_get_max_threads(); }
inline void set_max_team(int threads) { omp_set_num_threads(threads); }
// Inside a parallel loop: its team's size and this thread's number.
inline int team_size() { return omp_get_num_threads(); }
inline int team_index() { return omp_get_thread_num(); }
inline int processors() { return omp_get_num_procs(); }
// Worker threads a sweep may run its runs on at once.
inline int hardware_workers() { return static_cast<int>(std::thread::hardware_concurrency()); }
#else
inline constexpr bool kAvailable = false;
inline int max_team() { return 1; }
inline void set_max_team(int) {}
inline int team_size() { return 1; }
inline int team_index() { return 0; }
inline int processors() { return 1; }
inline int hardware_workers() { return 1; }
#endif

}  // namespace springlab::threads
