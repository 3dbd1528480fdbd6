// The backward-Euler step solved to convergence, as a diagonally implicit tableau's stage needs it
// (tableau_steps.cpp): Newton's method on
//   G(V) = M (V - v) - h f(x + h V, V) = 0
// with its true Jacobian, J = M - h df/dv - h^2 df/dx (the springs' exact blocks: a compressed
// spring's negative transverse stiffness and the damping's dependence on position included; drag;
// attractors), which is not symmetric, factorised by Eigen's SparseLU; so the iteration converges
// quadratically, where the definite Jacobian the linearised step uses (implicit_euler.cpp) made it
// linear and let it stall on a compressed cloth.
#pragma once

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <cstdint>
#include <vector>

#include "springlab/forces.hpp"
#include "springlab/methods.hpp"
#include "springlab/model.hpp"
#include "springlab/state.hpp"

namespace springlab::steps {

// What a stage's Newton iteration keeps between solves: the Jacobian's sparsity is the springs'
// (a 3 x 3 block a particle and a pair a spring, pinned or not), analysed once for a model.
struct NewtonSolver {
  Eigen::SparseMatrix<double> J;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  // The definite Jacobian's (symmetric: its lower half read), where Newton's direction fails.
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> definite;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd g, dv;
  Points f;
  SpringForces spring_forces;
  int analysed_particles = -1,
      analysed_springs = -1;  // the pattern the factorisation was analysed for
  // The factorisation held: of J at some earlier iterate, for a step of `factored_h` (Hairer and
  // Wanner's simplified Newton: kept while corrections contract it well, made again when not).
  double factored_h = 0.0;
  bool factored = false;
  std::int64_t factorisations = 0;
};

// Backward Euler from `in` by h into `out`, solved to convergence: the linearised step (the
// implicit-euler row's, with `settings`) as the first guess, then Newton's corrections (with the
// last factorisation of J while each correction cuts the residual at least threefold, else J
// factorised afresh at the iterate: the simplified Newton of Hairer and Wanner) until every
// free particle's |G_i| is within 1e-12 of its scale, h times the largest force, or its own
// momentum change (and above rounding). `corrections`, if given, is increased by the corrections
// made; ws.counters.newton_corrections too. Throws SolveFailure ("the equations were not solved")
// when 16 corrections do not converge: the method is not unstable, its equations were not solved.
void backward_euler_converged(const Model& model, const State& in, State& out, double h,
                              const StepSettings& settings, Workspace& ws, NewtonSolver& newton,
                              int* corrections = nullptr);

// J = dG/dV at the iterate (X, V) = (x + h V, V) for a step of h, as the corrections use it (for
// the tests, against finite differences of G).
Eigen::SparseMatrix<double> stage_jacobian(const Model& model, const Points& X, const Points& V,
                                           double h);

}  // namespace springlab::steps
