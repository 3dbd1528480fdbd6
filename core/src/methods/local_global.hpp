// The parts of local_global.cpp's step, for the benchmark of its floor (bench/iterative_bench.cpp):
// one local pass and one pair of triangular solves are what an iteration cannot go below.
#pragma once

#include "iterative.hpp"

namespace springlab::local_global_parts {

// The factor's order for the rows' graph in compressed rows (vertex r's neighbours
// index[begin[r] .. begin[r + 1])): Eigen's AMD order, then a postorder of its elimination tree
// (solve_tree.hpp). Each row's place; by place, each row's parent in the tree (or -1) and work
// (its column's entries twice, and one).
struct FactorOrder {
  std::vector<int> place, parent;
  std::vector<double> work;
};
FactorOrder factor_order(const std::vector<int>& begin, const std::vector<int>& index);
// Factorises M~ + sum_s w_s A_s A_s^T for the step h (throws StepFailure if it cannot).
void factorise(const Model& model, double h, const std::vector<double>& mass, LocalGlobalSolver& S);
// Plans the solves and the right side's sums for the factor and the team the threads now have
// (LocalGlobalSolver::SolvePlan); factorise() does, and the step again when the team changes.
void plan(const Model& model, LocalGlobalSolver& S);
// The local pass: the right side of the global step for the correction x - y from the iterate X,
// into S.rhs.
void global_rhs(const Model& model, const State& in, double h, const Points& X, const Points& y,
                LocalGlobalSolver& S);
// The global solve: (L D L^T) z = z in place, the factor's order, x y z interleaved.
void solve_in_place(LocalGlobalSolver& S, std::vector<double>& z);

// (L D L^T) z = b in place, three right sides interleaved (x y z a row): each entry of L read
// once for all three, where Eigen's solve reads L once a column. L is unit lower triangular,
// `rows` compressed columns without the diagonal (SimplicialLDLT's: begin, index, value), D^-1
// in inv_d. In T: double in the solver; the benchmark also times float.
template <typename T>
void solve_ldlt3(int rows, const int* begin, const int* index, const T* value, const T* inv_d,
                 T* Z) {
  for (int j = 0; j < rows; ++j) {  // L y = b
    const T y0 = Z[3 * j], y1 = Z[3 * j + 1], y2 = Z[3 * j + 2];
    for (int p = begin[j]; p < begin[j + 1]; ++p) {
      T* r = Z + 3 * index[p];
      r[0] -= value[p] * y0, r[1] -= value[p] * y1, r[2] -= value[p] * y2;
    }
  }
  for (int j = 0; j < rows; ++j) {  // D w = y
    const T inv = inv_d[j];
    Z[3 * j] *= inv, Z[3 * j + 1] *= inv, Z[3 * j + 2] *= inv;
  }
  for (int j = rows - 1; j >= 0; --j) {  // L^T z = w
    T s0 = Z[3 * j], s1 = Z[3 * j + 1], s2 = Z[3 * j + 2];
    for (int p = begin[j]; p < begin[j + 1]; ++p) {
      const T* r = Z + 3 * index[p];
      s0 -= value[p] * r[0], s1 -= value[p] * r[1], s2 -= value[p] * r[2];
    }
    Z[3 * j] = s0, Z[3 * j + 1] = s1, Z[3 * j + 2] = s2;
  }
}

}  // namespace springlab::local_global_parts
