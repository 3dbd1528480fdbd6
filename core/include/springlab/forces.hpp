// Forces on every particle: springs, gravity and drag, gathered without races.
//
// One evaluation runs in two phases, each split evenly over the threads:
//   1. springs: each spring's force on its end a, into a per-spring buffer (no shared writes);
//   2. particles: each particle sums gravity, drag and the forces of the springs at its ends.
// Every particle's sum is taken in the same order whatever the number of threads (span by span,
// a-ends before b-ends), so results are bit-identical for any thread count.
#pragma once

#include <vector>

#include "springlab/model.hpp"
#include "springlab/state.hpp"

namespace springlab {

// Per-spring force on end a, structure of arrays; reused between evaluations.
struct SpringForces {
  std::vector<double> x, y, z;
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

}  // namespace springlab
