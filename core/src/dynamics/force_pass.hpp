// The force pass behind every force evaluation (forces.hpp), as a template so that a step can
// finish it its own way: the explicit methods integrate each thread's particles right where
// their forces were summed, instead of in further passes over memory.
//
// The particles are cut into fixed blocks (their size depends on the particle count only), and
// each block holds the springs whose a-end is in it. Each thread takes a run of consecutive
// blocks and does for each:
//   1. gravity, drag and the fields of its last particles; then the springs whose b-ends are in
//      a later block: their forces added to their a-ends and kept in a buffer for that block
//   2. chunk by chunk (kChunkParticles): the springs with both ends in the block and their
//      a-ends in the chunk, span by span, four at a time, added to the a-ends and taken from the
//      b-ends in the same loop (springs_both; where the ends are fewer than four particles
//      apart, as along a rope, springs_chain runs over the particles instead); then the kept
//      forces of springs reaching into the chunk from earlier blocks; the chunk's forces are
//      then complete (a spring's b-end follows its a-end) and finish(block, begin, end) uses
//      them while they are in the cache
// Step 2 of a block waits for step 1 of that block and of the blocks its springs come from, and
// for nothing else: step 2 never writes outside its block. A thread does step 1 of all its
// blocks first (its last first, since the next thread's first block waits for it), then step 2
// of its blocks in order; a thread that has finished its own takes step 2 of the blocks at the
// back of another's run, so a core that runs slower for a while is helped instead of waited for
// (perf, 64 x 64 cloth: 20 % of two threads' time in OpenMP's barrier instead of 26 %).
// Every particle's force is summed in the same order (step 1, then step 2 chunk by chunk and
// span by span) whichever thread does a block and whatever the number of threads, so results
// are bit-identical for any thread count.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <thread>
#include <type_traits>

#include "dynamics/threads.hpp"
#include "springlab/fields.hpp"
#include "springlab/forces.hpp"
#include "springlab/spring_kernel.hpp"

namespace springlab {

namespace force_detail {

using simd::f64x4;
using simd::kLanes;

// A block's particles are finished this many at a time: the forces of a chunk and the springs
// reaching on from it stay in the L1 and L2 caches between being summed and being used.
inline constexpr int kChunkParticles = 256;

// What the spring kernels read: positions and velocities, one array a coordinate.
struct SpringInput {
  const double* x[3];
  const double* v[3];
};

// One span's constants.
struct SpanLaw {
  double ks, kd, rest;
};

// What a kernel computes: elastic springs (k_d = 0, no velocities read), damped springs, or
// damped springs and the power their damping takes out, sum k_d (dv . u)^2 (the app and `render`
// follow the energy dissipated, and it costs a pass over the springs of its own otherwise).
enum class Law { Elastic, Damped, Measured };

// Power accumulated four lanes at a time; a single spring's goes into lane 0.
inline void accumulate(f64x4& sum, f64x4 power) {
  sum += power;
}
inline void accumulate(f64x4& sum, double power) {
  sum[0] += power;
}

// g, the force on the a-ends of the springs between particles a (+ lane) and b (+ lane), and
// with Law::Measured their damping's power: one spring for T = double, four for T = f64x4.
// spring_scale() holds the formula; this gathers its inputs with the same arithmetic as
// spring_force(). Always inlined: called out of line, its vectors go through memory (measured:
// 30 instructions a spring a step instead of 23).
template <Law kLaw, typename T>
[[gnu::always_inline]] inline void spring_lanes(const SpringInput& in, int a, int b, SpanLaw law,
                                                T g[3], T& power) {
  using simd::at;
  constexpr bool kDamped = kLaw != Law::Elastic;
  const T dx = at<T>(in.x[0] + b) - at<T>(in.x[0] + a);
  const T dy = at<T>(in.x[1] + b) - at<T>(in.x[1] + a);
  const T dz = at<T>(in.x[2] + b) - at<T>(in.x[2] + a);
  const T l2 = dx * dx + dy * dy + dz * dz;
  T rate{};
  if constexpr (kDamped)
    rate = (at<T>(in.v[0] + b) - at<T>(in.v[0] + a)) * dx +
           (at<T>(in.v[1] + b) - at<T>(in.v[1] + a)) * dy +
           (at<T>(in.v[2] + b) - at<T>(in.v[2] + a)) * dz;
  const T s = spring_scale<kDamped>(l2, rate, law.ks, law.kd, law.rest,
                                    kLaw == Law::Measured ? &power : nullptr);
  g[0] = s * dx;
  g[1] = s * dy;
  g[2] = s * dz;
}

// The loops below take four springs at a time: `body.template operator()<T>(k, lanes)` is the
// same code for T = f64x4 (springs k .. k + 3, of which the first `lanes` exist: the others'
// forces are made zero) and T = double (spring k). The springs that do not fill a vector at the
// end go four at once too where `last_four_fit` (what the vector reads and writes beyond them
// is in memory the caller owns: adding a zero changes nothing there), else one at a time.
template <typename Body>
inline void four_at_a_time(int count, bool last_four_fit, const Body& body) {
  int k = 0;
  for (; k + kLanes <= count; k += kLanes) body.template operator()<f64x4>(k, kLanes);
  if (k < count && last_four_fit) return body.template operator()<f64x4>(k, count - k);
  for (; k < count; ++k) body.template operator()<double>(k, 1);
}

// g and the power with their lanes from `lanes` up set to zero.
inline void first_lanes(f64x4 g[3], f64x4& power, int lanes) {
  if (lanes < kLanes) {
    for (int c = 0; c < 3; ++c) g[c] = simd::first_lanes(g[c], lanes);
    power = simd::first_lanes(power, lanes);
  }
}
inline void first_lanes(double[3], double&, int) {}

// `count` springs joining a + k and b + k, b - a >= kLanes: g added to F at the a-ends and taken
// from it at the b-ends in the same loop (four springs at once never share a particle). F may be
// read and written below `limit`.
template <Law kLaw>
void springs_both(const SpringInput& in, double* const F[3], int a, int b, int count, SpanLaw law,
                  int limit, f64x4& power) {
  const int whole = count / kLanes * kLanes;
  four_at_a_time(count, b + whole + kLanes <= limit, [&]<typename T>(int k, int lanes) {
    T g[3], p{};
    spring_lanes<kLaw>(in, a + k, b + k, law, g, p);
    first_lanes(g, p, lanes);
    for (int c = 0; c < 3; ++c) {
      simd::store(F[c] + a + k, simd::at<T>(F[c] + a + k) + g[c]);
      simd::store(F[c] + b + k, simd::at<T>(F[c] + b + k) - g[c]);
    }
    if constexpr (kLaw == Law::Measured) accumulate(power, p);
  });
}

// `count` springs of a chain, joining a + k and a + kOffset + k with kOffset < kLanes (a rope's
// springs, a cloth's along its rows): four springs at once would touch some particles twice, so
// the loop runs over particles instead, each taking its own spring's g and giving back the one
// that ends there, kOffset springs earlier:
//   F[a + k] += g_k - g_{k - kOffset}    for k in [0, count + kOffset)
// (g is 0 outside [0, count)); g_{k - kOffset} comes from the vector before by a shuffle, so
// every force is loaded and stored once. F may be read and written below `limit`.
template <Law kLaw, int kOffset>
void springs_chain(const SpringInput& in, double* const F[3], int a, int count, SpanLaw law,
                   int limit, f64x4& power) {
  static_assert(kOffset >= 1 && kOffset < kLanes);
  f64x4 before[3] = {};  // g of the four springs before (zero before the first)
  const auto particles = [&](int k, const f64x4 g[3]) {
    for (int c = 0; c < 3; ++c) {
      simd::store(F[c] + a + k,
                  simd::load(F[c] + a + k) + (g[c] - simd::shifted_in<kOffset>(before[c], g[c])));
      before[c] = g[c];
    }
  };
  int k = 0;
  for (; k + kLanes <= count; k += kLanes) {
    f64x4 g[3], p{};
    spring_lanes<kLaw>(in, a + k, a + kOffset + k, law, g, p);
    particles(k, g);
    if constexpr (kLaw == Law::Measured) accumulate(power, p);
  }
  // The last springs and the kOffset particles past the last a-end, four at a time while what
  // that reads and writes is below `limit`, then one at a time.
  for (; k < count + kOffset && a + kOffset + k + kLanes <= limit; k += kLanes) {
    f64x4 g[3] = {}, p{};
    if (k < count) {
      spring_lanes<kLaw>(in, a + k, a + kOffset + k, law, g, p);
      first_lanes(g, p, count - k);
    }
    particles(k, g);
    if constexpr (kLaw == Law::Measured) accumulate(power, p);
  }
  if (k >= count + kOffset) return;
  // window[c][kLanes + j] is g of spring k + j: the vector before, then these, then zeros.
  const int left = count - k;  // fewer than kLanes
  double window[3][2 * kLanes + kOffset] = {};
  for (int c = 0; c < 3; ++c)
    for (int lane = 0; lane < kLanes; ++lane) window[c][lane] = before[c][lane];
  for (int j = 0; j < kLanes - 1 + kOffset && j < left + kOffset; ++j) {
    if (j < left) {
      double g[3], p = 0.0;
      spring_lanes<kLaw>(in, a + k + j, a + kOffset + k + j, law, g, p);
      for (int c = 0; c < 3; ++c) window[c][kLanes + j] = g[c];
      if constexpr (kLaw == Law::Measured) accumulate(power, p);
    }
    for (int c = 0; c < 3; ++c)
      F[c][a + k + j] += window[c][kLanes + j] - window[c][kLanes + j - kOffset];
  }
}

// Springs whose b-ends are in a later block: g added at the a-ends and kept in K for that block.
template <Law kLaw>
void springs_kept(const SpringInput& in, double* const F[3], int a, int b, int count, SpanLaw law,
                  double* const K[3], f64x4& power) {
  four_at_a_time(count, false, [&]<typename T>(int k, int) {
    T g[3], p{};
    spring_lanes<kLaw>(in, a + k, b + k, law, g, p);
    for (int c = 0; c < 3; ++c) {
      simd::store(F[c] + a + k, simd::at<T>(F[c] + a + k) + g[c]);
      simd::store(K[c] + k, g[c]);
    }
    if constexpr (kLaw == Law::Measured) accumulate(power, p);
  });
}

// Springs [lo, hi) of a span whose b-ends are all in the block being summed, which ends at
// particle `end`.
template <Law kLaw>
void springs_in_block(const SpringInput& in, double* const F[3], const SpringSpan& span, int lo,
                      int hi, SpanLaw law, int end, f64x4& power) {
  const int a = span.a0 + lo, count = hi - lo;
  switch (span.b0 - span.a0) {
    case 1:
      return springs_chain<kLaw, 1>(in, F, a, count, law, end, power);
    case 2:
      return springs_chain<kLaw, 2>(in, F, a, count, law, end, power);
    case 3:
      return springs_chain<kLaw, 3>(in, F, a, count, law, end, power);
    default:
      return springs_both<kLaw>(in, F, a, span.b0 + lo, count, law, end, power);
  }
}

// Calls f with std::integral_constant<Law, ...> for a span of damping kd.
template <typename F>
void with_law(double kd, bool measured, const F& f) {
  if (kd == 0.0)
    f(std::integral_constant<Law, Law::Elastic>{});
  else if (measured)
    f(std::integral_constant<Law, Law::Measured>{});
  else
    f(std::integral_constant<Law, Law::Damped>{});
}

// Waits until `flag` holds `value` (acquire): spins briefly, as the wait is usually short, then
// yields, so that a thread that is not running (more threads than cores) gets the core.
inline void wait_for(std::uint32_t& flag, std::uint32_t value) {
  threads::atomic_ref<std::uint32_t> ref(flag);
  threads::Team::wait([&] { return ref.load(std::memory_order_acquire) == value; });
}

inline void subtract(double* __restrict out, const double* __restrict f, int count) {
  for (int k = 0; k < count; ++k) out[k] -= f[k];
}

// The particles a block holds for a model of n (a multiple of 64): an eighth of them, at least
// 256 (enough blocks for the threads to share, few enough that little crosses between them; a
// block need not fit a cache, its chunks do), and at most 1024 until there are 16 blocks, so that
// a large model gives up to 16 threads a block each. A thread gains from a block of 1024 on: on a
// lent 16-core machine the 128 x 128 cloth's 16 blocks of 1024 ran symplectic Euler at 16 threads
// 1.8 times as fast as its 8 blocks of 2048, and implicit Euler's CG 1.2 to 1.35 times
// (docs/performance.md); below that the springs that cross a block's edge, which the CG's product
// computes on both sides, cost more (640 of the 6,100 a block there). Fixed by n alone: the
// blocks set the order of every particle's sum, the same for any thread count.
inline int block_particles(int n) {
  const auto multiple_of_64 = [](int k) { return (k + 63) / 64 * 64; };
  const int eighth = std::max(multiple_of_64(n / 8), 256);
  return std::max(multiple_of_64(n / 16), std::min(eighth, 1024));
}

// The plan of the pass for a model: its blocks (block_particles) and each block's pieces of spans.
inline void make_plan(const Model& model, ForcePlan& plan) {
  const int n = model.particle_count();
  plan.particles = n;
  plan.springs = model.spring_count();
  plan.spans = model.spans.data();
  plan.block = block_particles(n);
  const int blocks = std::max(1, (n + plan.block - 1) / plan.block);
  plan.own.assign(blocks, {});
  plan.incoming.assign(blocks, {});
  plan.source.resize(blocks);
  plan.done.assign(blocks, 0);
  plan.started.assign(blocks, 0);
  plan.passes = 0;
  plan.reach = 0;
  for (const SpringSpan& span : model.spans) plan.reach = std::max(plan.reach, span.b0 - span.a0);
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
  plan.chunk_first.assign(blocks + 1, 0);
  plan.chunk_own.clear();
  for (int b = 0; b < blocks; ++b) {
    const int begin = b * plan.block, end = std::min(n, begin + plan.block);
    for (int first = begin; first < end; first += kChunkParticles) {
      const int last = std::min(end, first + kChunkParticles);
      std::vector<ForcePlan::Piece>& mine = plan.chunk_own.emplace_back();
      for (const ForcePlan::Piece& piece : plan.own[b]) {
        const SpringSpan& span = model.spans[piece.span];
        const int lo = std::max(piece.lo, first - span.a0), hi = std::min(piece.hi, last - span.a0);
        if (lo < hi) mine.push_back({piece.span, lo, hi});
      }
    }
    plan.chunk_first[b + 1] = static_cast<int>(plan.chunk_own.size());
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
// called for each chunk [begin, end) of a block's particles, in order, as soon as their forces
// are complete. With `block_power` (one a block), also the power that spring damping and drag
// take out of each block's springs and particles: dissipation_power() (energy.hpp), summed by
// blocks.
// Long: its parts are the named lambdas in it (external, start, try_start, ensure_started, sweep,
// claim, pass), which share the pass's locals (the plan, the columns, the pass's number); as one
// function the compiler inlines them into the loops the benchmarks measure (docs/performance.md).
template <typename Finish>
void force_pass(const Model& model, const Points& x, const Points& v, double* const F[3],
                SpringForces& buffer, const Finish& finish, double* block_power = nullptr) {
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
  const SpringInput in{{X[0], X[1], X[2]}, {V[0], V[1], V[2]}};
  const auto law_of = [&](const SpringSpan& span) {
    const SpringMaterial& mat = model.materials[span.material];
    return SpanLaw{mat.ks, mat.kd, span.rest};
  };
  // A block's particles [begin, end) (plain variables where used: Clang 14 cannot capture
  // structured bindings in a lambda).
  const auto begin_of = [&](int blk) { return blk * plan.block; };
  const auto end_of = [&](int blk) { return std::min(n, (blk + 1) * plan.block); };
  // Springs [lo, inside) of an own piece have their b-end in the block, [inside, hi) beyond it.
  const auto inside = [](const ForcePlan::Piece& piece, const SpringSpan& span, int end) {
    return std::clamp(end - span.b0, piece.lo, piece.hi);
  };

  const bool measured = block_power != nullptr;
  const double* inv_mass = model.inv_mass.data();
  const double wind[3] = {model.wind.x(), model.wind.y(), model.wind.z()};

  // Gravity, drag and the fields: the forces F starts from, for particles [begin, end); measured,
  // the power drag takes out of the free ones, k_drag v . (v - wind).
  const auto external = [&](int begin, int end, f64x4& power) {
    // One loop for the three coordinates, four particles at a time. The constants are copied
    // (captured by value): a store of a force might otherwise change them, as far as the
    // compiler knows, and they would be loaded again after each.
    four_at_a_time(end - begin, false, [=]<typename T>(int k, int) {
      using simd::at;
      const int i = begin + k;
      const T m = at<T>(mass + i);
      for (int c = 0; c < 3; ++c)
        simd::store(F[c] + i, (m * g[c] + blow[c]) - drag * at<T>(V[c] + i));
    });
    for (const Attractor& field : model.attractors)
      for (int i = begin; i < end; ++i) {
        const Vec3 acc = field_acceleration(field, Vec3(X[0][i], X[1][i], X[2][i]));
        for (int c = 0; c < 3; ++c) F[c][i] += mass[i] * acc[c];
      }
    if (measured && drag != 0.0)
      four_at_a_time(end - begin, false, [&]<typename T>(int k, int) {
        using simd::at;
        const int i = begin + k;
        T dot{};
        for (int c = 0; c < 3; ++c) dot += at<T>(V[c] + i) * (at<T>(V[c] + i) - wind[c]);
        accumulate(power, drag * simd::where_greater(at<T>(inv_mass + i), 0.0, dot));
      });
  };
  // A block's last plan.reach particles hold the a-ends of the springs that leave it; step 1
  // starts those, step 2 the others, a chunk ahead of the springs that reach them.
  const auto tail = [&](int begin, int end) { return std::max(begin, end - plan.reach); };

  // Step 1 of a block: the springs reaching into later blocks, their forces added to their a-ends
  // and kept for those blocks, then published (release) for the threads whose step 2 waits.
  const std::uint32_t pass_number = ++plan.passes;
  std::uint32_t* done = plan.done.data();
  std::uint32_t* started = plan.started.data();
  const auto start = [&](int blk) {
    const int begin = begin_of(blk), end = end_of(blk);
    f64x4 power{};
    external(tail(begin, end), end, power);
    for (const ForcePlan::Piece& piece : plan.own[blk]) {
      const SpringSpan& span = model.spans[piece.span];
      const int from = inside(piece, span, end);
      if (from == piece.hi) continue;
      double* const kept[3] = {SF[0] + span.first + from, SF[1] + span.first + from,
                               SF[2] + span.first + from};
      const SpanLaw law = law_of(span);
      with_law(law.kd, measured, [&](auto kind) {
        springs_kept<decltype(kind)::value>(in, F, span.a0 + from, span.b0 + from, piece.hi - from,
                                            law, kept, power);
      });
    }
    if (measured) block_power[blk] = simd::sum(power);
    threads::atomic_ref<std::uint32_t>(done[blk]).store(pass_number, std::memory_order_release);
  };
  // Step 1 of a block by the first thread to claim it: false if another had.
  const auto try_start = [&](int blk) {
    threads::atomic_ref<std::uint32_t> claim(started[blk]);
    std::uint32_t old = claim.load(std::memory_order_relaxed);
    while (old != pass_number)
      if (claim.compare_exchange_weak(old, pass_number, std::memory_order_relaxed)) {
        start(blk);
        return true;
      }
    return false;
  };
  // Step 1 of a block done, by this thread if no other has claimed it (never waiting for a thread
  // that has not come: only for one that is doing it).
  const auto ensure_started = [&](int blk) {
    if (!try_start(blk)) wait_for(done[blk], pass_number);
  };

  // Step 2 of a block, chunk by chunk: the external forces of the particles the chunk's springs
  // reach (those step 1 did not start), the springs with both ends in the block and their a-ends
  // in the chunk, then the kept forces of the springs reaching into the chunk from earlier blocks
  // (waited for: another thread may start them), then finish(chunk).
  const auto sweep = [&](int blk) {
    const int begin = begin_of(blk), end = end_of(blk);
    ensure_started(blk);  // its own step 1, done here if its run's owner has not come
    bool waited = false;
    int started = begin;  // external forces are in F below this
    f64x4 power{};
    for (int first = begin; first < end; first += kChunkParticles) {
      const int last = std::min(end, first + kChunkParticles);
      const int reached = std::min(tail(begin, end), last + plan.reach);
      if (started < reached) external(started, reached, power);
      started = std::max(started, reached);
      const int chunk = plan.chunk_first[blk] + (first - begin) / kChunkParticles;
      for (const ForcePlan::Piece& piece : plan.chunk_own[chunk]) {
        const SpringSpan& span = model.spans[piece.span];
        const int lo = piece.lo, hi = inside(piece, span, end);
        if (lo >= hi) continue;
        const SpanLaw law = law_of(span);
        with_law(law.kd, measured, [&](auto kind) {
          springs_in_block<decltype(kind)::value>(in, F, span, lo, hi, law, end, power);
        });
      }
      for (const ForcePlan::Piece& piece : plan.incoming[blk]) {
        const SpringSpan& span = model.spans[piece.span];
        const int lo = std::max(piece.lo, first - span.b0), hi = std::min(piece.hi, last - span.b0);
        if (lo >= hi) continue;
        if (!waited) {
          for (int src = plan.source[blk]; src < blk; ++src) ensure_started(src);
          waited = true;
        }
        for (int c = 0; c < 3; ++c) subtract(F[c] + span.b0 + lo, SF[c] + span.first + lo, hi - lo);
      }
      finish(blk, first, last);
    }
    if (measured) block_power[blk] += simd::sum(power);
  };

  // Run by every thread of the team (threads.hpp: the helpers that come), or by the caller alone.
  // Each thread has a run of blocks. It starts them all (step 1, short: the springs leaving each
  // block), its last first, since the next run's first block waits for it. Then it sweeps them
  // (step 2) from the front, and when its own are done, sweeps the blocks left at the back of
  // another run: the cores of this machine slow down one at a time, and the faster one helps
  // rather than waits; a helper kept off its core by another program does nothing and is not
  // waited for (its blocks' step 1 is done by whoever needs it first, its run swept from the
  // back). A run's unclaimed blocks are one atomic word, the pass's number (24 bits), front and
  // back (20 bits each), set for every run before the team starts.
  const bool parallel = threads::worth_threads(springs + n);
  const int team =
      parallel ? std::min(threads::max_team(), blocks) : 1;  // (a thread a block at most)
  plan.runs.resize(team);
  const std::uint64_t tag = pass_number & 0xFFFFFFu;
  const auto word = [tag](std::uint64_t front, std::uint64_t back) {
    return tag << 40 | front << 20 | back;
  };
  const auto first_of = [&](int thread, int threads) { return blocks * thread / threads; };
  for (int r = 0; r < team; ++r)
    threads::atomic_ref<std::uint64_t>(plan.runs[r])
        .store(word(first_of(r, team), first_of(r + 1, team)), std::memory_order_relaxed);
  // Claims a block of run r, from the front (its owner) or the back; -1 when none is left.
  const auto claim = [&](int r, bool front) {
    threads::atomic_ref<std::uint64_t> run(plan.runs[r]);
    std::uint64_t old = run.load(std::memory_order_relaxed);
    for (;;) {
      const int f = static_cast<int>(old >> 20 & 0xFFFFF), b = static_cast<int>(old & 0xFFFFF);
      if (old >> 40 != tag || f >= b) return -1;  // not this pass's yet, or all claimed
      const std::uint64_t claimed = front ? word(f + 1, b) : word(f, b - 1);
      if (run.compare_exchange_weak(old, claimed, std::memory_order_relaxed))
        return front ? f : b - 1;
    }
  };
  // A thread's number is its run's; the runs are the team's whoever comes to do them (alone, the
  // caller does its own and then every other).
  const auto pass = [&](int, int thread) {
    const int first = first_of(thread, team), last = first_of(thread + 1, team);
    if (first < last) {
      try_start(last - 1);
      for (int blk = first; blk < last - 1; ++blk) try_start(blk);
    }
    for (int blk; (blk = claim(thread, true)) >= 0;) sweep(blk);
    for (int other = 1; other < team; ++other)
      for (int blk; (blk = claim((thread + other) % team, false)) >= 0;) {
        threads::atomic_ref<std::uint64_t>(plan.stolen).fetch_add(1, std::memory_order_relaxed);
        sweep(blk);
      }
  };
  threads::Team::run(team, pass);
}

}  // namespace springlab
