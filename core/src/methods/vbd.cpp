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
// The first iterate is the paper's adaptive one: x + h v + h^2 a~, a~ the last step's
// acceleration along gravity, clamped to [0, |g|] (a cloth at rest starts where it is, a falling
// one falls), or y where that is not known.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "dynamics/threads.hpp"
#include "iterative.hpp"
#include "springlab/spring_kernel.hpp"
#include "steps.hpp"

namespace springlab {

namespace {

// One vertex's Newton step, from positions X (updated in place) and the start of the step X0.
void descend(const Model& model, const VertexBlockDescent& C, const IterativeSolvers& I, const State& in,
             double h, int i, Points& X) {
  const double inertia = I.mass[i] / (h * h);
  const Vec3 x = X.row(i).transpose();
  const Vec3 dx_i = x - in.x.row(i).transpose();
  Vec3 f = inertia * (I.y.row(i).transpose() - x);
  Eigen::Matrix3d H = inertia * Eigen::Matrix3d::Identity();
  for (int k = C.first[i]; k < C.first[i + 1]; ++k) {
    const int s = C.spring[k], j = C.other[k];
    const SpringMaterial& material = model.materials[model.spring_material[s]];
    const Vec3 d = X.row(j).transpose() - x;
    const double l = d.norm(), rest = model.rest_length[s];
    if (coincident(l, rest)) continue;
    const Vec3 u = d / l;
    const double rate = u.dot(X.row(j).transpose() - in.x.row(j).transpose() - dx_i) / h;
    f += (material.ks * (l - rest) + material.kd * rate) * u;
    const Eigen::Matrix3d uu = u * u.transpose();
    const double across = material.ks * std::max(0.0, 1.0 - rest / l);
    H += (material.ks + material.kd / h - across) * uu + across * Eigen::Matrix3d::Identity();
  }
  X.row(i) += H.llt().solve(f).transpose();
}

}  // namespace

namespace steps {

void vbd(const Model& model, const State& in, State& out, double h, const StepSettings& settings, Workspace& ws) {
  if (!ws.iterative) ws.iterative = std::make_unique<IterativeSolvers>();
  IterativeSolvers& I = *ws.iterative;
  VertexBlockDescent& C = I.vbd;
  const int n = in.particle_count();
  if (C.spans != model.spans.data() || C.particles != n || C.springs != model.spring_count())
    colour_vertices(model, C);
  iterative::predict(model, in, h, I.y, I.mass);

  out.resize(n);
  out.x = I.y;
  const double g = model.gravity.norm();
  if (ws.vbd_ready && g > 0.0 && C.v_before.rows() == n) {
    const Vec3 down = model.gravity / g;
    for (int i = 0; i < n; ++i) {
      if (model.pinned(i)) continue;
      const double along = std::clamp((in.v.row(i) - C.v_before.row(i)).dot(down.transpose()) / h, 0.0, g);
      out.x.row(i) = in.x.row(i) + h * in.v.row(i) + (h * h * along) * down.transpose();
    }
  }

  const int iterations = iterative::iterations(settings, Method::VBD);
  const int colours = static_cast<int>(C.colour_first.size()) - 1;
  for (int k = 0; k < iterations; ++k)
    for (int c = 0; c < colours; ++c) {
      const int begin = C.colour_first[c], end = C.colour_first[c + 1];
#pragma omp parallel for schedule(static) if (end - begin >= 4096 && threads::kAvailable)
      for (int q = begin; q < end; ++q) {
        const int i = C.order[q];
        if (!model.pinned(i)) descend(model, C, I, in, h, i, out.x);
      }
    }
  ws.counters.solver_iterations += iterations;
  C.v_before = in.v;
  ws.vbd_ready = true;
  iterative::finish(model, in, out, h);
}

}  // namespace steps
}  // namespace springlab
