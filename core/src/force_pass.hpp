// The force pass behind every force evaluation (forces.hpp), as a template so that a step can
// finish it its own way: the explicit methods integrate each thread's particles right where
// their forces were summed, instead of in further passes over memory.
//
// The particles are cut into fixed blocks (their size depends on the particle count only), and
// each block holds the springs whose a-end is in it. Each thread takes a run of consecutive
// blocks and does for each:
//   1. gravity, drag and the fields; then span by span the springs' forces, added to their
//      a-ends and taken from their b-ends in the same loop where both ends are in the block and
//      far enough apart (kInPlaceDistance), else (neighbours: a rope's springs) kept in an
//      L1-sized chunk and taken from the b-ends after it; forces reaching into a later block are
//      kept in a buffer
//   2. the kept forces of the springs reaching into the block from earlier blocks, then
//      finish(block, begin, end)
// Step 2 of a block waits for step 1 of the blocks its springs come from. A thread does step 1
// of its last block first, since the next thread's first block waits for it; then its blocks in
// order, each with both steps (the last one's step 2 at the end). So no thread waits for
// another's whole share, and with one thread nothing waits at all.
// Every particle's force is summed in the same order (step 1, then step 2 span by span) whatever
// the number of threads, so results are bit-identical for any thread count; and most forces
// never leave the L1 cache.
#pragma once

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <thread>

#include "springlab/fields.hpp"
#include "springlab/forces.hpp"
#include "springlab/spring_kernel.hpp"

namespace springlab {

namespace force_detail {

// Below this much work (springs + particles) one thread is faster than waking a second.
inline constexpr int kParallelThreshold = 4096;
// Springs computed at once: their forces (3 x 8 bytes each) stay in the L1 cache.
inline constexpr int kChunk = 256;

// Where span_forces puts the force g of spring k (g on its a-end, -g on its b-end):
enum class Ends {
  Both,   // FA[k] += g, FB[k] -= g: FA and FB are one array, the b-ends at least
          // kInPlaceDistance after the a-ends (a vector of that many springs never holds both
          // ends of one spring, which `safelen` tells the compiler)
  KeepB,  // FA[k] += g, FB[k] = g (kept: for b-ends in a later block, or neighbours, whose
          // ends a vector would hold both of)
};
inline constexpr int kInPlaceDistance = 4;

// Forces of `count` springs whose ends are consecutive particles a0 + k and b0 + k.
// Both ends in one loop where possible: a second loop would store, reload and add each force
// again, and the loop is bound by how many instructions it issues (about 17 a spring).
// Plain arrays, without branches, so that the compiler vectorises it (positions are read
// contiguously): the division is done even for coincident ends (giving infinity) and the result
// selected away. 1/l is l (1/l^2), so that the division need not wait for the square root.
// Same arithmetic as spring_force(): s = (k_s (l - L) + k_d (dv . d) / l) / l, f_a = s d.
template <bool kDamped, Ends kEnds>
void span_forces(const double* __restrict X, const double* __restrict Y, const double* __restrict Z,
                 const double* __restrict VX, const double* __restrict VY, const double* __restrict VZ,
                 int a0, int b0, int count, double rest, double ks, double kd,
                 double* FAX, double* FAY, double* FAZ, double* FBX, double* FBY, double* FBZ) {
  const double coincident = kCoincident * std::max(rest, 1.0);
#pragma omp simd safelen(4)
  for (int k = 0; k < count; ++k) {
    const double dx = X[b0 + k] - X[a0 + k];
    const double dy = Y[b0 + k] - Y[a0 + k];
    const double dz = Z[b0 + k] - Z[a0 + k];
    const double l2 = dx * dx + dy * dy + dz * dz;
    const double l = std::sqrt(l2);
    const double inverse = l * (1.0 / l2);
    const double inv = l > coincident ? inverse : 0.0;
    double s;
    if constexpr (kDamped) {
      const double rate = (VX[b0 + k] - VX[a0 + k]) * dx + (VY[b0 + k] - VY[a0 + k]) * dy +
                          (VZ[b0 + k] - VZ[a0 + k]) * dz;
      s = (ks * (l - rest) + kd * rate * inv) * inv;
    } else {
      s = ks * (l - rest) * inv;
    }
    const double gx = s * dx, gy = s * dy, gz = s * dz;
    FAX[k] += gx;
    FAY[k] += gy;
    FAZ[k] += gz;
    if constexpr (kEnds == Ends::Both) {
      FBX[k] -= gx;
      FBY[k] -= gy;
      FBZ[k] -= gz;
    } else {
      FBX[k] = gx;
      FBY[k] = gy;
      FBZ[k] = gz;
    }
  }
}

// Waits until `flag` holds `value` (acquire): spins briefly, as the wait is usually short, then
// yields, so that a thread that is not running (more threads than cores) gets the core.
inline void wait_for(std::uint32_t& flag, std::uint32_t value) {
  std::atomic_ref<std::uint32_t> ref(flag);
  for (int spins = 0; ref.load(std::memory_order_acquire) != value; ++spins) {
    if (spins < 4096) {
#if defined(__x86_64__) || defined(__i386__)
      __builtin_ia32_pause();
#endif
    } else {
      std::this_thread::yield();
    }
  }
}

inline void subtract(double* __restrict out, const double* __restrict f, int count) {
  for (int k = 0; k < count; ++k) out[k] -= f[k];
}

// The plan of the pass for a model: blocks of about a sixteenth of the particles (at least 256,
// at most 2048, a multiple of 64), and each block's pieces of spans.
inline void make_plan(const Model& model, ForcePlan& plan) {
  const int n = model.particle_count();
  plan.particles = n;
  plan.springs = model.spring_count();
  plan.spans = model.spans.data();
  plan.block = std::clamp((n / 8 + 63) / 64 * 64, 256, 2048);
  const int blocks = std::max(1, (n + plan.block - 1) / plan.block);
  plan.own.assign(blocks, {});
  plan.incoming.assign(blocks, {});
  plan.source.resize(blocks);
  plan.done.assign(blocks, 0);
  plan.passes = 0;
  for (int b = 0; b < blocks; ++b) plan.source[b] = b;
  for (int s = 0; s < static_cast<int>(model.spans.size()); ++s) {
    const SpringSpan& span = model.spans[s];
    for (int b = 0; b < blocks; ++b) {
      const int begin = b * plan.block, end = std::min(n, begin + plan.block);
      const int lo = std::max(0, begin - span.a0), hi = std::min(span.count, end - span.a0);
      if (lo < hi) plan.own[b].push_back({s, lo, hi});
      // Springs with the b-end here and the a-end in an earlier block (b-ends follow a-ends).
      const int blo = std::max(0, begin - span.b0), bhi = std::min(span.count, end - span.b0);
      const int from_before = std::min(bhi, begin - span.a0);
      if (blo < from_before) {
        plan.incoming[b].push_back({s, blo, from_before});
        plan.source[b] = std::min(plan.source[b], (span.a0 + blo) / plan.block);
      }
    }
  }
}

}  // namespace force_detail

// The plan of the pass for a model, made on first use (and again when the springs change).
inline ForcePlan& plan_for(const Model& model, SpringForces& buffer) {
  ForcePlan& plan = buffer.plan;
  const int springs = model.spring_count();
  if (plan.particles != model.particle_count() || plan.springs != springs ||
      plan.spans != model.spans.data()) {
    force_detail::make_plan(model, plan);
    buffer.x.resize(springs);
    buffer.y.resize(springs);
    buffer.z.resize(springs);
  }
  return plan;
}

// F: three arrays (x, y, z) of particle_count() forces, written. `finish(block, begin, end)` is
// called once per block, after its particles' forces are complete, with the block's index and
// particle range.
template <typename Finish>
void force_pass(const Model& model, const Points& x, const Points& v, double* const F[3],
                SpringForces& buffer, const Finish& finish) {
  using namespace force_detail;
  const int n = model.particle_count();
  const int springs = model.spring_count();
  ForcePlan& plan = plan_for(model, buffer);
  const double* X[3] = {x.col(0).data(), x.col(1).data(), x.col(2).data()};
  const double* V[3] = {v.col(0).data(), v.col(1).data(), v.col(2).data()};
  double* SF[3] = {buffer.x.data(), buffer.y.data(), buffer.z.data()};
  const double g[3] = {model.gravity.x(), model.gravity.y(), model.gravity.z()};
  const double drag = model.drag;
  // -k_drag (v - wind) = k_drag wind - k_drag v: the first term is a constant (0 in still air).
  const double blow[3] = {drag * model.wind.x(), drag * model.wind.y(), drag * model.wind.z()};
  const double* mass = model.mass.data();
  const int blocks = static_cast<int>(plan.own.size());

  // The springs k in [lo, hi) of a span: their forces, onto the ends in F or kept in K as `ends`
  // says (kept forces at K[k - lo]).
  const auto springs_of = [&](const SpringSpan& span, int lo, int hi, Ends ends, double* const K[3]) {
    const SpringMaterial& mat = model.materials[span.material];
    const int a = span.a0 + lo, b = span.b0 + lo;
    // Undamped springs need no velocities: (k_s (l - L) + 0) / l is the same number.
    using Kernel = decltype(&span_forces<true, Ends::Both>);
    constexpr Kernel kernels[2][2] = {{span_forces<false, Ends::Both>, span_forces<false, Ends::KeepB>},
                                      {span_forces<true, Ends::Both>, span_forces<true, Ends::KeepB>}};
    double* const* B = ends == Ends::Both ? F : K;
    const int shift = ends == Ends::Both ? b : 0;
    kernels[mat.kd != 0.0][static_cast<int>(ends)](
        X[0], X[1], X[2], V[0], V[1], V[2], a, b, hi - lo, span.rest, mat.ks, mat.kd, F[0] + a,
        F[1] + a, F[2] + a, B[0] + shift, B[1] + shift, B[2] + shift);
  };

  // Step 1 of a block (see the top of this file).
  const auto springs_into = [&](int blk, double* const chunk[3]) {
    const int begin = blk * plan.block, end = std::min(n, begin + plan.block);
    for (int c = 0; c < 3; ++c)
      for (int i = begin; i < end; ++i) F[c][i] = (mass[i] * g[c] + blow[c]) - drag * V[c][i];
    for (const Attractor& field : model.attractors)
      for (int i = begin; i < end; ++i) {
        const Vec3 acc = field_acceleration(field, Vec3(X[0][i], X[1][i], X[2][i]));
        for (int c = 0; c < 3; ++c) F[c][i] += mass[i] * acc[c];
      }
    for (const ForcePlan::Piece& piece : plan.own[blk]) {
      const SpringSpan& span = model.spans[piece.span];
      // Springs [lo, inside) have their b-end in this block, [inside, hi) beyond it.
      const int inside = std::clamp(end - span.b0, piece.lo, piece.hi);
      if (span.b0 - span.a0 >= kInPlaceDistance) {
        springs_of(span, piece.lo, inside, Ends::Both, nullptr);
      } else {
        for (int lo = piece.lo; lo < inside; lo += kChunk) {
          const int count = std::min(inside - lo, kChunk);
          springs_of(span, lo, lo + count, Ends::KeepB, chunk);
          for (int c = 0; c < 3; ++c) subtract(F[c] + span.b0 + lo, chunk[c], count);
        }
      }
      if (inside < piece.hi) {
        double* const kept[3] = {SF[0] + span.first + inside, SF[1] + span.first + inside,
                                 SF[2] + span.first + inside};
        springs_of(span, inside, piece.hi, Ends::KeepB, kept);
      }
    }
  };

  // Step 1 done: published (release) for the threads whose step 2 waits for it.
  const std::uint32_t pass_number = ++plan.passes;
  std::uint32_t* done = plan.done.data();
  const auto publish = [&](int blk) {
    std::atomic_ref<std::uint32_t>(done[blk]).store(pass_number, std::memory_order_release);
  };

  // Step 2 of a block; blocks before `mine` (another thread's) are waited for.
  const auto complete = [&](int blk, int mine) {
    for (int src = plan.source[blk]; src < std::min(blk, mine); ++src) wait_for(done[src], pass_number);
    const int begin = blk * plan.block, end = std::min(n, begin + plan.block);
    for (const ForcePlan::Piece& piece : plan.incoming[blk]) {
      const SpringSpan& span = model.spans[piece.span];
      for (int c = 0; c < 3; ++c)
        subtract(F[c] + span.b0 + piece.lo, SF[c] + span.first + piece.lo, piece.hi - piece.lo);
    }
    finish(blk, begin, end);
  };

  // Run by every thread of the team, or by the caller alone (a parallel region costs an
  // allocation and a wake-up even with one thread).
  const auto pass = [&] {
    // Kept forces of neighbouring springs (small enough for the L1 cache).
    alignas(64) double chunk_x[kChunk], chunk_y[kChunk], chunk_z[kChunk];
    double* const chunk[3] = {chunk_x, chunk_y, chunk_z};
    const int threads = omp_get_num_threads(), thread = omp_get_thread_num();
    const int first = blocks * thread / threads, last = blocks * (thread + 1) / threads;
    if (first == last) return;
    springs_into(last - 1, chunk);
    publish(last - 1);
    for (int blk = first; blk < last - 1; ++blk) {
      springs_into(blk, chunk);
      publish(blk);
      complete(blk, first);
    }
    complete(last - 1, first);
  };
  if (springs + n >= kParallelThreshold && omp_get_max_threads() > 1) {
#pragma omp parallel
    pass();
  } else {
    pass();
  }
}

}  // namespace springlab
