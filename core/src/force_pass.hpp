// The force pass behind every force evaluation (forces.hpp), as a template so that a step can
// finish it its own way: the explicit methods integrate each thread's particles right where
// their forces were summed, instead of in further passes over memory.
//
// Each thread owns a range of particles, and the springs whose a-end it owns:
//   phase 1  its particles' gravity and drag; then, span by span, its springs' forces, added to
//            their a-ends at once (while at hand) and kept for their b-ends in a per-spring buffer
//   phase 2  span by span, the buffered forces subtracted at its particles that are b-ends; then
//            finish(begin, end) on its particles
// So every particle's force is summed in one order, whatever the number of threads: gravity and
// drag, its a-end springs in span order, its b-end springs in span order. Results are
// bit-identical for any thread count, and the buffer is written once and read once.
#pragma once

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "springlab/forces.hpp"
#include "springlab/spring_kernel.hpp"

namespace springlab {

namespace force_detail {

// Below this much work (springs + particles) one thread is faster than waking a second.
inline constexpr int kParallelThreshold = 4096;

struct Range {
  int begin, end;
};

// Thread t's share of [0, n), in multiples of 8 so that the vector loops stay aligned.
inline Range share(int n, int threads, int t) {
  const int chunk = ((n + threads - 1) / threads + 7) / 8 * 8;
  return {std::min(n, t * chunk), std::min(n, (t + 1) * chunk)};
}

// Forces of `count` springs whose ends are consecutive particles a0 + k and b0 + k: added to
// F at the a-ends and kept in f for the b-ends. Plain arrays, without branches, so that the
// compiler vectorises it (positions are read contiguously): the division is done even for
// coincident ends (giving infinity) and the result selected away, which keeps the loop free of
// control flow.
// Same arithmetic as spring_force(): s = (k_s (l - L) + k_d (dv . d) / l) / l, f_a = s d.
template <bool kDamped>
void span_forces(const double* __restrict X, const double* __restrict Y, const double* __restrict Z,
                 const double* __restrict VX, const double* __restrict VY, const double* __restrict VZ,
                 int a0, int b0, int count, const double* __restrict rest, double ks, double kd,
                 double* __restrict FX, double* __restrict FY, double* __restrict FZ,
                 double* __restrict fx, double* __restrict fy, double* __restrict fz) {
  for (int k = 0; k < count; ++k) {
    const double dx = X[b0 + k] - X[a0 + k];
    const double dy = Y[b0 + k] - Y[a0 + k];
    const double dz = Z[b0 + k] - Z[a0 + k];
    const double l = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double inverse = 1.0 / l;
    const double inv = l > kCoincident * std::max(rest[k], 1.0) ? inverse : 0.0;
    double s;
    if constexpr (kDamped) {
      const double rate = (VX[b0 + k] - VX[a0 + k]) * dx + (VY[b0 + k] - VY[a0 + k]) * dy +
                          (VZ[b0 + k] - VZ[a0 + k]) * dz;
      s = (ks * (l - rest[k]) + kd * rate * inv) * inv;
    } else {
      s = ks * (l - rest[k]) * inv;
    }
    const double gx = s * dx, gy = s * dy, gz = s * dz;
    FX[a0 + k] += gx;
    FY[a0 + k] += gy;
    FZ[a0 + k] += gz;
    fx[k] = gx;
    fy[k] = gy;
    fz[k] = gz;
  }
}

// out[i] -= f[i - offset] for i in [lo, hi).
inline void subtract(double* __restrict out, const double* __restrict f, int lo, int hi, int offset) {
  for (int i = lo; i < hi; ++i) out[i] -= f[i - offset];
}

}  // namespace force_detail

// F: three arrays (x, y, z) of particle_count() forces, written. `finish(begin, end)` is called
// once per thread, after its particles' forces are complete, with that range.
template <typename Finish>
void force_pass(const Model& model, const Points& x, const Points& v, double* const F[3],
                SpringForces& buffer, const Finish& finish) {
  using namespace force_detail;
  const int n = model.particle_count();
  const int springs = model.spring_count();
  buffer.x.resize(springs);
  buffer.y.resize(springs);
  buffer.z.resize(springs);
  const double* X[3] = {x.col(0).data(), x.col(1).data(), x.col(2).data()};
  const double* V[3] = {v.col(0).data(), v.col(1).data(), v.col(2).data()};
  double* SF[3] = {buffer.x.data(), buffer.y.data(), buffer.z.data()};
  const double g[3] = {model.gravity.x(), model.gravity.y(), model.gravity.z()};
  const double drag = model.drag;
  const double* mass = model.mass.data();

#pragma omp parallel if (springs + n >= kParallelThreshold)
  {
    const Range own = share(n, omp_get_num_threads(), omp_get_thread_num());
    for (int c = 0; c < 3; ++c)
      for (int i = own.begin; i < own.end; ++i) F[c][i] = mass[i] * g[c] - drag * V[c][i];
    for (const SpringSpan& span : model.spans) {
      // This thread's springs of the span: those whose a-end it owns.
      const int lo = std::max(0, own.begin - span.a0), hi = std::min(span.count, own.end - span.a0);
      if (lo >= hi) continue;
      const SpringMaterial& mat = model.materials[span.material];
      const int first = span.first + lo;
      // Undamped springs need no velocities: (k_s (l - L) + 0) / l is the same number.
      (mat.kd != 0.0 ? span_forces<true> : span_forces<false>)(
          X[0], X[1], X[2], V[0], V[1], V[2], span.a0 + lo, span.b0 + lo, hi - lo,
          model.rest_length.data() + first, mat.ks, mat.kd, F[0], F[1], F[2], SF[0] + first,
          SF[1] + first, SF[2] + first);
    }
#pragma omp barrier
    for (const SpringSpan& span : model.spans) {
      const int lo = std::max(span.b0, own.begin), hi = std::min(span.b0 + span.count, own.end);
      if (lo >= hi) continue;
      for (int c = 0; c < 3; ++c) subtract(F[c], SF[c] + span.first, lo, hi, span.b0);
    }
    finish(own.begin, own.end);
  }
}

}  // namespace springlab
