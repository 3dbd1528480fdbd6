// What XPBD, local-global and vertex block descent share. Each solves, exactly in the limit of
// its iterations or approximately, one backward-Euler step written as a minimisation (Martin et
// al. 2011, "Example-based elastic materials"; Liu et al. 2013):
//
//   x1 = argmin_x  sum_i m~_i / (2 h^2) |x_i - y_i|^2  +  E(x)  +  D(x),    v1 = (x1 - x) / h
//
//   E = sum_s k_s (|x_b - x_a| - L)^2 / 2                  the springs' energy
//   D = sum_s k_d / (2 h) (u_s . (dx_b - dx_a))^2           their damping, dx = x1 - x over the
//   step,
//                                                           u_s the spring's direction (lagged)
//
// Its stationary point is the backward-Euler step of the notes' model, f(x1, v1) with v1 =
// (x1 - x) / h, with two choices made here and said once:
//   - drag is implicit, through the mass: m~ = m + h k_drag, so that a large k_drag never
//     overshoots (m (v1 - v) / h = ... - k_drag (v1 - wind) solved for v1);
//   - gravity and the fields (attractors, swirl) are explicit, at the start of the step:
//     y = x + h v~,   v~ = (m v + h (m a_ext(x) + k_drag wind)) / m~.
// Pinned particles move with their prescribed velocity, x1 = x + h v, as in every method.
//
// Colliders act after the step, as for every method (Simulation::step).
#pragma once

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cstdint>
#include <vector>

#include "dynamics/threads.hpp"
#include "solve_tree.hpp"
#include "springlab/methods.hpp"

namespace springlab {

namespace iterative {

// f(begin, end) for the particles [begin, end) of n, in pieces of kPiece on the team
// (threads.hpp) where n is worth it: each particle's result its own, so the same bits for any
// thread count.
template <typename F>
void each_particle_piece(int n, const F& f) {
  constexpr int kPiece = 1024;
  threads::for_each_piece((n + kPiece - 1) / kPiece, n,
                          [&](int p) { f(p * kPiece, std::min(n, (p + 1) * kPiece)); });
}

// y and m~ above, for every particle (pinned ones: y = x + h v).
void predict(const Model& model, const State& in, double h, Points& y, std::vector<double>& mass);

// Writes x1 (already in out.x) into the state: v1 = (x1 - x) / h, pinned particles moved with
// their velocity, t advanced.
void finish(const Model& model, const State& in, State& out, double h);

}  // namespace iterative

// local_global.cpp: the prefactored global matrix and what it was made for.
struct LocalGlobalSolver {
  // What the factorisation depends on; compared each step (without copying), refactorised and
  // taken again when any differs.
  struct Key {
    double h = 0.0, drag = 0.0;
    std::vector<double> mass, inv_mass;
    std::vector<SpringMaterial> materials;
    const void* spans = nullptr;
    int springs = -1;
    bool matches(const Model& model, double step) const;
    void take(const Model& model, double step);
  } key;
  std::vector<int> factor_row;  // per particle: its row of the factor, or -1 (pinned)
  std::vector<int> row;         // per particle: its row's place in the solves (SolvePlan), or -1
  // The factor, of the matrix with its rows in a fill-reducing order of the solver's own
  // (local_global_solves.cpp, factor_order): Eigen's own ordering would not keep subtrees' rows
  // consecutive. `nodes`: its rows as blocks of the elimination tree (solve_tree.hpp).
  using Factor =
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>;
  Factor factor;
  std::vector<SolveTree::Node> nodes;
  std::vector<double> inv_d;  // 1 / D, D the factor's diagonal, by place (SolvePlan)
  bool factored = false;
  std::int64_t factorisations = 0;
  // One step of a row's forward sum (local_global_solves.cpp): the sum of the values of its
  // `children` steps before it, then of the row's entries [first, last) times their solutions;
  // or (slot >= 0) the value a piece's thread left in that slot.
  struct SumStep {
    int first = 0, last = 0, children = 0, slot = -1;
  };
  // The triangular solves' schedule, made with the factor (local_global_solves.cpp): the factor's
  // subtrees dealt to the team's threads, a piece each, and the blocks above them (the top),
  // solved after the pieces (forward) or before them (backward). The solves keep
  // each row at a place of its own (the pieces' rows in turn, then the top's: `row`, `inv_d` and
  // `rhs` are by place), and L by rows and by columns at those places.
  struct SolvePlan {
    std::vector<int> row_begin, row_index, col_begin, col_index;
    std::vector<double> row_value, col_value;
    // Each row's forward sum, its steps [sum_first[i], sum_first[i + 1]) of `sums`; then each
    // piece's sums for the top's rows, [job_first[k], job_first[k + 1]) of `jobs`.
    std::vector<int> sum_first;
    std::vector<SumStep> sums;
    struct Job {
      int first, last, slot;  // steps [first, last) of `sums`, their value into the slot
    };
    std::vector<Job> jobs;
    std::vector<int> job_first;
    int slots = 0, most_pending = 1;  // the partial sums' slots; the steps' most values pending
    std::vector<int> piece_first;     // piece k: places [piece_first[k], piece_first[k + 1])
    int top_first = 0;                // the top: places [top_first, rows)
    double piece_work = 0.0;          // the pieces' entries, both solves
    int asked = 0;                    // the threads it was made for (threads::max_team)
    int team = 0;                     // the threads it uses, as many as pay: a piece each
  } plan;
  // The solves' scratch (solve_in_place sizes it to the plan, once): the pieces' sums for the top's
  // rows (3 a slot), and a stack of pending sums for each piece and for the top, each on cache
  // lines of its own.
  std::vector<double> partial, stacks;
  // The top's rows one coordinate a thread (solve_top): each coordinate's rows, then its stack.
  std::vector<double> top;
  // Each particle's springs by row of the factor (compressed): spring s and +1 if the row is its
  // b end, -1 its a end; springs ascending, so that a row's sum takes them in the springs' order.
  std::vector<int> row_springs_first, row_springs;
  std::vector<double> rhs;   // the right side, then the solution: x y z a row, the factor's order
  std::vector<double> wt;    // each spring's w t: all x, all y, all z
  Points previous, current;  // Chebyshev: x^(k-1), x^k
};

// vbd.cpp: the vertex colouring and each vertex's springs.
struct VertexBlockDescent {
  const void* spans = nullptr;  // of the model the colouring was made for
  int particles = -1, springs = -1;
  // Each vertex's springs (compressed rows): spring index and the other end.
  std::vector<int> first, spring, other;
  // Vertices grouped by colour: colour c is order[colour_first[c] .. colour_first[c + 1]).
  std::vector<int> order, colour_first;
  std::vector<double>
      colour_work;  // a colour's vertices and their springs (threads::worth_threads)
};

// xpbd.cpp: the springs coloured so that no two of a colour share a particle, so that a colour's
// constraints are projected side by side (Gauss-Seidel colour by colour).
struct SpringColouring {
  const void* spans = nullptr;  // of the model the colouring was made for
  int particles = -1, springs = -1;
  // Springs grouped by colour, ascending in each: colour c is order[colour_first[c], [c + 1]).
  std::vector<int> order, colour_first;
  // What a projection reads of spring order[k], at k: its ends, material and rest length, in the
  // order a pass reads them (a colour's springs are every other one or sparser in the model's
  // arrays: read through `order`, each cache line brought half used or less).
  struct Spring {
    std::int32_t a, b, material;
    double rest;
  };
  std::vector<Spring> springs_in_order;
};

// What the three keep between steps, one Workspace's worth.
struct IterativeSolvers {
  Points y;                  // the inertial prediction
  std::vector<double> mass;  // m~
  std::vector<double>
      lambda;             // xpbd: each spring's Lagrange multiplier, at its place in the colouring
  std::vector<double> w;  // xpbd: each particle's 1 / m~, 0 if pinned
  // xpbd: each material's compliance a~ = 1 / (k_s h^2) and damping gamma = k_d / (k_s h)
  std::vector<double> compliance, gamma;
  LocalGlobalSolver local_global;
  VertexBlockDescent vbd;
  SpringColouring xpbd_colours;
};

// Greedy colouring of the particles so that no two of one colour share a spring (pinned ones
// too: a drag pins and unpins particles, the colouring stays). Deterministic: particles in index
// order, each the least colour its neighbours do not have. Returns the colours' first indices into
// `order`.
void colour_vertices(const Model& model, VertexBlockDescent& out);

// Greedy colouring of the springs so that no two of one colour share a particle (pinned ones too,
// as for the vertices). Deterministic: springs in index order, each the least colour neither of
// its ends' other springs has (at most 2 D - 1 colours, D the most springs at a particle).
void colour_springs(const Model& model, SpringColouring& out);

// Chebyshev semi-iterative acceleration (Wang 2015, "A Chebyshev semi-iterative approach for
// accelerating projective and position-based dynamics"), its weights:
//   omega_1 = 1,  omega_2 = 2 / (2 - rho^2),  omega_(k+1) = 4 / (4 - rho^2 omega_k)
// for iteration k (1-based), rho the estimated spectral radius of the plain iteration.
double chebyshev_omega(int k, double rho, double omega_before);

}  // namespace springlab
