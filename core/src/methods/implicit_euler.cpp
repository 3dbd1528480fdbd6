// Implicit (backward) Euler, linearised once per step (Baraff and Witkin 1998): with
// K = df/dx and D = df/dv at the start of the step, solve
//   A dv = b,   A = M - h D - h^2 K,   b = h (f + h K v)
// then v1 = v + dv, x1 = x + h v1.
//
// How A dv = b is solved, and why. A is symmetric positive definite (K uses the definite spring
// Jacobian, spring_kernel.hpp) and sparse, so conjugate gradients solve it. What makes them fast:
//   - Matrix-free. A spring's block of A is B = h D_s + h^2 K_s = along d d^T + across I
//     (d = x_b - x_a): two numbers a spring. The product A p is a pass over the springs like the
//     force pass, g = B (p_b - p_a) taken from row a and added to row b, after each particle's
//     own block (particle_blocks). It reads 16 bytes a spring where an assembled matrix reads
//     216 (18 nonzeros at 12 bytes), and its loop vectorises along the spans.
//   - Block-Jacobi preconditioner: the inverses of A's 3x3 diagonal blocks. Cloth is stiff along
//     its surface and soft across it, in directions that turn as it folds; a 3x3 block follows
//     that, a diagonal does not (up to a third fewer iterations than Jacobi on cloth).
//   - A first guess extrapolated from the last three steps' dv (guess below): a fifth to a third
//     fewer iterations than starting from the last dv.
//   - Stop at |r| <= solver_tolerance |b| (StepSettings, 1e-5). The step is first order and
//     linearised once; on cloth 64 x 64 at h = 1/60, 30 steps move no particle more than 4e-7 m
//     from a 1e-10 solve, where halving h moves them by 3.5e-3 m, and the energy after 200 steps
//     agrees to 1e-6. It takes about 110 iterations a step there; 1e-10 takes 300.
//   - Three passes an iteration (the product, the update, the next direction), each a job of the
//     core's team (dynamics/threads.hpp): the particles are cut into the force pass's fixed
//     blocks (force_pass.hpp), claimed one at a time by whichever thread is running, so a thread
//     another program has parked is never waited for. Each particle's sum and each dot product
//     (per block, then the blocks in order) is taken in an order the blocks alone fix, so results
//     are bit-identical for any number of threads.
// Other solvers tried and set aside, with their figures: docs/decisions.md, "Implicit Euler's
// solve".
//
// Pinned particles keep dv = 0: their rows and columns of A are the identity's, which is exact
// because their dv is known; their motion still enters b through K v.
//
// Sections: kernels (vectorised span loops, dot products); the solver (setup, first guess,
// product, conjugate gradients); the step.
#include "implicit_euler.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "dynamics/force_pass.hpp"
#include "iterative.hpp"
#include "springlab/spring_kernel.hpp"
#include "step_scratch.hpp"
#include "steps.hpp"
#include "tableau_steps.hpp"

namespace springlab {

namespace {

// ---- Kernels ----------------------------------------------------------------------------------

// Symmetric 3x3 blocks, one a particle, structure of arrays.
struct SymmetricBlocks {
  std::vector<double> xx, yy, zz, xy, xz, yz;
  void resize(int n) {
    for (std::vector<double>* v : {&xx, &yy, &zz, &xy, &xz, &yz}) v->resize(n);
  }
  void set_identity_times(int i, double s) {
    xx[i] = yy[i] = zz[i] = s;
    xy[i] = xz[i] = yz[i] = 0.0;
  }
  void copy(const SymmetricBlocks& from, int begin, int end) {
    for (int i = begin; i < end; ++i) {
      xx[i] = from.xx[i], yy[i] = from.yy[i], zz[i] = from.zz[i];
      xy[i] = from.xy[i], xz[i] = from.xz[i], yz[i] = from.yz[i];
    }
  }
  // Inverts blocks [begin, end) in place (each symmetric positive definite): the cofactors over
  // the determinant.
  void invert(int begin, int end) {
    SPRINGLAB_VECTORISE
    for (int i = begin; i < end; ++i) {
      const double a = xx[i], b = yy[i], c = zz[i], d = xy[i], e = xz[i], f = yz[i];
      const double cxx = b * c - f * f, cyy = a * c - e * e, czz = a * b - d * d;
      const double cxy = e * f - d * c, cxz = d * f - e * b, cyz = d * e - a * f;
      const double inv_det = 1.0 / (a * cxx + d * cxy + e * cxz);
      xx[i] = cxx * inv_det, yy[i] = cyy * inv_det, zz[i] = czz * inv_det;
      xy[i] = cxy * inv_det, xz[i] = cxz * inv_det, yz[i] = cyz * inv_det;
    }
  }
};

// The three coordinate arrays of a Points (x | y | z), each contiguous.
struct Columns {
  const double *x, *y, *z;
  explicit Columns(const Points& p) : x(p.col(0).data()), y(p.col(1).data()), z(p.col(2).data()) {}
};

// For `count` springs of a span (spring k joins particles a0 + k and b0 + k), from positions X
// and velocities V: the spring's block of A, B = h dfdv + h^2 dfdx = along d d^T + across I, and
// kv = h^2 dfdx (v_b - v_a), its a-end's share of h^2 K v (definite_spring_jacobian).
void span_blocks(const Columns& X, const Columns& V, int a0, int b0, int count, double ks,
                 double kd, double rest, double h, double* __restrict along,
                 double* __restrict across, double* __restrict kvx, double* __restrict kvy,
                 double* __restrict kvz) {
  const double h2 = h * h;
  SPRINGLAB_VECTORISE
  for (int k = 0; k < count; ++k) {
    const double dx = X.x[b0 + k] - X.x[a0 + k];
    const double dy = X.y[b0 + k] - X.y[a0 + k];
    const double dz = X.z[b0 + k] - X.z[a0 + k];
    const double wx = V.x[b0 + k] - V.x[a0 + k];
    const double wy = V.y[b0 + k] - V.y[a0 + k];
    const double wz = V.z[b0 + k] - V.z[a0 + k];
    const DefiniteSpringJacobian J =
        definite_spring_jacobian(dx * dx + dy * dy + dz * dz, ks, kd, rest);
    along[k] = h * J.damp_along + h2 * J.stiff_along;
    across[k] = h2 * J.stiff_across;
    const double s = h2 * J.stiff_along * (dx * wx + dy * wy + dz * wz);
    const double c = h2 * J.stiff_across;
    kvx[k] = s * dx + c * wx;
    kvy[k] = s * dy + c * wy;
    kvz[k] = s * dz + c * wz;
  }
}

// Adds `count` springs of a span (spring k joins a0 + k and b0 + k) to the rows of one of their
// ends, at + k: B = along d d^T + across I to the diagonal block D, sign kv to b.
void add_spring_blocks(const Columns& X, int a0, int b0, int at, int count,
                       const double* __restrict along, const double* __restrict across,
                       const double* __restrict kvx, const double* __restrict kvy,
                       const double* __restrict kvz, double sign, SymmetricBlocks& D, Points& b) {
  double *xx = D.xx.data() + at, *yy = D.yy.data() + at, *zz = D.zz.data() + at;
  double *xy = D.xy.data() + at, *xz = D.xz.data() + at, *yz = D.yz.data() + at;
  double *bx = b.col(0).data() + at, *by = b.col(1).data() + at, *bz = b.col(2).data() + at;
  SPRINGLAB_VECTORISE
  for (int k = 0; k < count; ++k) {
    const double dx = X.x[b0 + k] - X.x[a0 + k];
    const double dy = X.y[b0 + k] - X.y[a0 + k];
    const double dz = X.z[b0 + k] - X.z[a0 + k];
    xx[k] += along[k] * dx * dx + across[k];
    yy[k] += along[k] * dy * dy + across[k];
    zz[k] += along[k] * dz * dz + across[k];
    xy[k] += along[k] * dx * dy;
    xz[k] += along[k] * dx * dz;
    yz[k] += along[k] * dy * dz;
    bx[k] += sign * kvx[k];
    by[k] += sign * kvy[k];
    bz[k] += sign * kvz[k];
  }
}

// Q = M P for particles [begin, end): a symmetric block times a vector, each particle's.
void multiply(const SymmetricBlocks& M, const double* const P[3], double* const Q[3], int begin,
              int end) {
  const double *xx = M.xx.data(), *yy = M.yy.data(), *zz = M.zz.data();
  const double *xy = M.xy.data(), *xz = M.xz.data(), *yz = M.yz.data();
  const double *px = P[0], *py = P[1], *pz = P[2];
  double *qx = Q[0], *qy = Q[1], *qz = Q[2];
  SPRINGLAB_VECTORISE
  for (int i = begin; i < end; ++i) {
    qx[i] = xx[i] * px[i] + xy[i] * py[i] + xz[i] * pz[i];
    qy[i] = xy[i] * px[i] + yy[i] * py[i] + yz[i] * pz[i];
    qz[i] = xz[i] * px[i] + yz[i] * py[i] + zz[i] * pz[i];
  }
}

// The springs' part of A p for `count` springs of a span (spring k joins particles a0 + k and
// b0 + k): g = B (p_b - p_a), B = along d d^T + across I with d = x_b - x_a. Row a of A p gets
// -g, row b gets +g. Plain arrays without branches, so that it vectorises (positions and p are
// read contiguously), like span_forces in force_pass.hpp.
void span_product(const double* __restrict X, const double* __restrict Y,
                  const double* __restrict Z, const double* __restrict PX,
                  const double* __restrict PY, const double* __restrict PZ, int a0, int b0,
                  int count, const double* __restrict along, const double* __restrict across,
                  double* __restrict gx, double* __restrict gy, double* __restrict gz) {
  for (int k = 0; k < count; ++k) {
    const double dx = X[b0 + k] - X[a0 + k];
    const double dy = Y[b0 + k] - Y[a0 + k];
    const double dz = Z[b0 + k] - Z[a0 + k];
    const double ex = PX[b0 + k] - PX[a0 + k];
    const double ey = PY[b0 + k] - PY[a0 + k];
    const double ez = PZ[b0 + k] - PZ[a0 + k];
    const double s = along[k] * (dx * ex + dy * ey + dz * ez);
    const double c = across[k];
    gx[k] = s * dx + c * ex;
    gy[k] = s * dy + c * ey;
    gz[k] = s * dz + c * ez;
  }
}

void add(double* __restrict out, const double* __restrict g, int count) {
  for (int k = 0; k < count; ++k) out[k] += g[k];
}
void subtract(double* __restrict out, const double* __restrict g, int count) {
  for (int k = 0; k < count; ++k) out[k] -= g[k];
}

// The sum of a[i] b[i] over [begin, end), in four interleaved partial sums (so that it
// vectorises) added in a fixed order.
double dot(const double* __restrict a, const double* __restrict b, int begin, int end) {
  double s[4] = {0.0, 0.0, 0.0, 0.0};
  int i = begin;
  for (; i + 4 <= end; i += 4)
    for (int j = 0; j < 4; ++j) s[j] += a[i + j] * b[i + j];
  for (; i < end; ++i) s[0] += a[i] * b[i];
  return (s[0] + s[1]) + (s[2] + s[3]);
}

double dot(const Points& a, const Points& b, int begin, int end) {
  return dot(a.col(0).data(), b.col(0).data(), begin, end) +
         dot(a.col(1).data(), b.col(1).data(), begin, end) +
         dot(a.col(2).data(), b.col(2).data(), begin, end);
}

// Calls f(block, begin, end) for every particle block of the plan, on the team where the pass's
// `work` (particles + springs) is worth it (threads.hpp), each block claimed by whichever thread
// is running. What a block computes does not depend on which thread computes it.
template <typename F>
void each_block(const ForcePlan& plan, int n, double work, const F& f) {
  const int blocks = static_cast<int>(plan.own.size());
  threads::for_each_piece(blocks, work,
                          [&](int k) { f(k, k * plan.block, std::min(n, (k + 1) * plan.block)); });
}

// The diagonal block of A and the terms of b that come from forces on one particle alone, for
// particles [begin, end):
//   own_i = m_i I - h df_i/dv_i - h^2 df_i/dx_i,   b_i += h^2 (df_i/dx_i) v_i.
// Drag is such a force (df/dv = -k_drag I); gravity has no derivative. A position-dependent
// field on particles (an attractor, say) adds its 3x3 df_i/dx_i here: -h^2 df_i/dx_i to own_i
// (symmetric, as conjugate gradients need) and h^2 df_i/dx_i v_i to b_i.
void particle_blocks(const Model& model, const State&, double h, int begin, int end,
                     SymmetricBlocks& own, Points&) {
  for (int i = begin; i < end; ++i) own.set_identity_times(i, model.mass[i] + h * model.drag);
}

}  // namespace

// ---- The solver -------------------------------------------------------------------------------

struct ImplicitSolver {
  // Per spring, in the model's order.
  std::vector<double> along, across;     // its block of A: along d d^T + across I, d = x_b - x_a
  std::vector<double> kv_x, kv_y, kv_z;  // h^2 dfdx (v_b - v_a): b_a gets it, b_b minus it
  // Per particle.
  SymmetricBlocks own;      // its own block of A (particle_blocks)
  SymmetricBlocks inverse;  // the inverse of A's diagonal block: the preconditioner
  std::vector<int> pinned;  // in increasing order
  Points f, b, r, z, p, q;
  // The solution dv; between steps, the last step's. Before it, the dv of the two steps before
  // (earlier[0], earlier[1]); `known` of these three are from earlier steps.
  Points dv, earlier[2];
  int known = 0;
  // Per block, the block's part of each dot product.
  enum Slot { kPQ, kRR, kRZ, kBB, kSlots };
  std::vector<double> partial;
  // The last solve.
  int iterations = 0;
  bool converged = true;
  double work = 0.0;  // a pass's particle- and spring-visits, for threads::worth_threads

  void resize(const Model& model, const ForcePlan& plan) {
    const int n = model.particle_count(), springs = model.spring_count();
    if (dv.rows() != n) {
      for (Points* v : {&f, &b, &r, &z, &p, &q}) v->resize(n, 3);
      for (Points* v : {&dv, &earlier[0], &earlier[1]}) *v = Points::Zero(n, 3);
      known = 0;
      own.resize(n);
      inverse.resize(n);
    }
    for (std::vector<double>* v : {&along, &across, &kv_x, &kv_y, &kv_z}) v->resize(springs);
    work = static_cast<double>(n) + springs;
    partial.resize(kSlots * plan.own.size());
    pinned.clear();
    for (int i = 0; i < n; ++i)
      if (model.pinned(i)) pinned.push_back(i);
  }

  // The pinned particles in [begin, end).
  std::span<const int> pinned_in(int begin, int end) const {
    const auto first = std::lower_bound(pinned.begin(), pinned.end(), begin);
    const auto last = std::lower_bound(first, pinned.end(), end);
    return {std::to_address(first),
            static_cast<std::size_t>(last - first)};  // (LLVM 14's span takes no iterators)
  }

  // The sum of the blocks' parts of a dot product, in block order: the same on every thread and
  // for any number of threads.
  double total(Slot slot) const {
    double sum = 0.0;
    for (std::size_t k = slot; k < partial.size(); k += kSlots) sum += partial[k];
    return sum;
  }

  // The springs' blocks and b's spring terms, then b, the particles' own blocks and the
  // preconditioner, from the state `in` and its forces f.
  // With `v_start` (Newton's correction of a backward-Euler step at the iterate `in` = (X, V)):
  // the same A at (X, V), b = h f(X, V) - M (V - v_start), no K v term, and a first guess of 0.
  void setup(const Model& model, const ForcePlan& plan, const State& in, double h,
             const Points* v_start = nullptr) {
    const int n = model.particle_count();
    const Columns X(in.x), V(in.v);
    if (v_start) known = 0;
    each_block(plan, n, work, [&](int block, int, int) {
      for (const ForcePlan::Piece& piece : plan.own[block]) {
        const SpringSpan& span = model.spans[piece.span];
        const SpringMaterial& mat = model.materials[span.material];
        const int s = span.first + piece.lo, count = piece.hi - piece.lo;
        span_blocks(X, V, span.a0 + piece.lo, span.b0 + piece.lo, count, mat.ks, mat.kd, span.rest,
                    h, &along[s], &across[s], &kv_x[s], &kv_y[s], &kv_z[s]);
        if (v_start)
          for (std::vector<double>* kv : {&kv_x, &kv_y, &kv_z})
            std::fill_n(kv->begin() + s, count, 0.0);
      }
    });
    each_block(plan, n, work, [&](int block, int begin, int end) {
      guess(begin, end);
      for (int c = 0; c < 3; ++c)
        for (int i = begin; i < end; ++i)
          b(i, c) = h * f(i, c) - (v_start ? model.mass[i] * (in.v(i, c) - (*v_start)(i, c)) : 0.0);
      particle_blocks(model, in, h, begin, end, own, b);
      SymmetricBlocks& D = inverse;  // A's diagonal blocks, inverted below
      D.copy(own, begin, end);
      // Springs [lo, hi) of a span at their ends `at` + k (a0 or b0): B_s on the diagonal, and
      // kv_s in b with the sign of that end.
      const auto add = [&](const SpringSpan& span, int lo, int hi, int at, double sign) {
        const int s = span.first + lo;
        add_spring_blocks(X, span.a0 + lo, span.b0 + lo, at + lo, hi - lo, &along[s], &across[s],
                          &kv_x[s], &kv_y[s], &kv_z[s], sign, D, b);
      };
      for (const ForcePlan::Piece& piece : plan.own[block]) {
        const SpringSpan& span = model.spans[piece.span];
        add(span, piece.lo, piece.hi, span.a0, 1.0);
        add(span, piece.lo, std::max(piece.lo, std::min(piece.hi, end - span.b0)), span.b0, -1.0);
      }
      for (const ForcePlan::Piece& piece : plan.incoming[block]) {
        const SpringSpan& span = model.spans[piece.span];
        add(span, piece.lo, piece.hi, span.b0, -1.0);
      }
      for (int i : pinned_in(begin, end)) {
        b.row(i).setZero();
        dv.row(i).setZero();
        own.set_identity_times(i, 1.0);
        D.set_identity_times(i, 1.0);
      }
      D.invert(begin, end);
    });
  }

  // The first guess of dv, for particles [begin, end): the parabola through the last three
  // steps' dv, extended one step (fewer if fewer are known): 3 dv1 - 3 dv2 + dv3. On cloth at one
  // step a frame it starts conjugate gradients a fifth to a third closer than the last dv alone.
  void guess(int begin, int end) {
    static constexpr double kWeights[4][3] = {{0, 0, 0}, {1, 0, 0}, {2, -1, 0}, {3, -3, 1}};
    const double* w = kWeights[std::min(known, 3)];
    for (int c = 0; c < 3; ++c) {
      double *d1 = dv.col(c).data(), *d2 = earlier[0].col(c).data(), *d3 = earlier[1].col(c).data();
      SPRINGLAB_VECTORISE
      for (int i = begin; i < end; ++i) {
        const double next = w[0] * d1[i] + w[1] * d2[i] + w[2] * d3[i];
        d3[i] = d2[i];
        d2[i] = d1[i];
        d1[i] = next;
      }
    }
  }

  // out = A in, and each block's part of in . out (slot kPQ). Each block sums its particles'
  // rows completely: their own blocks, then span by span the springs with an a-end in the block
  // (and their b-ends there), then the springs reaching into it from earlier blocks. Those are
  // computed twice, once by each block they touch (about a fifth of a cloth's springs), which
  // spares a second pass and a wait for the other threads.
  void product(const Model& model, const ForcePlan& plan, const Points& x, const Points& in,
               Points& out) {
    constexpr int kChunk = 256;  // springs at once: their products stay in the L1 cache
    const int n = model.particle_count();
    const double* X[3] = {x.col(0).data(), x.col(1).data(), x.col(2).data()};
    const double* P[3] = {in.col(0).data(), in.col(1).data(), in.col(2).data()};
    double* Q[3] = {out.col(0).data(), out.col(1).data(), out.col(2).data()};
    each_block(plan, n, work, [&](int block, int begin, int end) {
      multiply(own, P, Q, begin, end);
      alignas(64) double g[3][kChunk];
      const auto springs = [&](const SpringSpan& span, int lo, int count) {
        const int s = span.first + lo;
        span_product(X[0], X[1], X[2], P[0], P[1], P[2], span.a0 + lo, span.b0 + lo, count,
                     &along[s], &across[s], g[0], g[1], g[2]);
      };
      for (const ForcePlan::Piece& piece : plan.own[block]) {
        const SpringSpan& span = model.spans[piece.span];
        for (int lo = piece.lo; lo < piece.hi; lo += kChunk) {
          const int count = std::min(kChunk, piece.hi - lo);
          springs(span, lo, count);
          const int a_end = span.a0 + lo, b_end = span.b0 + lo;
          const int inside = std::clamp(end - b_end, 0, count);  // b-ends in this block
          for (int d = 0; d < 3; ++d) {
            subtract(Q[d] + a_end, g[d], count);
            add(Q[d] + b_end, g[d], inside);
          }
        }
      }
      for (const ForcePlan::Piece& piece : plan.incoming[block]) {
        const SpringSpan& span = model.spans[piece.span];
        for (int lo = piece.lo; lo < piece.hi; lo += kChunk) {
          const int count = std::min(kChunk, piece.hi - lo);
          springs(span, lo, count);
          for (int d = 0; d < 3; ++d) add(Q[d] + span.b0 + lo, g[d], count);
        }
      }
      for (int i : pinned_in(begin, end)) out.row(i) = in.row(i);
      partial[kSlots * block + kPQ] = dot(in, out, begin, end);
    });
  }

  // z = the preconditioner applied to r, for particles [begin, end).
  void precondition(int begin, int end) {
    const double* R[3] = {r.col(0).data(), r.col(1).data(), r.col(2).data()};
    double* Z[3] = {z.col(0).data(), z.col(1).data(), z.col(2).data()};
    multiply(inverse, R, Z, begin, end);
  }

  // Preconditioned conjugate gradients on A dv = b from the dv held (the first guess), until
  // |r| <= tolerance |b| or max_iterations products. The scalars come from the blocks' partial
  // sums added in block order: the same decisions for any number of threads.
  void solve(const Model& model, const ForcePlan& plan, const Points& x, double tolerance,
             int max_iterations) {
    const int n = model.particle_count();
    product(model, plan, x, dv, q);
    each_block(plan, n, work, [&](int block, int begin, int end) {
      r.middleRows(begin, end - begin) =
          b.middleRows(begin, end - begin) - q.middleRows(begin, end - begin);
      precondition(begin, end);
      p.middleRows(begin, end - begin) = z.middleRows(begin, end - begin);
      partial[kSlots * block + kRR] = dot(r, r, begin, end);
      partial[kSlots * block + kRZ] = dot(r, z, begin, end);
      partial[kSlots * block + kBB] = dot(b, b, begin, end);
    });
    const double bb = total(kBB);
    const double threshold = tolerance * tolerance * bb;
    double rr = total(kRR), rz = total(kRZ);
    if (bb == 0.0) {  // dv = 0 exactly, whatever the guess
      each_block(plan, n, work,
                 [&](int, int begin, int end) { dv.middleRows(begin, end - begin).setZero(); });
      rr = 0.0;
    }
    int k = 0;
    while (rr > threshold && k < max_iterations) {
      product(model, plan, x, p, q);
      ++k;
      // p A p > 0 for a definite A and p != 0; it is 0 only when the residual has underflowed (a
      // motion decayed to 1e-160 of its size, squared below the smallest double): nothing is
      // left to solve, and 0 / 0 would write NaN into dv.
      const double pq = total(kPQ);
      if (!(pq > 0.0 && rz > 0.0)) break;
      const double alpha = rz / pq;
      each_block(plan, n, work, [&](int block, int begin, int end) {
        for (int c = 0; c < 3; ++c) {
          double *solution = dv.col(c).data(), *residual = r.col(c).data();
          const double *direction = p.col(c).data(), *product = q.col(c).data();
          SPRINGLAB_VECTORISE
          for (int i = begin; i < end; ++i) {
            solution[i] += alpha * direction[i];
            residual[i] -= alpha * product[i];
          }
        }
        precondition(begin, end);
        partial[kSlots * block + kRR] = dot(r, r, begin, end);
        partial[kSlots * block + kRZ] = dot(r, z, begin, end);
      });
      rr = total(kRR);
      if (rr <= threshold) break;
      const double rz_next = total(kRZ);
      const double beta = rz_next / rz;
      rz = rz_next;
      each_block(plan, n, work, [&](int, int begin, int end) {
        for (int c = 0; c < 3; ++c) {
          double* direction = p.col(c).data();
          const double* preconditioned = z.col(c).data();
          SPRINGLAB_VECTORISE
          for (int i = begin; i < end; ++i) direction[i] = preconditioned[i] + beta * direction[i];
        }
      });
    }
    iterations = k;
    converged = rr <= threshold;
  }
};

// Defined here, where ImplicitSolver (and IterativeSolvers, StageSolvers and StepScratch) are
// complete.
Workspace::Workspace() = default;
Workspace::~Workspace() = default;
Workspace::Workspace(Workspace&&) noexcept = default;
Workspace& Workspace::operator=(Workspace&&) noexcept = default;

void Workspace::invalidate() {
  verlet_ready = false;
  if (scratch) scratch->fsal_ready = false;  // a scratch not yet made has nothing to forget
}

// ---- The step ---------------------------------------------------------------------------------

namespace steps {

void implicit_euler(const Model& model, const State& in, State& out, double h,
                    const StepSettings& settings, Workspace& ws) {
  if (!ws.implicit) ws.implicit = std::make_unique<ImplicitSolver>();
  ImplicitSolver& S = *ws.implicit;
  const int n = model.particle_count();

  evaluate_forces(model, in.x, in.v, S.f, ws.spring_forces, ForceOutput::Force);
  ++ws.counters.force_evals;
  const ForcePlan& plan = ws.spring_forces.plan;  // made for this model by the force pass
  S.resize(model, plan);
  out.resize(n);
  // As Eigen's conjugate gradients: twice the unknowns (never reached unless A is ill-posed).
  const int max_iterations =
      settings.max_solver_iterations > 0 ? settings.max_solver_iterations : 6 * n;

  S.setup(model, plan, in, h);
  S.solve(model, plan, in.x, settings.solver_tolerance, max_iterations);
  each_block(plan, n, S.work, [&](int, int begin, int end) {
    for (int c = 0; c < 3; ++c)
      for (int i = begin; i < end; ++i) {
        out.v(i, c) = in.v(i, c) + S.dv(i, c);
        out.x(i, c) = in.x(i, c) + h * out.v(i, c);
      }
  });
  S.known = std::min(S.known + 1, 3);
  ++ws.counters.linear_solves;
  ws.counters.solver_iterations += S.iterations;
  if (!S.converged) ++ws.counters.unconverged_solves;
  out.t = in.t + h;
}

}  // namespace steps

namespace implicit_euler_system {

void evaluate(const Model& model, const State& in, double h, const Points& p, Points& Ap,
              Points& b) {
  ImplicitSolver S;
  SpringForces forces;
  evaluate_forces(model, in.x, in.v, S.f, forces, ForceOutput::Force);
  S.resize(model, forces.plan);
  S.setup(model, forces.plan, in, h);
  S.product(model, forces.plan, in.x, p, S.q);
  Ap = S.q;
  b = S.b;
}

}  // namespace implicit_euler_system
}  // namespace springlab
