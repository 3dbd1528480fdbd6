// Determinism: the same scene, method and inputs give a bit-identical state, run after run and
// whatever the number of threads.
#include <gtest/gtest.h>
#include <omp.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "dynamics/force_pass.hpp"
#include "dynamics/threads.hpp"
#include "springlab/forces.hpp"
#include "springlab/stability.hpp"
#include "support.hpp"

namespace springlab {
namespace {

// A test of the team's own workings runs its jobs as a team even on a machine busy with other
// tests: the caller does not judge the load (threads.hpp) while one of these lives. (Without it,
// the checking build's AJobWakesOnlyItsOwnTeam once ran 32 of its passes as a team, the rest
// alone after late helpers.)
struct TeamAlways {
  TeamAlways() { threads::Team::judge_shared_cores(false); }
  ~TeamAlways() { threads::Team::judge_shared_cores(true); }
  TeamAlways(const TeamAlways&) = delete;
  TeamAlways& operator=(const TeamAlways&) = delete;
};

std::uint64_t run_hash(const Scene& scene, Method method, int threads, int steps) {
  set_thread_count(threads);
  Simulation sim = test::simulation(scene, method, scene.dt);
  sim.advance(steps);
  set_thread_count(0);
  return state_hash(sim.state());
}

TEST(Determinism, SameRunSameBits) {
  const Scene scene = test::shipped("cloth-sphere");
  EXPECT_EQ(run_hash(scene, Method::SymplecticEuler, 0, 300),
            run_hash(scene, Method::SymplecticEuler, 0, 300));
}

TEST(Determinism, ThreadCountDoesNotChangeABit) {
  const TeamAlways team;
  // Big enough for the force loops to run in parallel.
  const Scene scene = test::shipped("cloth", {"cloth.width=48", "cloth.height=48"});
  for (const MethodInfo& m : methods()) {  // every row of the table
    const Method method = m.id;
    const auto one = run_hash(scene, method, 1, 40);
    const auto two = run_hash(scene, method, 2, 40);
    const auto three = run_hash(scene, method, 3, 40);
    EXPECT_EQ(one, two) << method_info(method).name;
    EXPECT_EQ(one, three) << method_info(method).name;
  }
  // More threads than blocks (and than cores): threads with one block, or none, waiting on others.
  EXPECT_EQ(run_hash(scene, Method::SymplecticEuler, 1, 40),
            run_hash(scene, Method::SymplecticEuler, 12, 40));
}

// A large model's finer blocks (force_pass.hpp's block_particles: an eighth of the particles, at
// most 1024 until there are 16 blocks) and local-global's top a coordinate a thread (from 3
// threads on): the same bits on any team. A 92 x 92 cloth has 9 blocks, 8 of 1024 and one of 272.
TEST(Determinism, ALargeModelsBlocksAndTopGiveTheSameBitsOnAnyTeam) {
  using force_detail::block_particles;
  EXPECT_EQ(block_particles(576), 256);     // the shipped cloth: 3 blocks, as before
  EXPECT_EQ(block_particles(4096), 512);    // 64 x 64: 8 blocks, as before
  EXPECT_EQ(block_particles(8192), 1024);   // 8 blocks
  EXPECT_EQ(block_particles(8464), 1024);   // 92 x 92: 9 (was 8 of 1088)
  EXPECT_EQ(block_particles(16384), 1024);  // 128 x 128: 16 (was 8 of 2048)
  EXPECT_EQ(block_particles(65536), 4096);  // 256 x 256: 16
  const TeamAlways team;
  const Scene scene = test::shipped("cloth", {"cloth.width=92", "cloth.height=92"});
  for (const auto& [method, steps] :
       {std::pair{Method::SymplecticEuler, 10}, std::pair{Method::ImplicitEuler, 2},
        std::pair{Method::LocalGlobal, 2}}) {
    const auto one = run_hash(scene, method, 1, steps);
    EXPECT_EQ(run_hash(scene, method, 3, steps), one) << method_info(method).name;
    EXPECT_EQ(run_hash(scene, method, 16, steps), one) << method_info(method).name;
  }
}

// The team hands a job only to its own helpers: after passes at 12 threads (the pool then holds 11
// helpers), passes at 2 threads are handed to one of them and wake none of the others (which, on 2
// cores, spun on the team's cores: the default ran at a quarter of its speed). And the state is
// the same bits. The two-thread passes must have run as a team (else no helper was handed a job
// to begin with), on a cloth large enough (64 x 64, implicit Euler's CG: a pass of some hundred
// microseconds) for a helper woken by mistake to arrive while the job is still on.
TEST(Determinism, AJobWakesOnlyItsOwnTeam) {
  const TeamAlways team;
  const Scene scene = test::shipped("cloth", {"cloth.width=48", "cloth.height=48"});
  const Scene large = test::shipped("cloth", {"cloth.width=64", "cloth.height=64"});
  const long before = threads::Team::strays();
  const auto twelve = run_hash(scene, Method::SymplecticEuler, 12, 40);
  const long team_before = threads::Team::counts().team;
  const auto two = run_hash(scene, Method::SymplecticEuler, 2, 40);
  for (int k = 0; k < 4; ++k) run_hash(large, Method::ImplicitEuler, 2, 10);
  EXPECT_GT(threads::Team::counts().team - team_before, 100)
      << "the two-thread passes did not run as a team";
  EXPECT_EQ(threads::Team::strays(), before);
  EXPECT_EQ(twelve, two);
}

// The stability analysis's searches run side by side (threads::each): every limit, and the mode
// that sets it, to the bit whatever the number of threads. The large scenes' path (the traced
// numerical range) on a cloth small enough to run in a test.
TEST(Determinism, TheStabilityAnalysisIsTheSameOnAnyNumberOfThreads) {
  // The traced range (10 x 10 cloth, dense spectrum off) and the dense spectrum (8 x 8 cloth, 186
  // free coordinates: every eigenvalue of a 372 x 372 matrix, whose reduction multiplies blocks
  // large enough for Eigen to share among threads where it may: EIGEN_DONT_PARALLELIZE).
  for (const std::pair<int, int>& which : {std::pair{10, 0}, std::pair{8, kDenseDofs}}) {
    const int side = which.first, dense_dofs = which.second;  // (clang 14 captures no binding)
    const std::string w = "cloth.width=" + std::to_string(side),
                      h = "cloth.height=" + std::to_string(side);
    const Scene scene = test::shipped("cloth", {w, h});
    const auto analyse = [&](int threads) {
      set_thread_count(threads);
      StabilityAnalysis a(scene.model, scene.state, dense_dofs);
      set_thread_count(0);
      return a;
    };
    const StabilityAnalysis one = analyse(1), two = analyse(2), three = analyse(3);
    ASSERT_EQ(one.dense(), dense_dofs > 0) << side;
    for (const StabilityAnalysis* other : {&two, &three}) {
      EXPECT_EQ(one.w_max(), other->w_max());
      for (const MethodInfo& m : methods()) {
        SCOPED_TRACE(m.name);
        const StabilityLimit &p = one.limit(m.id), &q = other->limit(m.id);
        if (std::isnan(p.h)) {
          EXPECT_TRUE(std::isnan(q.h));
          continue;
        }
        EXPECT_EQ(p.h, q.h);
        EXPECT_EQ(p.exact, q.exact);
        EXPECT_EQ(p.residual, q.residual);
        ASSERT_EQ(p.mode.has_value(), q.mode.has_value());
        if (p.mode) {
          EXPECT_EQ(p.mode->w, q.mode->w);
          EXPECT_EQ(p.mode->c, q.mode->c);
          EXPECT_EQ(p.mode->shape, q.mode->shape);
        }
      }
      ASSERT_EQ(one.modes().size(), other->modes().size());
      for (std::size_t k = 0; k < one.modes().size(); ++k) {
        EXPECT_EQ(one.modes()[k].gamma, other->modes()[k].gamma) << k;
        EXPECT_EQ(one.modes()[k].kappa, other->modes()[k].kappa) << k;
      }
    }
  }
}

// threads::each runs every job once, on as many threads as asked, and hands the first error a job
// throws to the caller after the others have stopped (none is lost in a worker).
TEST(Threads, EachRunsEveryJobOnceAndPassesOnTheFirstError) {
  threads::each(0, 2, [](int) { ADD_FAILURE() << "no job to run"; });
  for (int workers : {1, 2, 5}) {
    std::vector<std::atomic<int>> runs(37);
    threads::each(37, workers, [&](int j) { ++runs[j]; });
    for (int j = 0; j < 37; ++j) EXPECT_EQ(runs[j].load(), 1) << workers << " workers, job " << j;
    // Jobs 3 and 5 fail. One worker stops at job 3 and says so; with more, each job still runs
    // at most once, and one of the two failures reaches the caller.
    std::vector<std::atomic<int>> started(37);
    std::string message;
    try {
      threads::each(37, workers, [&](int j) {
        ++started[j];
        if (j == 3 || j == 5) throw std::runtime_error("job " + std::to_string(j));
      });
      ADD_FAILURE() << "no error passed on with " << workers << " workers";
    } catch (const std::runtime_error& e) {
      message = e.what();
    }
    int count = 0;
    for (int j = 0; j < 37; ++j) {
      EXPECT_LE(started[j].load(), 1) << workers << " workers, job " << j;
      count += started[j].load();
    }
    if (workers == 1) {
      EXPECT_EQ(count, 4);
      EXPECT_EQ(message, "job 3");
    } else {
      EXPECT_EQ(started[3].load(), 1);
      EXPECT_TRUE(message == "job 3" || message == "job 5") << message;
    }
  }
}

// for_each_piece's runs, on two threads (the caller's run, pieces 0 to 3, and the helper's, 4 to
// 7): the thread that ran each piece, whether the helper came (ran a piece of its own run), and
// the caller's stalls counted meanwhile. `piece(p)` is the work.
struct Runs {
  bool caller[8] = {};
  bool helper_came = false;
  long stalls = 0;
};
template <typename Piece>
Runs run_pieces(const Piece& piece) {
  const TeamAlways team;
  set_thread_count(2);
  const std::thread::id caller = std::this_thread::get_id();
  const long stalls = threads::Team::counts().stalls;
  Runs runs;
  std::atomic<bool> came{false};
  threads::for_each_piece(8, 1e9, [&](int p) {
    runs.caller[p] = std::this_thread::get_id() == caller;
    if (p >= 4 && !runs.caller[p]) came = true;
    piece(p);
  });
  set_thread_count(0);
  runs.helper_came = came;
  runs.stalls = threads::Team::counts().stalls - stalls;
  return runs;
}

void busy_for(std::chrono::microseconds d) {
  const auto until = std::chrono::steady_clock::now() + d;
  while (std::chrono::steady_clock::now() < until) {
  }
}

// A run its owner stops in (here, the helper's first piece waits for every other piece: a thread
// another program has parked) is finished by the others: the caller, done with its own run (1 ms
// a piece, time for the helper to come), takes the rest from its back and counts a stall. Were it
// to wait for the owner, each would wait for the other: the 10 s limit below.
TEST(Threads, ARunWhoseOwnerStopsIsFinishedByTheOthers) {
  bool checked = false;
  for (int attempt = 0; attempt < 20 && !checked; ++attempt) {
    std::atomic<int> done{0};
    std::atomic<bool> timed_out{false};
    const std::thread::id caller = std::this_thread::get_id();
    const Runs runs = run_pieces([&](int p) {
      if (p < 4) busy_for(std::chrono::microseconds(1000));
      if (p == 4 && std::this_thread::get_id() != caller) {
        const auto limit = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        while (done.load() < 7 && !timed_out)
          if (std::chrono::steady_clock::now() > limit) timed_out = true;
      }
      ++done;
    });
    ASSERT_FALSE(timed_out) << "the caller waited for a run whose owner had stopped";
    EXPECT_LE(runs.stalls, 1);
    // (the helper came late and the caller found its run not begun: again)
    checked = runs.helper_came && !runs.caller[4] && runs.stalls == 1;
  }
  EXPECT_TRUE(checked) << "in 20 tries, the helper never began its run before the caller took it";
}

// A run whose owner is working on it is left to it, though the owner is slower (3 ms a piece
// against the caller's 2: the caller, done at 8 ms, sees the helper's last piece claimed at
// 9 ms, within its patience of two of its own pieces). Taken at once, that piece and its data
// would move to the caller's core, and back for the next pass. A try in which another program
// delays a thread may see otherwise (the caller then rightly takes the stalled run); a quarter of
// 20 tries clean is asked for, where taking the working owner's piece at once leaves none clean.
TEST(Threads, ARunWhoseOwnerWorksIsLeftToIt) {
  int clean = 0;
  for (int attempt = 0; attempt < 20; ++attempt) {
    const Runs runs =
        run_pieces([](int p) { busy_for(std::chrono::microseconds(p < 4 ? 2000 : 3000)); });
    bool all_its_own = runs.helper_came;
    for (int p = 0; p < 8; ++p) all_its_own = all_its_own && runs.caller[p] == (p < 4);
    if (all_its_own && runs.stalls == 0) ++clean;
  }
  EXPECT_GE(clean, 5) << "in 20 tries the caller took a piece of the working helper's run in "
                      << 20 - clean;
}

// Called from the threads of an enclosing parallel region (each with its own buffers, as
// independent simulations would be), the force pass gives every thread the forces one call gives:
// alone (a small cloth) or with a nested region of its own (a larger one).
// Jobs of 8 pieces of 50 us on 2 threads for `duration`: how many ran, and how many of them ran
// alone because the caller's core was shared.
struct SharedJobs {
  long jobs = 0, alone = 0;
};
SharedJobs shared_jobs(std::chrono::milliseconds duration) {
  set_thread_count(2);
  const long before = threads::Team::counts().shared;
  SharedJobs out;
  const auto until = std::chrono::steady_clock::now() + duration;
  for (; std::chrono::steady_clock::now() < until; ++out.jobs)
    threads::for_each_piece(8, 1e9, [](int) { busy_for(std::chrono::microseconds(50)); });
  set_thread_count(0);
  out.alone = threads::Team::counts().shared - before;
  return out;
}

// The caller whose core another program shares runs its jobs alone: here the test and its
// helper pinned to one processor with a busy process beside them, the caller waits for its core
// about two thirds of the time, and most jobs of 300 ms run alone (the first window's jobs, before
// anything is known, as a team).
TEST(Threads, ACallerWhoseCoreIsSharedRunsAlone) {
  if (!threads::kAvailable) GTEST_SKIP() << "built without threads";
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(sched_getcpu(), &one);
  cpu_set_t all;
  ASSERT_EQ(sched_getaffinity(0, sizeof all, &all), 0);
  ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
  const pid_t busy = fork();
  ASSERT_GE(busy, 0);
  if (busy == 0) {  // the other program: a loop on the same processor until killed
    volatile unsigned long spins = 0;  // (a loop with no effect may be compiled away)
    for (;;) spins = spins + 1;
  }
  const SharedJobs run = shared_jobs(std::chrono::milliseconds(300));
  kill(busy, SIGKILL);
  waitpid(busy, nullptr, 0);
  sched_setaffinity(0, sizeof all, &all);
  EXPECT_GT(2 * run.alone, run.jobs)
      << "a caller sharing its core with a busy process ran " << run.jobs - run.alone << " of "
      << run.jobs << " jobs as a team";
}

// And on a quiet machine it keeps its team. Only where nothing else runs (ctest runs it alone,
// RUN_SERIAL, with SPRINGLAB_QUIET_MACHINE set: tests/CMakeLists.txt); a run among other tests
// skips it. The team's own helper, woken on the caller's processor until the kernel moves it,
// may share the caller's core for a window now and then (once in eight runs of 300 ms): one
// window's jobs alone, a fifteenth of them, at most.
TEST(Threads, AQuietCallerKeepsItsTeam) {
  if (!std::getenv("SPRINGLAB_QUIET_MACHINE")) GTEST_SKIP() << "run alone by ctest (RUN_SERIAL)";
  shared_jobs(std::chrono::milliseconds(100));  // (the helper's start)
  const SharedJobs run = shared_jobs(std::chrono::milliseconds(300));
  EXPECT_LE(15 * run.alone, run.jobs)
      << "a caller on a quiet machine ran " << run.alone << " of " << run.jobs << " jobs alone";
}

// Between passes a helper spins before it sleeps: on a quiet machine through a solver's serial
// parts (local-global's top solves, up to 500 us on the 128 x 128 cloth), since a helper woken
// from sleep comes tens of microseconds late to the next pass; but only 50 us where its spin would
// take a core something else needs. (What the spin does is measured, not asserted here: whether a
// helper sleeps in a given pause depends on the machine's scheduling, and on these virtual 2 cores
// a timed check of it failed both ways: in 2 runs of 12 a quiet helper judged its core shared for a
// 20 ms window, and in 4 of 12 a passive one was woken too late to sleep again. springlab_threads's
// sleeps= counts it, docs/performance.md.)
TEST(Threads, AHelperSpinsThroughASerialPartOnlyWhereItsCoreIsSpare) {
  using std::chrono::microseconds;
  const int cores = threads::processors();
  const microseconds spare = threads::Team::spin_window(cores, false, false);
  EXPECT_GE(spare, microseconds(500)) << "a quiet helper would sleep in local-global's top solves";
  EXPECT_LE(spare, microseconds(2000)) << "an idle app's helpers would spin long after each frame";
  EXPECT_EQ(threads::Team::spin_window(1, false, false), spare);
  EXPECT_LE(threads::Team::spin_window(cores, true, false), microseconds(50))
      << "a helper spins on a core another program shares";
  EXPECT_LE(threads::Team::spin_window(cores, false, true), microseconds(50))
      << "a helper spins where OMP_WAIT_POLICY=passive asks it not to";
  EXPECT_LE(threads::Team::spin_window(cores + 1, false, false), microseconds(50))
      << "a helper of a team larger than the processors spins on a core its team needs";
}

TEST(Determinism, ForcesInsideAnotherParallelRegionAreTheSame) {
  for (int side : {20, 48}) {
    const Scene scene = test::shipped(
        "cloth", {"cloth.width=" + std::to_string(side), "cloth.height=" + std::to_string(side)});
    Points expected;
    SpringForces buffer;
    evaluate_forces(scene.model, scene.state.x, scene.state.v, expected, buffer,
                    ForceOutput::Force);
    constexpr int kThreads = 2;
    Points got[kThreads];
#pragma omp parallel num_threads(kThreads)
    {
      SpringForces mine;
      const int t = omp_get_thread_num();
      evaluate_forces(scene.model, scene.state.x, scene.state.v, got[t], mine, ForceOutput::Force);
    }
    for (const Points& f : got) EXPECT_TRUE(f == expected) << side;
  }
}

// A block stolen from another thread's run (swept by a thread that did not start it) gives the
// forces its owner would have, to the bit: twelve threads share a cloth's eight blocks, so the
// threads left without a run of their own take blocks from the others' runs, pass after pass. The
// cloth is in motion (every spring stretched and moving), so that a force summed in another
// order would differ in its last bits.
TEST(Determinism, StolenBlocksGiveTheSameForces) {
  const TeamAlways team;
  const Scene scene = test::shipped("cloth", {"cloth.width=48", "cloth.height=48"});
  State moving = scene.state;
  test::jitter(moving, 0.02, 0.2, 5);
  // The bits of forces (state_hash tells -0 from +0, and any last bit).
  const auto bits = [&](const Points& f) {
    State s = moving;
    s.x = f;
    return state_hash(s);
  };
  Points forces;
  SpringForces buffer;
  set_thread_count(1);
  evaluate_forces(scene.model, moving.x, moving.v, forces, buffer);
  const std::uint64_t expected = bits(forces);
  set_thread_count(12);
  int differing = 0, passes = 0;
  for (; passes < 2000 && (passes < 50 || buffer.plan.stolen == 0); ++passes) {
    evaluate_forces(scene.model, moving.x, moving.v, forces, buffer);
    differing += bits(forces) != expected;
  }
  set_thread_count(0);
  EXPECT_GT(buffer.plan.stolen, 0u) << "no block was stolen in " << passes << " passes";
  EXPECT_EQ(differing, 0) << "of " << passes << " passes, " << buffer.plan.stolen
                          << " blocks stolen";
}

TEST(Determinism, HashSeesTheSmallestChange) {
  const Scene scene = test::shipped("spring");
  State s = scene.state;
  const auto before = state_hash(s);
  s.x(1, 0) = std::nextafter(s.x(1, 0), 2.0);
  EXPECT_NE(state_hash(s), before);
}

}  // namespace
}  // namespace springlab
