// The local-global solver of Liu, Bargteil, O'Brien and Kavan 2013 ("Fast simulation of
// mass-spring systems"; for springs, projective dynamics: Bouaziz et al. 2014): the
// backward-Euler step of iterative.hpp minimised by alternating two exact minimisations.
//
//   local:   each spring's target  d_s = L u_s,  u_s = (x_b - x_a) / |x_b - x_a|
//   global:  (M~ + sum_s w_s A_s A_s^T) x = M~ y + sum_s w_s A_s t_s        w_s = h^2 k_s + h k_d
//            w_s t_s = h^2 k_s d_s + h k_d (e_s(x0) + P_s (e_s(x) - e_s(x0)))
//
// with e_s(x) = x_b - x_a, A_s the spring's +1 / -1 incidence, P_s = I - u_s u_s^T. The matrix is
// the same for x, y and z and for every iteration: factorised once (Eigen's SimplicialLDLT) and
// again only when h, a mass, a pin, k_s, k_d or the drag change. Iterations start from y.
//
// The notes' damping, k_d (u . (v_b - v_a)) u with v = (x1 - x0) / h, enters as the dissipation
// potential k_d / (2h) (u . de)^2 (iterative.hpp). Its matrix depends on u, which changes every
// iteration; so the constant matrix holds its isotropic part k_d / (2h) |de|^2, and the part across
// the spring, which the notes' model does not damp, is taken back on the right side with the
// current iterate's u (the P_s term). That part is at most the isotropic one, so the lagged
// iteration still contracts; converged, the step is the backward-Euler step of the notes' model.
// Drag is in M~ (m + h k_drag), exactly.
//
// Chebyshev acceleration (Wang 2015), with rho = settings.chebyshev_rho > 0:
//   x^(k+1) = omega_(k+1) (x^ - x^(k-1)) + x^(k-1),  x^ the plain iteration's result from x^k.
#include <algorithm>
#include <cmath>
#include <vector>

#include "iterative.hpp"
#include "springlab/error.hpp"
#include "springlab/spring_kernel.hpp"
#include "steps.hpp"

namespace springlab {

bool LocalGlobalSolver::Key::operator==(const Key& o) const {
  if (h != o.h || drag != o.drag || spans != o.spans || springs != o.springs || mass != o.mass ||
      inv_mass != o.inv_mass || materials.size() != o.materials.size())
    return false;
  for (std::size_t m = 0; m < materials.size(); ++m)
    if (materials[m].ks != o.materials[m].ks || materials[m].kd != o.materials[m].kd) return false;
  return true;
}

namespace {

double spring_weight(const SpringMaterial& m, double h) { return h * h * m.ks + h * m.kd; }

void factorise(const Model& model, double h, const std::vector<double>& mass, LocalGlobalSolver& S) {
  const int n = model.particle_count();
  S.row.assign(n, -1);
  S.free.clear();
  for (int i = 0; i < n; ++i)
    if (!model.pinned(i)) {
      S.row[i] = static_cast<int>(S.free.size());
      S.free.push_back(i);
    }
  const int rows = static_cast<int>(S.free.size());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(rows + 4 * model.spring_count());
  for (int r = 0; r < rows; ++r) entries.emplace_back(r, r, mass[S.free[r]]);
  for (int s = 0; s < model.spring_count(); ++s) {
    const double w = spring_weight(model.materials[model.spring_material[s]], h);
    if (w == 0.0) continue;
    const int ra = S.row[model.spring_a[s]], rb = S.row[model.spring_b[s]];
    if (ra >= 0) entries.emplace_back(ra, ra, w);
    if (rb >= 0) entries.emplace_back(rb, rb, w);
    if (ra >= 0 && rb >= 0) {
      entries.emplace_back(ra, rb, -w);
      entries.emplace_back(rb, ra, -w);
    }
  }
  Eigen::SparseMatrix<double> matrix(rows, rows);
  matrix.setFromTriplets(entries.begin(), entries.end());
  S.factor.compute(matrix);
  if (S.factor.info() != Eigen::Success)  // M~ > 0 makes it definite: only a bad mass gets here
    throw StepFailure("local-global: the global matrix could not be factorised (a zero or negative mass?)");
  S.factored = true;
  ++S.factorisations;
  S.rhs.resize(rows, 3);
  S.solution.resize(rows, 3);
}

// The right side of the global step from the iterate x (pinned rows of x hold their positions).
void global_rhs(const Model& model, const State& in, double h, const Points& x, const Points& y,
                const std::vector<double>& mass, LocalGlobalSolver& S) {
  const int rows = static_cast<int>(S.free.size());
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < rows; ++r) S.rhs(r, c) = mass[S.free[r]] * y(S.free[r], c);
  for (int s = 0; s < model.spring_count(); ++s) {
    const SpringMaterial& material = model.materials[model.spring_material[s]];
    const double w = spring_weight(material, h);
    if (w == 0.0) continue;
    const int a = model.spring_a[s], b = model.spring_b[s];
    const int ra = S.row[a], rb = S.row[b];
    if (ra < 0 && rb < 0) continue;
    const Vec3 e = (x.row(b) - x.row(a)).transpose();
    const Vec3 e0 = (in.x.row(b) - in.x.row(a)).transpose();
    const double l = e.norm(), rest = model.rest_length[s];
    const bool none = coincident(l, rest);  // no direction: no force, no damping
    const Vec3 u = none ? Vec3::Zero() : Vec3(e / l);
    const Vec3 d = none ? e : Vec3(rest * u);  // local step: the target at rest length
    const Vec3 de = e - e0;
    const Vec3 across = none ? de : Vec3(de - u * u.dot(de));
    const Vec3 wt = (h * h * material.ks) * d + (h * material.kd) * (e0 + across);
    if (rb >= 0) S.rhs.row(rb) += (ra >= 0 ? wt : Vec3(wt + w * x.row(a).transpose())).transpose();
    if (ra >= 0) S.rhs.row(ra) -= (rb >= 0 ? wt : Vec3(wt - w * x.row(b).transpose())).transpose();
  }
}

}  // namespace

namespace steps {

void local_global(const Model& model, const State& in, State& out, double h, const StepSettings& settings,
                  Workspace& ws) {
  if (!ws.iterative) ws.iterative = std::make_unique<IterativeSolvers>();
  IterativeSolvers& I = *ws.iterative;
  LocalGlobalSolver& S = I.local_global;
  iterative::predict(model, in, h, I.y, I.mass);

  LocalGlobalSolver::Key key{h, model.drag, model.mass, model.inv_mass, model.materials,
                             model.spans.data(), model.spring_count()};
  if (!S.factored || !(key == S.key)) {
    factorise(model, h, I.mass, S);
    S.key = std::move(key);
  }

  out.resize(in.particle_count());
  out.x = I.y;  // the first iterate; pinned rows stay at x + h v
  const double rho = settings.chebyshev_rho;
  if (rho > 0.0) S.previous = out.x;
  double omega = 1.0;
  const int iterations = iterative::iterations(settings, Method::LocalGlobal);
  for (int k = 1; k <= iterations; ++k) {
    global_rhs(model, in, h, out.x, I.y, I.mass, S);
    S.solution = S.factor.solve(S.rhs);
    if (rho > 0.0) {
      omega = chebyshev_omega(k, rho, omega);
      S.current = out.x;
      for (int c = 0; c < 3; ++c)
        for (std::size_t r = 0; r < S.free.size(); ++r) {
          const int i = S.free[r];
          out.x(i, c) = omega * (S.solution(r, c) - S.previous(i, c)) + S.previous(i, c);
        }
      S.previous.swap(S.current);
    } else {
      for (int c = 0; c < 3; ++c)
        for (std::size_t r = 0; r < S.free.size(); ++r) out.x(S.free[r], c) = S.solution(r, c);
    }
  }
  ws.counters.solver_iterations += iterations;
  ++ws.counters.linear_solves;
  iterative::finish(model, in, out, h);
}

}  // namespace steps
}  // namespace springlab
