// Four doubles at once, for the few loops the compiler cannot vectorise by itself (the force
// pass: a spring's force lands on particles that a neighbouring spring of the same vector also
// touches). A GCC/Clang vector extension, not intrinsics: the same source gives AVX2 code when
// built with -mavx2 and SSE2 pairs otherwise, and every operation is the IEEE operation of the
// scalar code lane by lane, so a loop written once for `double` and for `f64x4` gives the same
// bits either way (no FMA: -ffp-contract=off).
//
// The functions are overloaded for double too, so that a kernel written as a template on its
// number type serves the vector body and the scalar remainder of a loop alike.
#pragma once

#include <cmath>

namespace springlab::simd {

using f64x4 = double __attribute__((vector_size(32)));
inline constexpr int kLanes = 4;

// Loads and stores at any address of a double (one vmovupd), through a packed struct (Clang
// honours no lesser alignment on a vector typedef). Accessed as doubles, not as bytes (as memcpy
// would), so the compiler knows that a store of forces changes no pointer it holds.
struct [[gnu::packed]] Unaligned {
  f64x4 v;
};

inline f64x4 load(const double* p) {
  return reinterpret_cast<const Unaligned*>(p)->v;
}
inline void store(double* p, f64x4 v) {
  reinterpret_cast<Unaligned*>(p)->v = v;
}
inline void store(double* p, double v) {
  *p = v;
}

// load as the type T: `at<f64x4>(p)` reads p[0..3], `at<double>(p)` reads p[0].
template <typename T>
T at(const double* p) {
  if constexpr (sizeof(T) == sizeof(double))
    return *p;
  else
    return load(p);
}

inline f64x4 sqrt(f64x4 v) {
  return f64x4{std::sqrt(v[0]), std::sqrt(v[1]), std::sqrt(v[2]), std::sqrt(v[3])};
}
inline double sqrt(double v) {
  return std::sqrt(v);
}

// x where a > b, else 0 (lane by lane): a compare and a mask, no branch.
inline f64x4 where_greater(f64x4 a, double b, f64x4 x) {
  return a > b ? x : f64x4{};
}
inline double where_greater(double a, double b, double x) {
  return a > b ? x : 0.0;
}

// v's lanes [0, count), zeros above.
inline f64x4 first_lanes(f64x4 v, int count) {
  const f64x4 lane = {0.0, 1.0, 2.0, 3.0};
  return lane < static_cast<double>(count) ? v : f64x4{};
}

// The lanes of `cur` moved up by K, the last K lanes of `prev` coming in below:
// shifted_in<1>(p, c) = {p3, c0, c1, c2}. Two shuffles at most.
template <int K>
f64x4 shifted_in(f64x4 prev, f64x4 cur) {
  static_assert(K >= 1 && K <= 3);
  if constexpr (K == 1)
    return __builtin_shufflevector(prev, cur, 3, 4, 5, 6);
  else if constexpr (K == 2)
    return __builtin_shufflevector(prev, cur, 2, 3, 4, 5);
  else
    return __builtin_shufflevector(prev, cur, 1, 2, 3, 4);
}

// (v0 + v1) + (v2 + v3): a fixed order, so the same bits every time.
inline double sum(f64x4 v) {
  return (v[0] + v[1]) + (v[2] + v[3]);
}

}  // namespace springlab::simd
