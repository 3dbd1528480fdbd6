#include "stability/lanczos.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "stability/cancel.hpp"

namespace springlab {

namespace {

// Gershgorin's radius of row i of the k x k symmetric tridiagonal T: |beta_(i-1)| + |beta_i|.
double radius(const std::vector<double>& beta, int k, int i) {
  return (i > 0 ? std::abs(beta[i - 1]) : 0.0) + (i + 1 < k ? std::abs(beta[i]) : 0.0);
}

// The largest eigenvalue of the k x k symmetric tridiagonal T, at least `floor`, by bisection on
// Sturm counts: the pivots of T - x I = L D L^T,
//   d_0 = alpha_0 - x,  d_i = alpha_i - x - beta_{i-1}^2 / d_{i-1},
// have as many negatives as T has eigenvalues below x: all of them (T - x I negative definite)
// exactly when x is above lambda_max. O(k) a probe, full precision in at most ~64 probes; a QR
// sweep of T costs O(k^2) each time Lanczos asks: 1.3 s over a 1000-node rope's 1000 steps.
double largest_eigenvalue(const std::vector<double>& alpha, const std::vector<double>& beta, int k,
                          double floor) {
  double lo = floor, hi = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < k; ++i) {
    lo = std::max(lo, alpha[i]);  // lambda_max >= any diagonal entry
    hi = std::max(hi, alpha[i] + radius(beta, k, i));
  }
  const auto all_below = [&](double x) {
    double d = alpha[0] - x;
    for (int i = 1; i < k && d < 0.0; ++i) d = alpha[i] - x - beta[i - 1] * beta[i - 1] / d;
    return d < 0.0;
  };
  while (hi > lo) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;  // adjacent doubles
    (all_below(mid) ? hi : lo) = mid;
  }
  return hi;
}

// The eigenvector of T for its largest eigenvalue lambda, by inverse iteration: s <- (sigma I -
// T)^-1 s with sigma just above lambda. sigma I - T is then positive definite, so its LDL^T
// factors (O(k), no pivoting) are stable, and each solve shrinks the other components by
// delta / (lambda - lambda_j + delta). A full eigendecomposition of T costs O(k^3).
Eigen::VectorXd top_eigenvector(const std::vector<double>& alpha, const std::vector<double>& beta,
                                int k, double lambda) {
  double scale = 0.0;  // |T| (a bound)
  for (int i = 0; i < k; ++i) scale = std::max(scale, std::abs(alpha[i]) + radius(beta, k, i));
  // T = 0 (no stiffness anywhere, e.g. coincident ends): every vector is an eigenvector.
  if (!(scale > 0.0)) return Eigen::VectorXd::Unit(k, 0);
  const double sigma = lambda + 1e-10 * scale;
  // sigma I - T = L D L^T, L unit lower bidiagonal with l[i] below the diagonal in row i.
  std::vector<double> d(k), l(k, 0.0);
  d[0] = sigma - alpha[0];
  for (int i = 1; i < k; ++i) {
    l[i] = -beta[i - 1] / d[i - 1];
    d[i] = (sigma - alpha[i]) + l[i] * beta[i - 1];
  }
  // A start with every component (alternating signs favour the top of a chain's spectrum).
  Eigen::VectorXd s(k);
  for (int i = 0; i < k; ++i) s[i] = (i % 2 == 0 ? 1.0 : -1.0) * (1.0 + 0.5 * std::sin(i + 1.0));
  for (int iteration = 0; iteration < 4; ++iteration) {
    for (int i = 1; i < k; ++i) s[i] -= l[i] * s[i - 1];           // L y = s
    for (int i = 0; i < k; ++i) s[i] /= d[i];                      // D z = y
    for (int i = k - 2; i >= 0; --i) s[i] -= l[i + 1] * s[i + 1];  // L^T s = z
    s /= s.cwiseAbs().maxCoeff();  // first to about 1: |s|^2 of a huge s would overflow
    s /= s.norm();
  }
  return s;
}

// The calling thread's array of kept Lanczos vectors (uninitialised: a run writes each vector
// before it reads it), and whether a run is using it.
struct KeptVectors {
  std::unique_ptr<double[]> data;
  std::size_t capacity = 0;
  double* reserve(std::size_t size) {
    if (size > capacity) {
      data.reset();  // the old array first: both at once could double the peak
      capacity = 0;  // (and none, should the new one throw)
      data.reset(new double[size]);
      capacity = size;
    }
    return data.get();
  }
};
thread_local KeptVectors g_kept;
thread_local bool g_kept_in_use = false;

// Marks the thread's array in use for the run's lifetime (a nested run leaves it alone).
struct InUse {
  bool nested;
  explicit InUse(bool n) : nested(n) {
    if (!nested) g_kept_in_use = true;
  }
  ~InUse() {
    if (!nested) g_kept_in_use = false;
  }
  InUse(const InUse&) = delete;
  InUse& operator=(const InUse&) = delete;
};

}  // namespace

void release_lanczos_memory() {
  if (!g_kept_in_use) g_kept = KeptVectors{};
}

// Long: the run and its second pass (the vector made again where it was not kept) share the three
// rotating vectors, the kept array and the step (lanczos_step); apart, each would take all of them.
TopEigenpair top_eigenpair(const SymmetricOperator& apply, const Points& start, int max_steps,
                           double tolerance) {
  TopEigenpair result;
  const Eigen::Index n = start.rows();
  const double start_norm = start.norm();
  if (!(start_norm > 0.0)) {
    result.vector = start;
    return result;
  }

  // The Lanczos vectors are kept while they fit in 64 MB (the second pass then sums them);
  // beyond that the second pass makes them again. They go one after another, column by column,
  // into the thread's own array (lanczos.hpp), room for all of them made at once; a run started
  // from inside another's `apply` on the same thread has an array of its own.
  const long keep = std::clamp<long>((64L << 20) / std::max<long>(1, 24L * n), 0, max_steps);
  KeptVectors own;
  const bool nested = g_kept_in_use;
  const InUse in_use(nested);
  double* const kept =
      (nested ? own : g_kept)
          .reserve(static_cast<std::size_t>(keep) * 3 * static_cast<std::size_t>(n));
  const auto kept_column = [&](long k, int c) {
    return Eigen::Map<Eigen::VectorXd>(kept + (3 * k + c) * n, n);
  };

  // Three vectors in rotation: q_(k-1), q_k and y = B q_k. A step is three passes over them:
  // alpha = q_k . y; then y -= alpha q_k + beta_(k-1) q_(k-1) and beta = |y|, a column at a
  // time; then q_(k+1) = y / beta, in q_(k-1)'s place and the kept array (five passes before,
  // and a copy into the array). `written` counts the kept columns: a step whose beta is not
  // positive (0, or NaN from a NaN in the operator) writes none.
  Points buffers[2] = {Points(n, 3), Points(n, 3)}, y(n, 3);
  long written = 0;
  Points* q = &buffers[0];
  Points* q_prev = &buffers[1];
  const auto lanczos_step = [&](long k, double beta_prev, double& alpha, double& beta) {
    apply(*q, y);
    alpha = 0.0;
    for (int c = 0; c < 3; ++c) alpha += q->col(c).dot(y.col(c));
    double squared = 0.0;
    for (int c = 0; c < 3; ++c) {
      y.col(c) -= alpha * q->col(c) + beta_prev * q_prev->col(c);
      squared += y.col(c).squaredNorm();
    }
    beta = std::sqrt(squared);
    std::swap(q, q_prev);
    if (!(beta > 0.0)) return;
    const bool keeping = k + 1 < keep;
    for (int c = 0; c < 3; ++c) {
      q->col(c) = y.col(c) / beta;
      if (keeping) kept_column(k + 1, c) = q->col(c);
    }
    if (keeping) written = k + 2;
  };
  const auto begin = [&] {
    *q = start / start_norm;
    q_prev->setZero();
  };

  std::vector<double> alpha, beta;
  double lambda = -std::numeric_limits<double>::infinity(), scale = 0.0, last = lambda;
  begin();
  if (keep > 0) {
    for (int c = 0; c < 3; ++c) kept_column(0, c) = q->col(c);
    written = 1;
  }
  for (int k = 0; k < max_steps; ++k) {
    if (k % 32 == 0) check_cancel();
    double a = 0.0, b = 0.0;
    lanczos_step(k, beta.empty() ? 0.0 : beta.back(), a, b);
    alpha.push_back(a);
    beta.push_back(b);
    result.steps = k + 1;
    scale = std::max(scale, std::abs(a) + b + (k > 0 ? beta[k - 1] : 0.0));
    // T's largest eigenvalue costs up to 64 passes over T: looked at every step at first, then
    // every eighth.
    if (k >= 16 && k % 8 != 7 && b > 0.0 && k + 1 < max_steps) continue;
    // T_k's largest eigenvalue is never below T_(k-1)'s (they interlace).
    lambda = largest_eigenvalue(alpha, beta, k + 1, lambda);
    // The Ritz pair's residual |B y - theta y| is beta_k |s_k|, s the eigenvector of T: small,
    // it is an eigenpair of B (a value that merely stalls for a while is not). beta = 0: the
    // steps span an invariant subspace, and T's eigenvalues are exact.
    // Where the top is a tight cluster (a long chain's fastest modes) the residual falls slowly
    // while the value no longer moves: a value unchanged since the last look, with a residual
    // under 1e-5, is taken too (a mix of the cluster's vectors is as good as any of them).
    const double tail = b * std::abs(top_eigenvector(alpha, beta, k + 1, lambda)[k]);
    result.converged = b <= 1e-14 * scale || tail <= tolerance * scale ||
                       (std::abs(lambda - last) <= 1e-14 * scale && tail <= 1e-5 * scale);
    last = lambda;
    if (result.converged) break;
  }
  result.value = lambda;

  // The vector, sum_j s_j q_j with s the top eigenvector of T: from the kept vectors, or the
  // same steps again.
  const int steps = result.steps;
  const Eigen::VectorXd s = top_eigenvector(alpha, beta, steps, lambda);
  Points vector = Points::Zero(n, 3);
  if (steps <= written) {
    for (int k = 0; k < steps; ++k)
      for (int c = 0; c < 3; ++c) vector.col(c) += s[k] * kept_column(k, c);
  } else {
    begin();
    for (int k = 0; k < steps; ++k) {
      vector += s[k] * *q;
      if (k + 1 < steps) {
        double a = 0.0, b = 0.0;
        lanczos_step(keep, k == 0 ? 0.0 : beta[k - 1], a, b);  // (keep: no more kept)
      }
    }
  }
  const double norm = vector.norm();
  result.vector = norm > 0.0 ? Points(vector / norm) : vector;
  return result;
}

}  // namespace springlab
