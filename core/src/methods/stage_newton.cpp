// Backward Euler solved to convergence by Newton's method with its true Jacobian
// (stage_newton.hpp).
//
//   G(V) = M (V - v) - h f(X, V),  X = x + h V
//   J = dG/dV = M - h df/dv - h^2 df/dx
// assembled from each spring's exact blocks (spring_kernel.hpp, spring_jacobian with definite =
// false: f_a's derivatives with respect to the b end; the other three blocks follow from f_b = -f_a
// and f depending on differences), the drag's -k_drag I and each attractor's m da/dx. A pinned
// particle's row and column are the identity's: its velocity is prescribed. The matrix is not
// symmetric (the damping's dependence on position, the swirl of a vortex) and, on a compressed
// spring at a large step, not definite, so it is factorised by SparseLU (its pattern analysed
// once for a model's springs).
//
// G is, to the damping's turning with the springs, the gradient of the incremental potential
//   Phi(V) = 1/2 (V - v)^T M (V - v) + E(X) + h R(V)
// (E: the springs', gravity's and the attractors' potential; R: the drag's and the springs'
// dissipation, 1/2 k_drag |V - wind|^2 + 1/2 k_d ((V_b - V_a) . u)^2), whose minimum is the step.
// A correction is Newton's, -J^-1 G, where that lowers Phi (where J is definite enough: a stable
// stage); else the definite Jacobian's (the compressed springs' transverse stiffness clamped, the
// damping's turning dropped, as the linearised step has it; factorised by Cholesky), which always
// does: a buckled cloth or a jelly landing at one step a frame is still solved. Each is taken
// whole where it halves |G| (near the root, where Newton converges quadratically), else as far as
// Armijo's rule on Phi allows. A factorisation is kept from correction to correction, stage to
// stage and step to step while each correction with it cuts |G| at least threefold (Hairer and
// Wanner, "Solving ODEs II", IV.8: the simplified Newton iteration), and made afresh at the current
// iterate when not.
#include "stage_newton.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "springlab/fields.hpp"
#include "springlab/spring_kernel.hpp"
#include "steps.hpp"

namespace springlab::steps {

namespace {

constexpr double kNewtonTolerance = 1e-12;
constexpr int kMaxCorrections = 50, kMaxHalvings = 30;
constexpr double kEps = std::numeric_limits<double>::epsilon();

Eigen::Vector3d row(const Points& p, int i) {
  return p.row(i).transpose();
}

void add_block(std::vector<Eigen::Triplet<double>>& t, int r, int c, const Eigen::Matrix3d& B) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t.emplace_back(3 * r + i, 3 * c + j, B(i, j));
}

// J at (X, V), or with `definite` the definite Jacobian. Every spring's four blocks are entered,
// zero where a pinned particle's row or column is, so that the pattern depends on the springs alone
// (a drag pins and unpins particles).
void assemble(const Model& model, const Points& X, const Points& V, double h, bool definite,
              std::vector<Eigen::Triplet<double>>& entries, Eigen::SparseMatrix<double>& J) {
  const int n = model.particle_count();
  entries.clear();
  entries.reserve(static_cast<std::size_t>(9 * (n + 4 * model.spring_count())));
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  for (int i = 0; i < n; ++i) {
    if (model.pinned(i)) {
      add_block(entries, i, i, I);
      continue;
    }
    Eigen::Matrix3d B = (model.mass[i] + h * model.drag) * I;
    if (!definite)
      for (const Attractor& a : model.attractors)
        B -= h * h * model.mass[i] * field_jacobian(a, row(X, i));
    add_block(entries, i, i, B);
  }
  const Eigen::Matrix3d Z = Eigen::Matrix3d::Zero();
  for (int s = 0; s < model.spring_count(); ++s) {
    const int a = model.spring_a[s], b = model.spring_b[s];
    const SpringJacobian d =
        spring_jacobian(row(X, a), row(X, b), row(V, a), row(V, b), model.ks(s), model.kd(s),
                        model.rest_length[s], definite);
    const Eigen::Matrix3d K = h * d.dfdv + h * h * d.dfdx;
    const bool pa = model.pinned(a), pb = model.pinned(b);
    add_block(entries, a, a, pa ? Z : K);
    add_block(entries, b, b, pb ? Z : K);
    add_block(entries, a, b, pa || pb ? Z : Eigen::Matrix3d(-K));
    add_block(entries, b, a, pa || pb ? Z : Eigen::Matrix3d(-K));
  }
  J.resize(3 * n, 3 * n);
  J.setFromTriplets(entries.begin(), entries.end());
}

// Phi at `out` (the header comment's), summed in a fixed order.
double incremental_potential(const Model& model, const State& in, const State& out, double h) {
  double phi = 0.0;
  for (int i = 0; i < model.particle_count(); ++i) {
    if (model.pinned(i)) continue;
    const Eigen::Vector3d X = row(out.x, i), V = row(out.v, i);
    phi += 0.5 * model.mass[i] * (V - row(in.v, i)).squaredNorm();
    phi -= model.mass[i] * model.gravity.dot(X);
    for (const Attractor& a : model.attractors) phi += model.mass[i] * field_potential(a, X);
    phi += 0.5 * h * model.drag * (V - model.wind).squaredNorm();
  }
  for (int s = 0; s < model.spring_count(); ++s) {
    const int a = model.spring_a[s], b = model.spring_b[s];
    const Eigen::Vector3d d = row(out.x, b) - row(out.x, a);
    const double l = d.norm();
    phi += 0.5 * model.ks(s) * (l - model.rest_length[s]) * (l - model.rest_length[s]);
    if (model.kd(s) != 0.0 && l > 0.0) {
      const double rate = (row(out.v, b) - row(out.v, a)).dot(d / l);
      phi += 0.5 * h * model.kd(s) * rate * rate;
    }
  }
  return phi;
}

}  // namespace

Eigen::SparseMatrix<double> stage_jacobian(const Model& model, const Points& X, const Points& V,
                                           double h) {
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::SparseMatrix<double> J;
  assemble(model, X, V, h, false, entries, J);
  return J;
}

namespace {

// One stage's iteration: the iterate `out`, G and the merits at it, and the ways down.
struct Iteration {
  Iteration(const Model& m, const State& start_state, State& iterate, double step, Workspace& w,
            NewtonSolver& solver)
      : model(m), in(start_state), out(iterate), h(step), ws(w), N(solver) {}
  const Model& model;
  const State& in;
  State& out;
  double h;
  Workspace& ws;
  NewtonSolver& N;
  int n = model.particle_count();
  bool converged = false;
  double residual = 0.0;   // the largest |G_i|
  double tolerance = 0.0;  // the largest particle's, for the message
  double merit = 0.0;      // |G|
  Points start;            // where a correction starts from

  // G at `out`, its forces in N.f; the largest |G_i| against its own tolerance: 1e-12 max(h F,
  // m_i |V_i - v_i|) above its rounding floor, 64 eps times its terms' sizes (a particle's force
  // sums a dozen springs' and more), m_i (|V_i| + |v_i|), h R and h k_max (|X_i| + h |V_i|). F is
  // the force scale (the largest spring tension k_s |l - L|, weight m |g| or net force), R =
  // max k_s l the size spring forces are rounded at.
  void measure() {
    evaluate_forces(model, out.x, out.v, N.f, N.spring_forces, ForceOutput::Force);
    ++ws.counters.force_evals;
    double scale = 0.0, rounding = 0.0, largest = 0.0, stiffest = 0.0;
    for (int s = 0; s < model.spring_count(); ++s) {
      const double l = (out.x.row(model.spring_b[s]) - out.x.row(model.spring_a[s])).norm();
      scale = std::max(scale, model.ks(s) * std::abs(l - model.rest_length[s]));
      rounding = std::max(rounding, model.ks(s) * std::max(l, model.rest_length[s]));
      stiffest = std::max(stiffest, model.ks(s));
    }
    for (int i = 0; i < n; ++i)
      if (!model.pinned(i))
        scale = std::max({scale, model.mass[i] * model.gravity.norm(), N.f.row(i).norm()});
    converged = true;
    tolerance = 0.0;
    N.g.resize(3 * n);
    for (int i = 0; i < n; ++i) {
      if (model.pinned(i)) {
        N.g.segment<3>(3 * i).setZero();
        continue;
      }
      const Eigen::Vector3d gi = model.mass[i] * (row(out.v, i) - row(in.v, i)) - h * row(N.f, i);
      N.g.segment<3>(3 * i) = gi;
      const double change = model.mass[i] * (out.v.row(i) - in.v.row(i)).norm();
      const double speed = out.v.row(i).norm();
      const double floor = 64.0 * kEps *
                           (model.mass[i] * (speed + in.v.row(i).norm()) + h * rounding +
                            h * stiffest * (out.x.row(i).norm() + h * speed));
      largest = std::max(largest, gi.norm());
      const double allowed = kNewtonTolerance * std::max(h * scale, change) + floor;
      if (!(gi.norm() <= allowed)) converged = false;
      tolerance = std::max(tolerance, allowed);
    }
    const bool finite = std::isfinite(largest);
    merit = finite ? N.g.norm() : std::numeric_limits<double>::infinity();
    residual = finite ? largest : std::numeric_limits<double>::infinity();
  }

  [[noreturn]] void fail(const char* why) const {
    char what[320];
    std::snprintf(what, sizeof what,
                  "the equations were not solved: Newton's iteration %s (largest residual %.3g N s "
                  "against a tolerance of "
                  "%.3g, h = %.3g s)",
                  why, residual, tolerance, h);
    throw SolveFailure(what);
  }

  // The iterate moved by t d from `start`.
  void move(const Eigen::VectorXd& d, double t) {
    for (int i = 0; i < n; ++i)
      if (!model.pinned(i)) out.v.row(i) = start.row(i) + t * d.segment<3>(3 * i).transpose();
    out.x = in.x + h * out.v;
  }

  // Takes the longest of d, d/2, d/4, ... (up to 2^-halvings) from `start` that lowers the merit
  // by Armijo's rule: |G| (along Newton's direction |G| falls at the rate |G| itself, wherever J
  // is not singular) or Phi (along the definite Jacobian's direction Phi falls at the rate
  // G . d < 0, to a minimum where G = 0). Returns whether it moved (the iterate restored if not).
  enum class Merit { Residual, Potential };
  bool search(const Eigen::VectorXd& d, Merit by, int halvings) {
    const double slope = N.g.dot(d);  // dPhi/dt at t = 0: G is Phi's gradient
    if (by == Merit::Potential && !(slope < 0.0)) return false;
    const double merit_start = merit;
    const double phi_start =
        by == Merit::Potential ? incremental_potential(model, in, out, h) : 0.0;
    double t = 1.0;
    for (int halving = 0; halving <= halvings; ++halving, t *= 0.5) {
      move(d, t);
      measure();
      if (converged) return true;
      if (by == Merit::Residual
              ? merit <= (1.0 - 1e-4 * t) * merit_start
              : incremental_potential(model, in, out, h) <= phi_start + 1e-4 * t * slope)
        return true;
    }
    move(d, 0.0);
    measure();
    return false;
  }

  // J factorised at the iterate (its pattern analysed once for the model's springs).
  void factorise() {
    assemble(model, out.x, out.v, h, false, N.entries, N.J);
    if (N.analysed_particles != n || N.analysed_springs != model.spring_count()) {
      N.lu.analyzePattern(N.J);
      N.definite.analyzePattern(N.J);
      N.analysed_particles = n;
      N.analysed_springs = model.spring_count();
    }
    N.lu.factorize(N.J);
    N.factored = N.lu.info() == Eigen::Success;
    N.factored_h = h;
    ++N.factorisations;
  }

  // The definite Jacobian's direction down Phi as far as Armijo's rule allows; else, as little
  // as it takes to lower |G|, Newton's (`newton`, when the LU held is fresh) or the definite one.
  bool descend(const Eigen::VectorXd& newton, bool fresh) {
    assemble(model, out.x, out.v, h, true, N.entries, N.J);
    N.definite.factorize(N.J);
    if (N.definite.info() != Eigen::Success) fail("met a singular Jacobian");
    N.dv = N.definite.solve(-N.g);
    const bool moved = search(N.dv, Merit::Potential, kMaxHalvings) ||
                       (fresh && search(newton, Merit::Residual, kMaxHalvings)) ||
                       search(N.dv, Merit::Residual, kMaxHalvings);
    N.factored = false;  // (the LU held is of the point Newton's direction failed at)
    return moved;
  }

  // One correction; false where it made none (a kept factorisation to be made afresh).
  bool correct() {
    const double before = merit;
    start = out.v;
    const bool exact = !N.factored;
    if (exact) factorise();
    // Newton's direction, taken at least a sixteenth of the way; else (J indefinite or near
    // singular: a buckled or crushed stage) the definite Jacobian's, down Phi (descend).
    bool moved = false;
    if (N.factored) {
      N.dv = N.lu.solve(-N.g);
      moved = search(N.dv, Merit::Residual, 4);
    }
    if (!moved && !exact) {
      N.factored = false;  // a kept factorisation that gives no good way down
      return false;
    }
    if (!moved) moved = descend(Eigen::VectorXd(N.dv), N.factored);
    if (!moved) {
      // No direction lowers either merit: as good as doubles make it, or stuck at a kink.
      if (residual <= 1e3 * tolerance)
        converged = true;
      else
        fail("found no correction that lowers the residual (a spring through zero length?)");
    }
    // A kept factorisation that no longer cuts |G| threefold is made afresh next time.
    if (!exact && !(merit <= before / 3.0)) N.factored = false;
    // An exact correction that no longer halves |G| has reached rounding (Newton's would square
    // it): where that is within a thousand times the tolerance, solved as well as doubles solve it.
    if (exact && !converged && !(merit <= 0.5 * before) && residual <= 1e3 * tolerance)
      converged = true;
    return true;
  }
};

}  // namespace

void backward_euler_converged(const Model& model, const State& in, State& out, double h,
                              const StepSettings& settings, Workspace& ws, NewtonSolver& N,
                              int* corrections) {
  // The first guess: the linearised step (Baraff and Witkin's, the implicit-euler row's), its
  // conjugate gradients to 1e-4 only: the corrections take it from there.
  StepSettings guess = settings;
  guess.solver_tolerance = std::max(settings.solver_tolerance, 1e-4);
  implicit_euler(model, in, out, h, guess, ws);
  Iteration it(model, in, out, h, ws, N);
  it.measure();
  // A factorisation of another model or step is of no use.
  if (N.analysed_particles != it.n || N.analysed_springs != model.spring_count() ||
      N.factored_h != h)
    N.factored = false;
  for (int k = 0; !it.converged; ++k) {
    if (!std::isfinite(it.residual)) it.fail("met a non-finite force");
    if (k == kMaxCorrections) {
      char why[64];
      std::snprintf(why, sizeof why, "did not converge in %d corrections", kMaxCorrections);
      it.fail(why);
    }
    ++ws.counters.newton_corrections;
    if (corrections) ++*corrections;
    it.correct();
  }
}

}  // namespace springlab::steps
