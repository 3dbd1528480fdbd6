// The force of one spring and its derivatives: pure functions, no loops, no model.
//
// With d = x_b - x_a, l = |d|, u = d / l, dv = v_b - v_a:
//   f_a = k_s (l - L) u + k_d (dv . u) u,      f_b = -f_a.
// The first term is Hooke's law with rest length L; the second damps only the spring's change of
// length ("damp only the internal, spring-driven motion"): a rigid translation or rotation has
// dv . u = 0 and is not slowed.
//
// Coincident ends (l = 0) have no direction: the force is zero there rather than NaN. For L = 0
// the spring is linear, f_a = k_s d, and this is also the exact value at l = 0.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "springlab/simd.hpp"

namespace springlab {

// Below this length (relative to the rest length, or absolute for L = 0) the ends are treated as
// coincident.
inline constexpr double kCoincident = 1e-12;

inline double coincident_length(double rest) {
  return kCoincident * (rest > 1.0 ? rest : 1.0);
}
inline bool coincident(double l, double rest) {
  return l <= coincident_length(rest);
}

// The factor s of f_a = s d, from l2 = |d|^2 and rate = dv . d:
//   s = (k_s (l - L) + k_d rate / l) / l
// with 1/l computed as l (1/l^2), so that the division need not wait for the square root, and
// set to 0 for coincident ends (selected, not branched, so that it vectorises). A template on
// its number type: double, or simd::f64x4 for four springs at once, with the same bits lane by
// lane. Undamped springs (kDamped = false) skip the rate: (k_s (l - L) + 0) / l is the same number.
// With `power`, also the power the damping takes out: k_d (dv . u)^2 = (k_d rate / l)(rate / l).
template <bool kDamped, typename T>
inline T spring_scale(T l2, T rate, double ks, double kd, double rest, T* power = nullptr) {
  const T l = simd::sqrt(l2);
  const T inv = simd::where_greater(l, coincident_length(rest), l * (1.0 / l2));
  if constexpr (kDamped) {
    const T damping = kd * rate * inv;
    if (power) *power = damping * (rate * inv);
    return (ks * (l - rest) + damping) * inv;
  } else {
    return ks * (l - rest) * inv;
  }
}

// Force on end a.
inline Eigen::Vector3d spring_force(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                                    const Eigen::Vector3d& va, const Eigen::Vector3d& vb, double ks,
                                    double kd, double rest) {
  // The very arithmetic of the force pass (force_pass.hpp), so both give the same bits.
  const Eigen::Vector3d d = xb - xa;
  const Eigen::Vector3d dv = vb - va;
  const double l2 = d.x() * d.x() + d.y() * d.y() + d.z() * d.z();
  const double rate = dv.x() * d.x() + dv.y() * d.y() + dv.z() * d.z();
  return spring_scale<true>(l2, rate, ks, kd, rest) * d;
}

// Potential energy k_s (l - L)^2 / 2.
inline double spring_energy(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb, double ks,
                            double rest) {
  const double stretch = (xb - xa).norm() - rest;
  return 0.5 * ks * stretch * stretch;
}

// The 3x3 blocks of the Jacobian of f_a with respect to the other end:
//   dfdx = d f_a / d x_b,  dfdv = d f_a / d v_b.
// The other blocks follow from f_b = -f_a and f depending on differences only:
//   d f_a / d x_a = -dfdx,  d f_b / d x_b = -dfdx,  d f_b / d x_a = dfdx (likewise for v).
struct SpringJacobian {
  Eigen::Matrix3d dfdx;
  Eigen::Matrix3d dfdv;
};

// Exact derivatives, with P = I - u u^T (the projection across the spring):
//   elastic:   k_s [ u u^T + (1 - L/l) P ]
//   damping:   (k_d / l) [ u dv^T P + (dv . u) P ]            (depends on x through u)
//   dfdv:      k_d u u^T
// For implicit integration pass definite = true: the transverse factor (1 - L/l), negative for a
// compressed spring, is clamped at zero and the non-symmetric damping term is dropped, which
// keeps M - h df/dv - h^2 df/dx symmetric positive definite (Choi and Ko 2002; Baraff and
// Witkin 1998 make the same choice). Along the spring both forms agree.
inline SpringJacobian spring_jacobian(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                                      const Eigen::Vector3d& va, const Eigen::Vector3d& vb,
                                      double ks, double kd, double rest, bool definite) {
  const Eigen::Vector3d d = xb - xa;
  const double l = d.norm();
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  SpringJacobian J;
  if (coincident(l, rest)) {
    // Only the linear zero-length spring has a derivative here: f_a = k_s d.
    J.dfdx = rest == 0.0 ? Eigen::Matrix3d(ks * I) : Eigen::Matrix3d::Zero();
    J.dfdv.setZero();
    return J;
  }
  const Eigen::Vector3d u = d / l;
  const Eigen::Matrix3d uu = u * u.transpose();
  const Eigen::Matrix3d P = I - uu;
  double transverse = 1.0 - rest / l;
  if (definite && transverse < 0.0) transverse = 0.0;
  J.dfdx = ks * (uu + transverse * P);
  if (!definite && kd != 0.0) {
    const Eigen::Vector3d dv = vb - va;
    J.dfdx += (kd / l) * (u * (P * dv).transpose() + dv.dot(u) * P);
  }
  J.dfdv = kd * uu;
  return J;
}

// The definite Jacobian above in the compact form the implicit solver keeps, three numbers a
// spring that depend on its length only. With d = x_b - x_a (not normalised), l = |d|,
// u u^T = d d^T / l^2 and P = I - u u^T: k_s [u u^T + t P] = k_s [(1 - t) u u^T + t I], so
//   dfdx = stiff_along d d^T + stiff_across I,  stiff_along = k_s (1 - t) / l^2,
//                                               stiff_across = k_s t,  t = max(0, 1 - L/l)
//   dfdv = damp_along d d^T,                    damp_along = k_d / l^2.
// Coincident ends as above: t = 1 for the zero-length spring (k_s I), else zero. Written with
// selects, not branches, so that a loop over springs vectorises.
struct DefiniteSpringJacobian {
  double stiff_along = 0.0;
  double stiff_across = 0.0;
  double damp_along = 0.0;
};

inline DefiniteSpringJacobian definite_spring_jacobian(double length_squared, double ks, double kd,
                                                       double rest) {
  const double l = std::sqrt(length_squared);
  const bool apart = !coincident(l, rest);
  const double inv_l2 = apart ? 1.0 / length_squared : 0.0;
  const double t = apart ? std::max(0.0, 1.0 - rest / l) : (rest == 0.0 ? 1.0 : 0.0);
  return {ks * (1.0 - t) * inv_l2, ks * t, kd * inv_l2};
}

}  // namespace springlab
