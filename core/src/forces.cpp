#include "springlab/forces.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "springlab/spring_kernel.hpp"

namespace springlab {

namespace {

// Below this much work (springs + particles) one thread is faster than waking a second.
constexpr int kParallelThreshold = 4096;

struct Range {
  int begin, end;
};

// Thread t's share of [0, n), in multiples of 8 so that the vector loops stay aligned.
Range share(int n, int threads, int t) {
  const int chunk = ((n + threads - 1) / threads + 7) / 8 * 8;
  return {std::min(n, t * chunk), std::min(n, (t + 1) * chunk)};
}

// Forces of `count` springs whose ends are consecutive particles a0 + k and b0 + k. Written as
// plain arrays so that the compiler vectorises it (positions are read contiguously).
// Same arithmetic as spring_force(): s = (k_s (l - L) + k_d (dv . d) / l) / l, f_a = s d.
void span_forces(const double* __restrict X, const double* __restrict Y, const double* __restrict Z,
                 const double* __restrict VX, const double* __restrict VY,
                 const double* __restrict VZ, int a0, int b0, int count,
                 const double* __restrict rest, double ks, double kd, double* __restrict fx,
                 double* __restrict fy, double* __restrict fz) {
  if (kd == 0.0) {
    for (int k = 0; k < count; ++k) {
      const double dx = X[b0 + k] - X[a0 + k];
      const double dy = Y[b0 + k] - Y[a0 + k];
      const double dz = Z[b0 + k] - Z[a0 + k];
      const double l = std::sqrt(dx * dx + dy * dy + dz * dz);
      const double inv = coincident(l, rest[k]) ? 0.0 : 1.0 / l;
      const double s = ks * (l - rest[k]) * inv;
      fx[k] = s * dx;
      fy[k] = s * dy;
      fz[k] = s * dz;
    }
    return;
  }
  for (int k = 0; k < count; ++k) {
    const double dx = X[b0 + k] - X[a0 + k];
    const double dy = Y[b0 + k] - Y[a0 + k];
    const double dz = Z[b0 + k] - Z[a0 + k];
    const double l = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double inv = coincident(l, rest[k]) ? 0.0 : 1.0 / l;
    const double rate =
        (VX[b0 + k] - VX[a0 + k]) * dx + (VY[b0 + k] - VY[a0 + k]) * dy + (VZ[b0 + k] - VZ[a0 + k]) * dz;
    const double s = (ks * (l - rest[k]) + kd * rate * inv) * inv;
    fx[k] = s * dx;
    fy[k] = s * dy;
    fz[k] = s * dz;
  }
}

// out[i] += sign * f[i - offset] for i in [lo, hi).
void accumulate(double* __restrict out, const double* __restrict f, int lo, int hi, int offset,
                bool add) {
  if (add)
    for (int i = lo; i < hi; ++i) out[i] += f[i - offset];
  else
    for (int i = lo; i < hi; ++i) out[i] -= f[i - offset];
}

}  // namespace

void evaluate_forces(const Model& model, const Points& x, const Points& v, Points& out,
                     SpringForces& buffer, ForceOutput what) {
  const int n = model.particle_count();
  const int springs = model.spring_count();
  buffer.x.resize(springs);
  buffer.y.resize(springs);
  buffer.z.resize(springs);
  out.resize(n, 3);

  const double* X[3] = {x.col(0).data(), x.col(1).data(), x.col(2).data()};
  const double* V[3] = {v.col(0).data(), v.col(1).data(), v.col(2).data()};
  double* F[3] = {out.col(0).data(), out.col(1).data(), out.col(2).data()};
  double* SF[3] = {buffer.x.data(), buffer.y.data(), buffer.z.data()};
  const double g[3] = {model.gravity.x(), model.gravity.y(), model.gravity.z()};
  const double drag = model.drag;
  const double* mass = model.mass.data();
  const double* inv_mass = model.inv_mass.data();

#pragma omp parallel if (springs + n >= kParallelThreshold)
  {
    const int threads = omp_get_num_threads();
    const int t = omp_get_thread_num();

    // Phase 1: this thread's springs.
    const Range sr = share(springs, threads, t);
    for (const SpringSpan& span : model.spans) {
      const int lo = std::max(span.first, sr.begin);
      const int hi = std::min(span.first + span.count, sr.end);
      if (lo >= hi) continue;
      const int k0 = lo - span.first;
      const SpringMaterial& mat = model.materials[span.material];
      span_forces(X[0], X[1], X[2], V[0], V[1], V[2], span.a0 + k0, span.b0 + k0, hi - lo,
                  model.rest_length.data() + lo, mat.ks, mat.kd, SF[0] + lo, SF[1] + lo,
                  SF[2] + lo);
    }
#pragma omp barrier

    // Phase 2: this thread's particles: gravity and drag, then each span's a-ends and b-ends.
    const Range pr = share(n, threads, t);
    for (int c = 0; c < 3; ++c)
      for (int i = pr.begin; i < pr.end; ++i) F[c][i] = mass[i] * g[c] - drag * V[c][i];
    for (const SpringSpan& span : model.spans) {
      const int alo = std::max(span.a0, pr.begin), ahi = std::min(span.a0 + span.count, pr.end);
      const int blo = std::max(span.b0, pr.begin), bhi = std::min(span.b0 + span.count, pr.end);
      for (int c = 0; c < 3; ++c) {
        if (alo < ahi) accumulate(F[c], SF[c] + span.first, alo, ahi, span.a0, true);
        if (blo < bhi) accumulate(F[c], SF[c] + span.first, blo, bhi, span.b0, false);
      }
    }
    if (what == ForceOutput::Acceleration)
      for (int c = 0; c < 3; ++c)
        for (int i = pr.begin; i < pr.end; ++i) F[c][i] *= inv_mass[i];
  }
}

void set_thread_count(int threads) {
  omp_set_num_threads(threads > 0 ? threads : omp_get_num_procs());
}

int thread_count() { return omp_get_max_threads(); }

}  // namespace springlab
