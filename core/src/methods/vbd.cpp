// Vertex block descent (Chen, Liu, Yang, Yuksel 2024, "Vertex Block Descent"): the
// backward-Euler step of iterative.hpp minimised one vertex at a time, each with a 3x3 Newton
// step on its own block of the objective, the others held:
//
//   f_i = m~_i / h^2 (y_i - x_i) + sum_s [ k_s (l - L) + k_d u . (dx_j - dx_i) / h ] u
//   H_i = m~_i / h^2 I + sum_s [ k_s (u u^T + max(0, 1 - L/l) (I - u u^T)) + k_d / h u u^T ]
//   x_i += H_i^-1 f_i
//
// over each spring s from i to j (u = (x_j - x_i) / l, l = |x_j - x_i|, dx = x - x_start). The
// exact Hessian of a spring has k_s (1 - L/l) across it, negative when the spring is shorter than
// its rest length: there it is clamped at 0 (a compressed spring gets no stiffness across), so
// H_i >= m~_i / h^2 I is definite and no step can run uphill or explode. The damping's Hessian
// keeps u fixed (its term in u's derivative is dropped, as the paper does for its damping).
//
// Gauss-Seidel over a colouring of the vertices (iterative.cpp): no two vertices of a colour
// share a spring, so a colour's updates read only other colours' positions and run in parallel,
// each the same bits whatever the thread count. Iterations: `settings.iterations` (default 10).
//
// The first iterate is the inertial prediction y (as local-global's and XPBD's). The paper's
// adaptive one, x + h v + h^2 a~ with a~ the last step's acceleration along gravity clamped to
// [0, |g|], was tried: on the chain at h = 1/30 s with 10 iterations it never settles (a bounded
// cycle of about 1 J of kinetic energy for 300 s), where from y it comes to rest.
#include <algorithm>
#include <cmath>

#include "dynamics/threads.hpp"
#include "iterative.hpp"
#include "springlab/spring_kernel.hpp"
#include "steps.hpp"

namespace springlab {

namespace {

// One vertex's Newton step, from positions X (updated in place) and the start of the step X0.
// Plain arrays: a vertex reads its dozen neighbours' coordinates from three columns.
void descend(const Model& model, const VertexBlockDescent& C, const IterativeSolvers& I, double h,
             int i, double* const X[3], const double* const X0[3]) {
  const double inertia = I.mass[i] / (h * h);
  const double x[3] = {X[0][i], X[1][i], X[2][i]};
  const double dx_i[3] = {x[0] - X0[0][i], x[1] - X0[1][i], x[2] - X0[2][i]};
  double f[3], H[6];  // H: xx yy zz xy xz yz
  for (int c = 0; c < 3; ++c) f[c] = inertia * (I.y(i, c) - x[c]);
  H[0] = H[1] = H[2] = inertia;
  H[3] = H[4] = H[5] = 0.0;
  for (int k = C.first[i]; k < C.first[i + 1]; ++k) {
    const int s = C.spring[k], j = C.other[k];
    const SpringMaterial& material = model.materials[model.spring_material[s]];
    const double d[3] = {X[0][j] - x[0], X[1][j] - x[1], X[2][j] - x[2]};
    const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double rest = model.rest_length[s];
    if (coincident(l, rest)) continue;
    const double inv = 1.0 / l;
    const double u[3] = {d[0] * inv, d[1] * inv, d[2] * inv};
    double rate = 0.0;
    for (int c = 0; c < 3; ++c) rate += u[c] * ((X[c][j] - X0[c][j]) - dx_i[c]);
    const double scale = material.ks * (l - rest) + material.kd * rate / h;
    for (int c = 0; c < 3; ++c) f[c] += scale * u[c];
    const double across = material.ks * std::max(0.0, 1.0 - rest * inv);
    const double along = material.ks + material.kd / h - across;
    H[0] += along * u[0] * u[0] + across, H[1] += along * u[1] * u[1] + across,
        H[2] += along * u[2] * u[2] + across;
    H[3] += along * u[0] * u[1], H[4] += along * u[0] * u[2], H[5] += along * u[1] * u[2];
  }
  // H^-1 f by cofactors (H >= m~ / h^2 I: definite, the determinant positive).
  const double a = H[0], b = H[1], c = H[2], dd = H[3], e = H[4], g = H[5];
  const double cxx = b * c - g * g, cyy = a * c - e * e, czz = a * b - dd * dd;
  const double cxy = e * g - dd * c, cxz = dd * g - e * b, cyz = dd * e - a * g;
  const double inv_det = 1.0 / (a * cxx + dd * cxy + e * cxz);
  X[0][i] += (cxx * f[0] + cxy * f[1] + cxz * f[2]) * inv_det;
  X[1][i] += (cxy * f[0] + cyy * f[1] + cyz * f[2]) * inv_det;
  X[2][i] += (cxz * f[0] + cyz * f[1] + czz * f[2]) * inv_det;
}

}  // namespace

namespace steps {

void vbd(const Model& model, const State& in, State& out, double h, const StepSettings& settings,
         Workspace& ws) {
  if (!ws.iterative) ws.iterative = std::make_unique<IterativeSolvers>();
  IterativeSolvers& I = *ws.iterative;
  VertexBlockDescent& C = I.vbd;
  const int n = in.particle_count();
  if (C.spans != model.spans.data() || C.particles != n || C.springs != model.spring_count())
    colour_vertices(model, C);
  iterative::predict(model, in, h, I.y, I.mass);

  out.resize(n);
  out.x = I.y;

  double* const X[3] = {out.x.col(0).data(), out.x.col(1).data(), out.x.col(2).data()};
  const double* const X0[3] = {in.x.col(0).data(), in.x.col(1).data(), in.x.col(2).data()};
  const int iterations = iterations_for(Method::VBD, settings);
  const int colours = static_cast<int>(C.colour_first.size()) - 1;
  for (int k = 0; k < iterations; ++k)
    for (int c = 0; c < colours; ++c) {
      // A colour's vertices share no spring: each moves alone, in pieces of kPiece claimed by
      // whichever thread of the team is running (dynamics/threads.hpp). Small pieces, so that
      // the threads' shares end together: a colour of the 64 x 64 cloth is about 600 vertices,
      // 10 pieces of 64 (a thread with one more piece than the other, the step waits for it) or
      // 37 of 16 (2 threads, 10 alternations, medians: 4.60 ms a step with 64, 4.47 with 32,
      // 4.41 with 16; the OpenMP build's static halves, 4.28).
      constexpr int kPiece = 16;
      // A vertex's descent in the force pass's units (threads::worth_threads): its springs'
      // Hessians and a 3 x 3 solve cost about five force-pass visits a spring end (the 32 x 32
      // cloth on one thread: 15.5 ns a visit against the force pass's 2.7).
      constexpr double kDescentWork = 5.0;
      const int begin = C.colour_first[c], end = C.colour_first[c + 1];
      threads::for_each_piece(
          (end - begin + kPiece - 1) / kPiece, kDescentWork * C.colour_work[c], [&](int p) {
            for (int q = begin + p * kPiece; q < std::min(end, begin + (p + 1) * kPiece); ++q) {
              const int i = C.order[q];
              if (!model.pinned(i)) descend(model, C, I, h, i, X, X0);
            }
          });
    }
  ws.counters.solver_iterations += iterations;
  iterative::finish(model, in, out, h);
}

}  // namespace steps
}  // namespace springlab
