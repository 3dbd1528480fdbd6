// Forces on every particle: springs, gravity, drag and the fields, gathered without races.
//
// The pass (core/src/dynamics/force_pass.hpp) cuts the particles into fixed blocks, shared out
// among the threads as runs of consecutive blocks; each spring belongs to the block of its a-end,
// and the forces of springs reaching into a later block wait in a buffer until that block takes
// them. Every particle's sum is taken in an order fixed by the blocks alone, so results are
// bit-identical for any thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "springlab/model.hpp"
#include "springlab/state.hpp"

namespace springlab {

// Reused between evaluations: the plan of the force pass for a model (force_pass.hpp), and the
// forces of the springs that reach from one block of particles into another.
struct ForcePlan {
  struct Piece {
    int span;    // index into model.spans
    int lo, hi;  // springs [lo, hi) of the span (from its first)
  };
  int particles = -1, springs = -1;  // of the model it was made for
  const void* spans = nullptr;
  int block = 0;                        // particles a block
  int reach = 0;                        // the largest b - a of a spring (0 without springs)
  std::vector<std::vector<Piece>> own;  // per block: springs whose a-end it holds
  // Per chunk of a block's particles (block b's chunks from chunk_first[b] on): the pieces of
  // `own` cut to the springs whose a-ends are in the chunk, in the same order. A block of a
  // cloth holds a few spans a row, hundreds in all: a chunk finds its own without going
  // through them all.
  std::vector<std::vector<Piece>> chunk_own;
  std::vector<int> chunk_first;
  std::vector<std::vector<Piece>> incoming;  // per block: springs from an earlier block to it
  std::vector<int> source;                   // per block: the earliest block those come from
  // Per block: the number of the last pass that has computed its springs (step 1 in
  // force_pass.hpp), which another thread waits for before taking their kept forces.
  std::vector<std::uint32_t> done;
  // Per block: the number of the last pass whose step 1 a thread has claimed (its run's owner, or
  // a thread whose step 2 needs it first: no thread ever waits for one that has not come).
  std::vector<std::uint32_t> started;
  std::uint32_t passes = 0;
  // Per thread: the blocks of its run not yet claimed for step 2, [front, back), with the pass
  // they belong to (force_pass.hpp: the owner takes them from the front, a thread that has
  // finished its own from the back).
  std::vector<std::uint64_t> runs;
  // Blocks swept by a thread other than their run's owner, over all passes: a test checks that
  // stealing happens and changes no bit.
  std::uint64_t stolen = 0;
};

struct SpringForces {
  std::vector<double> x, y, z;  // per spring: the force on its a-end, where buffered
  ForcePlan plan;
};

enum class ForceOutput {
  Acceleration,  // out = M^-1 f; zero for pinned particles
  Force,         // out = f
};

void evaluate_forces(const Model& model, const Points& x, const Points& v, Points& out,
                     SpringForces& buffer, ForceOutput what = ForceOutput::Acceleration);

// Threads used by the force loops (and every parallel loop of the core); 0 = all cores.
void set_thread_count(int threads);
int thread_count();
// The calling thread's parallel passes so far: run by the team of threads, run on it alone (after
// a wait for a helper that another program kept off its core, the team goes without helpers for a
// while: dynamics/threads.hpp), those waits, and the helpers' runs of work taken from them once
// they had stopped claiming it (stalls), and the passes run alone because the calling thread's
// own core was shared with another program (shared, among alone too); and, in the whole process,
// the times a helper found no pass to join within its spin and slept (sleeps: the next pass wakes
// it, tens of microseconds late).
struct TeamCounts {
  long team = 0, alone = 0, yields = 0, stalls = 0, shared = 0, sleeps = 0;
};
TeamCounts team_counts();

}  // namespace springlab
