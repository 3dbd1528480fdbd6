// Implicit (backward) Euler, linearised once per step (Baraff and Witkin 1998): with
// K = df/dx and D = df/dv at the start of the step, solve
//   (M - h D - h^2 K) dv = h (f + h K v)
// then v1 = v + dv, x1 = x + h v1. The matrix is sparse (a 3x3 block per particle and per
// spring), symmetric and positive definite when K uses the definite spring Jacobian
// (spring_kernel.hpp), so conjugate gradients solve it. They start from the last step's dv,
// which is close once the motion is smooth, with a Jacobi preconditioner.
//
// Pinned particles keep dv = 0: their rows and columns are replaced by the identity, which is
// exact because their dv is known; their motion still enters through K v.
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <algorithm>
#include <vector>

#include "springlab/spring_kernel.hpp"
#include "steps.hpp"

namespace springlab {

struct ImplicitSolver {
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
  // The model the pattern was built for.
  int particles = -1;
  int springs = -1;
  const std::int32_t* spring_a = nullptr;

  Matrix A;
  // Where a block starts within each of its three rows (entries from the row's start; the three
  // rows of a block-row share one pattern).
  std::vector<int> diag;  // per particle: block (i, i)
  std::vector<int> ab;    // per spring: block (a, b), in block-row a
  std::vector<int> ba;    // per spring: block (b, a), in block-row b
  Eigen::VectorXd rhs, dv;
  Points f;
  Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper,
                           Eigen::DiagonalPreconditioner<double>>
      cg;

  bool matches(const Model& m) const {
    return particles == m.particle_count() && springs == m.spring_count() &&
           spring_a == m.spring_a.data();
  }

  void build_pattern(const Model& m) {
    particles = m.particle_count();
    springs = m.spring_count();
    spring_a = m.spring_a.data();
    const int n = particles;
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(9 * (n + 2 * springs));
    const auto block = [&](int i, int j) {
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) entries.emplace_back(3 * i + r, 3 * j + c, 0.0);
    };
    for (int i = 0; i < n; ++i) block(i, i);
    for (int s = 0; s < springs; ++s) {
      block(m.spring_a[s], m.spring_b[s]);
      block(m.spring_b[s], m.spring_a[s]);
    }
    A.resize(3 * n, 3 * n);
    A.setFromTriplets(entries.begin(), entries.end());  // sorted, compressed, zeros kept
    A.makeCompressed();
    const auto offset = [&](int i, int j) {
      const int* begin = A.innerIndexPtr() + A.outerIndexPtr()[3 * i];
      const int* end = A.innerIndexPtr() + A.outerIndexPtr()[3 * i + 1];
      return static_cast<int>(std::lower_bound(begin, end, 3 * j) - begin);
    };
    diag.resize(n);
    ab.resize(springs);
    ba.resize(springs);
    for (int i = 0; i < n; ++i) diag[i] = offset(i, i);
    for (int s = 0; s < springs; ++s) {
      ab[s] = offset(m.spring_a[s], m.spring_b[s]);
      ba[s] = offset(m.spring_b[s], m.spring_a[s]);
    }
    dv = Eigen::VectorXd::Zero(3 * n);
  }

  // A(block i, block at `offset` in its row) += scale * B
  void add(int i, int offset, const Eigen::Matrix3d& B, double scale) {
    double* values = A.valuePtr();
    const int* outer = A.outerIndexPtr();
    for (int r = 0; r < 3; ++r) {
      double* row = values + outer[3 * i + r] + offset;
      for (int c = 0; c < 3; ++c) row[c] += scale * B(r, c);
    }
  }
};

// Defined here, where ImplicitSolver is complete.
Workspace::Workspace() = default;
Workspace::~Workspace() = default;
Workspace::Workspace(Workspace&&) noexcept = default;
Workspace& Workspace::operator=(Workspace&&) noexcept = default;

namespace steps {

void implicit_euler(const Model& model, const State& in, State& out, double h,
                    const StepSettings& settings, Workspace& ws) {
  if (!ws.implicit) ws.implicit = std::make_unique<ImplicitSolver>();
  ImplicitSolver& S = *ws.implicit;
  if (!S.matches(model)) S.build_pattern(model);
  const int n = model.particle_count();

  evaluate_forces(model, in.x, in.v, S.f, ws.spring_forces, ForceOutput::Force);
  ++ws.counters.force_evals;

  // rhs = h f + h^2 K v, and A = M - h D - h^2 K.
  S.rhs.resize(3 * n);
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) S.rhs[3 * i + c] = h * S.f(i, c);
  std::fill(S.A.valuePtr(), S.A.valuePtr() + S.A.nonZeros(), 0.0);
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  for (int i = 0; i < n; ++i)
    S.add(i, S.diag[i], I, model.pinned(i) ? 1.0 : model.mass[i] + h * model.drag);
  for (int s = 0; s < model.spring_count(); ++s) {
    const int a = model.spring_a[s], b = model.spring_b[s];
    const Vec3 xa = in.x.row(a).transpose(), xb = in.x.row(b).transpose();
    const Vec3 va = in.v.row(a).transpose(), vb = in.v.row(b).transpose();
    const SpringJacobian J =
        spring_jacobian(xa, xb, va, vb, model.ks(s), model.kd(s), model.rest_length[s], true);
    const Vec3 Kv = J.dfdx * (vb - va);  // (K v)_a; (K v)_b = -(K v)_a
    const Eigen::Matrix3d B = h * J.dfdv + (h * h) * J.dfdx;
    const bool fa = !model.pinned(a), fb = !model.pinned(b);
    if (fa) {
      S.rhs.segment<3>(3 * a) += (h * h) * Kv;
      S.add(a, S.diag[a], B, 1.0);
    }
    if (fb) {
      S.rhs.segment<3>(3 * b) -= (h * h) * Kv;
      S.add(b, S.diag[b], B, 1.0);
    }
    if (fa && fb) {
      S.add(a, S.ab[s], B, -1.0);
      S.add(b, S.ba[s], B, -1.0);
    }
  }
  for (int i = 0; i < n; ++i)
    if (model.pinned(i)) {
      S.rhs.segment<3>(3 * i).setZero();
      S.dv.segment<3>(3 * i).setZero();
    }

  S.cg.setTolerance(settings.solver_tolerance);
  S.cg.compute(S.A);
  S.dv = S.cg.solveWithGuess(S.rhs, S.dv);
  ++ws.counters.linear_solves;
  ws.counters.solver_iterations += S.cg.iterations();
  if (S.cg.info() != Eigen::Success) ++ws.counters.unconverged_solves;

  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) out.v(i, c) = in.v(i, c) + S.dv[3 * i + c];
  out.x = in.x + h * out.v;
  out.t = in.t + h;
}

}  // namespace steps
}  // namespace springlab
