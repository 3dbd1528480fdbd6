// The largest eigenvalue of a symmetric operator and its eigenvector, by Lanczos iteration: after
// k products the largest eigenvalue of the k x k tridiagonal T (alpha on the diagonal, beta
// beside it) is a lower bound on the operator's that converges in far fewer products than a
// power iteration (tens to hundreds on a cloth, whose top modes crowd together). No
// reorthogonalisation: lost orthogonality only repeats converged eigenvalues, and the largest is
// still right. The eigenvector is summed from the Lanczos vectors, kept while they fit in 64 MB
// and else made again by a second pass over the same recurrence. The kept vectors live in the
// calling thread's own array from one run to the next (fresh memory for each run, tens of MB on
// a 128 x 128 cloth, cost more in page faults and copies than the products did), until
// release_lanczos_memory().
#pragma once

#include <functional>

#include "springlab/state.hpp"

namespace springlab {

struct TopEigenpair {
  double value = 0.0;
  Points vector;  // unit length
  int steps = 0;  // products of the first pass
  bool converged = false;
};

// y = B x for a symmetric B; `start` (any nonzero vector, e.g. the eigenvector of a nearby
// operator: a good start converges in a few steps). Stops when the Ritz pair's residual is at
// most `tolerance` relative to the operator's size (or the steps span an invariant subspace),
// or after max_steps.
using SymmetricOperator = std::function<void(const Points& x, Points& y)>;
TopEigenpair top_eigenpair(const SymmetricOperator& apply, const Points& start, int max_steps,
                           double tolerance = 1e-12);

// Frees the calling thread's array of kept vectors (an analysis does when it ends).
void release_lanczos_memory();

}  // namespace springlab
