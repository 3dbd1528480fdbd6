// The local-global solver of Liu, Bargteil, O'Brien and Kavan 2013 ("Fast simulation of
// mass-spring systems"; for springs, projective dynamics: Bouaziz et al. 2014): the
// backward-Euler step of iterative.hpp minimised by alternating two exact minimisations.
//
//   local:   each spring's target  d_s = L u_s,  u_s = (x_b - x_a) / |x_b - x_a|
//   global:  (M~ + sum_s w_s A_s A_s^T) x = M~ y + sum_s w_s A_s t_s        w_s = h^2 k_s + h k_d
//            w_s t_s = h^2 k_s d_s + h k_d (e_s(x0) + P_s (e_s(x) - e_s(x0)))
//
// with e_s(x) = x_b - x_a, A_s the spring's +1 / -1 incidence, P_s = I - u_s u_s^T. The matrix is
// the same for x, y and z and for every iteration: factorised once (Eigen's SimplicialLDLT, its
// triangular solves shared by a team of threads along its elimination tree:
// local_global_solves.cpp) and again only when h, a mass, a pin, k_s, k_d or the drag change.
// Iterations start from y.
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
#include "local_global.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "dynamics/threads.hpp"
#include "springlab/error.hpp"
#include "springlab/iterative_cost.hpp"
#include "springlab/spring_kernel.hpp"
#include "steps.hpp"

namespace springlab {

bool LocalGlobalSolver::Key::matches(const Model& model, double step) const {
  if (h != step || drag != model.drag || spans != model.spans.data() ||
      springs != model.spring_count() || mass != model.mass || inv_mass != model.inv_mass ||
      materials.size() != model.materials.size())
    return false;
  for (std::size_t m = 0; m < materials.size(); ++m)
    if (materials[m].ks != model.materials[m].ks || materials[m].kd != model.materials[m].kd)
      return false;
  return true;
}

void LocalGlobalSolver::Key::take(const Model& model, double step) {
  h = step;
  drag = model.drag;
  mass = model.mass;
  inv_mass = model.inv_mass;
  materials = model.materials;
  spans = model.spans.data();
  springs = model.spring_count();
}

namespace local_global_parts {

// The local step for `count` springs of a span (spring k joins a0 + k and b0 + k), from the
// iterate x, the start x0 and the prediction y: each spring's term of the right side, w t - w e(y)
// (global_rhs), x y z in wx, wy, wz. Plain arrays along the span, without branches, so that it
// vectorises (y's differences read along the span too, not gathered spring by spring).
void span_targets(const double* const x[3], const double* const x0[3], const double* const y[3],
                  int a0, int b0, int count, double ks, double kd, double rest, double h,
                  double* __restrict wx, double* __restrict wy, double* __restrict wz) {
  const double k_s = h * h * ks, k_d = h * kd, w = k_s + k_d, near = coincident_length(rest);
  SPRINGLAB_VECTORISE
  for (int k = 0; k < count; ++k) {
    const double ex = x[0][b0 + k] - x[0][a0 + k], ey = x[1][b0 + k] - x[1][a0 + k],
                 ez = x[2][b0 + k] - x[2][a0 + k];
    const double fx = x0[0][b0 + k] - x0[0][a0 + k], fy = x0[1][b0 + k] - x0[1][a0 + k],
                 fz = x0[2][b0 + k] - x0[2][a0 + k];
    const double l = std::sqrt(ex * ex + ey * ey + ez * ez);
    // Coincident ends have no direction: no force (d = e) and no damping (P de = de).
    const bool none = l <= near;
    const double inv = none ? 0.0 : 1.0 / l;
    const double ux = ex * inv, uy = ey * inv, uz = ez * inv;
    const double along = ux * (ex - fx) + uy * (ey - fy) + uz * (ez - fz);  // u . de
    const double target = none ? 1.0 : rest * inv;                          // d = target e
    // w t = k_s d + k_d (e0 + P de), e0 + P de = e - u (u . de); then less w e(y)
    const double tx = k_s * target * ex + k_d * (ex - ux * along);
    const double ty = k_s * target * ey + k_d * (ey - uy * along);
    const double tz = k_s * target * ez + k_d * (ez - uz * along);
    wx[k] = tx - w * (y[0][b0 + k] - y[0][a0 + k]);
    wy[k] = ty - w * (y[1][b0 + k] - y[1][a0 + k]);
    wz[k] = tz - w * (y[2][b0 + k] - y[2][a0 + k]);
  }
}

// The right side of the global step for the correction z = x - y from the prediction y (the
// file's header with x = y + z):
//   (M~ + sum_s w_s A_s A_s^T) z = sum_s A_s (w_s t_s - w_s e_s(y)),
// each spring's term made from its own differences and added to one end's row and taken from
// the other's. Its rows sum to zero to rounding of the springs' terms, not of the positions:
// solved for x itself, a body 2 m from the origin lost 1e-8 of its momentum over a throw to the
// solve's rounding of |x| (a free body keeps sum M~ x = sum M~ y exactly, momentum.hpp). From the
// iterate X (pinned rows hold their positions, which are y's), into S.rhs in the factor's order:
// each spring's w t - w e(y) (span by span, in parallel: each spring's own numbers), then each
// row's sum of its springs' terms, in the springs' order (rows in parallel: the same bits for any
// thread count, and as the springs added one by one to their ends' rows).
void global_rhs(const Model& model, const State& in, double h, const Points& X, const Points& y,
                LocalGlobalSolver& S) {
  const int springs = model.spring_count();
  double* B = S.rhs.data();
  const double* x[3] = {X.col(0).data(), X.col(1).data(), X.col(2).data()};
  const double* x0[3] = {in.x.col(0).data(), in.x.col(1).data(), in.x.col(2).data()};
  const double* Y[3] = {y.col(0).data(), y.col(1).data(), y.col(2).data()};
  S.wt.resize(3 * static_cast<std::size_t>(springs));
  double *wx = S.wt.data(), *wy = wx + springs, *wz = wy + springs;
  // Pieces of kPiece springs (a span cut where a piece ends), claimed by whichever thread of the
  // team is running (dynamics/threads.hpp), at least kPerThread springs a thread: a pass this
  // short (a tenth of an iteration on the 128 x 128 cloth) does not pay for waking many threads.
  constexpr int kPiece = 2048, kPerThread = 16384;
  threads::for_each_piece(
      (springs + kPiece - 1) / kPiece, springs,
      [&](int p) {
        const int lo = p * kPiece, hi = std::min(springs, lo + kPiece);
        auto span = std::upper_bound(model.spans.begin(), model.spans.end(), lo,
                                     [](int s, const SpringSpan& sp) { return s < sp.first; }) -
                    1;
        for (; span < model.spans.end() && span->first < hi; ++span) {
          const SpringMaterial& material = model.materials[span->material];
          const int from = std::max(lo - span->first, 0),
                    to = std::min(hi - span->first, span->count);
          if (from >= to) continue;
          const int at = span->first + from;
          span_targets(x, x0, Y, span->a0 + from, span->b0 + from, to - from, material.ks,
                       material.kd, span->rest, h, wx + at, wy + at, wz + at);
        }
      },
      kPerThread);
  // Each row its springs' terms, in the springs' order, pieces of rows in parallel.
  const int rows = static_cast<int>(S.inv_d.size());
  constexpr int kRowPiece = 2048;
  threads::for_each_piece(
      (rows + kRowPiece - 1) / kRowPiece, static_cast<double>(S.row_springs.size()),
      [&](int p) {
        const int lo = p * kRowPiece, hi = std::min(rows, lo + kRowPiece);
        for (int r = lo; r < hi; ++r) {
          double b0 = 0.0, b1 = 0.0, b2 = 0.0;
          for (int e = S.row_springs_first[r]; e < S.row_springs_first[r + 1]; ++e) {
            const int s = S.row_springs[e];
            if (s >= 0)
              b0 += wx[s], b1 += wy[s], b2 += wz[s];
            else
              b0 -= wx[~s], b1 -= wy[~s], b2 -= wz[~s];
          }
          B[3 * r] = b0, B[3 * r + 1] = b1, B[3 * r + 2] = b2;
        }
      },
      kPerThread);
}

}  // namespace local_global_parts

namespace steps {

using namespace local_global_parts;

void local_global(const Model& model, const State& in, State& out, double h,
                  const StepSettings& settings, Workspace& ws) {
  if (!ws.iterative) ws.iterative = std::make_unique<IterativeSolvers>();
  IterativeSolvers& I = *ws.iterative;
  LocalGlobalSolver& S = I.local_global;
  iterative::predict(model, in, h, I.y, I.mass);

  if (!S.factored || !S.key.matches(model, h)) {
    factorise(model, h, I.mass, S);
    S.key.take(model, h);
  } else if (S.plan.asked != std::max(1, threads::max_team())) {
    plan(model, S);  // the team changed: the solves' pieces for the new one (the same bits)
  }

  out.resize(in.particle_count());
  out.x = I.y;  // the first iterate; pinned rows stay at x + h v
  const double rho = settings.chebyshev_rho;
  if (rho > 0.0) S.previous = out.x;
  double omega = 1.0;
  const int iterations = iterations_for(Method::LocalGlobal, settings);
  const int n = in.particle_count();
  for (int k = 1; k <= iterations; ++k) {
    global_rhs(model, in, h, out.x, I.y, S);
    solve_in_place(S, S.rhs);  // the correction z from y
    // x = y + z, each particle's own (on the team: the same bits for any thread count).
    if (rho > 0.0) {
      omega = chebyshev_omega(k, rho, omega);
      S.current.resize(n, 3);
      iterative::each_particle_piece(n, [&](int begin, int end) {
        for (int c = 0; c < 3; ++c)
          for (int i = begin; i < end; ++i) {
            S.current(i, c) = out.x(i, c);
            if (S.row[i] >= 0)
              out.x(i, c) = omega * (I.y(i, c) + S.rhs[3 * S.row[i] + c] - S.previous(i, c)) +
                            S.previous(i, c);
          }
      });
      S.previous.swap(S.current);
    } else {
      iterative::each_particle_piece(n, [&](int begin, int end) {
        for (int c = 0; c < 3; ++c)
          for (int i = begin; i < end; ++i)
            if (S.row[i] >= 0) out.x(i, c) = I.y(i, c) + S.rhs[3 * S.row[i] + c];
      });
    }
  }
  ws.counters.solver_iterations += iterations;
  ++ws.counters.linear_solves;
  iterative::finish(model, in, out, h);
}

}  // namespace steps

// The plain iteration's contraction an iteration near its fixed point, as a power method finds a
// spectral radius: successive updates |x_k - x_(k-1)| shrink by it, measured over the last 8 of
// `iterations` from y.
double local_global_radius(const Model& model, const State& state, double h, int iterations) {
  using namespace local_global_parts;
  IterativeSolvers I;
  LocalGlobalSolver& S = I.local_global;
  iterative::predict(model, state, h, I.y, I.mass);
  factorise(model, h, I.mass, S);
  Points x = I.y;
  std::vector<double> updates;
  for (int k = 0; k < iterations; ++k) {
    global_rhs(model, state, h, x, I.y, S);
    solve_in_place(S, S.rhs);
    double squared = 0.0;
    for (int i = 0; i < model.particle_count(); ++i)
      for (int c = 0; c < 3 && S.row[i] >= 0; ++c) {
        const double next = I.y(i, c) + S.rhs[3 * S.row[i] + c];
        squared += (next - x(i, c)) * (next - x(i, c));
        x(i, c) = next;
      }
    updates.push_back(std::sqrt(squared));
  }
  const int tail = std::min(8, iterations / 2), last = iterations - 1;
  if (tail < 1 || !(updates[last - tail] > 0.0)) return 0.0;
  return std::pow(updates[last] / updates[last - tail], 1.0 / tail);
}

}  // namespace springlab
