// Force fields a particle scene may declare beside gravity and drag (docs/numerics.md, "The model":
// only where declared): an attractor, optionally swirling (a vortex). Accelerations, so f = m a.
//
// With d = c - x and q = |d|^2 + eps^2 (eps, the softening, keeps the pull finite at the centre):
//   pull    a = S d / q^(3/2)                         S = strength, m^3/s^2 (G M of a point mass)
//           potential per unit mass  -S / sqrt(q);    da/dx = S (3 d d^T / q^(5/2) - I / q^(3/2))
// With r = x - c, its part across the axis p = r - (r . k) k and q_p = |p|^2 + eps^2:
//   swirl   a = W (k x p) / q_p                       W = swirl, m^2/s^2: circles about the axis,
//           not a gradient (no potential): it feeds energy in or takes it out.
//           da/dx = W ([k]x / q_p - 2 (k x p) p^T / q_p^2)     ([k]x p = k x p; [k]x k = 0)
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace springlab {

struct Attractor {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double strength = 0.0;   // S, m^3/s^2; negative repels
  double softening = 0.1;  // eps, m, > 0
  double swirl = 0.0;      // W, m^2/s^2; positive turns counter-clockwise seen from +axis
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();  // unit length
};

inline Eigen::Vector3d field_acceleration(const Attractor& f, const Eigen::Vector3d& x) {
  const double eps2 = f.softening * f.softening;
  const Eigen::Vector3d d = f.center - x;
  const double q = d.squaredNorm() + eps2;
  Eigen::Vector3d a = (f.strength / (q * std::sqrt(q))) * d;
  if (f.swirl != 0.0) {
    const Eigen::Vector3d p = -d - (-d).dot(f.axis) * f.axis;
    a += (f.swirl / (p.squaredNorm() + eps2)) * f.axis.cross(p);
  }
  return a;
}

// d a / d x, 3 x 3 (not symmetric when there is swirl).
inline Eigen::Matrix3d field_jacobian(const Attractor& f, const Eigen::Vector3d& x) {
  const double eps2 = f.softening * f.softening;
  const Eigen::Vector3d d = f.center - x;
  const double q = d.squaredNorm() + eps2;
  const double q32 = q * std::sqrt(q);
  Eigen::Matrix3d J =
      f.strength * (3.0 * d * d.transpose() / (q32 * q) - Eigen::Matrix3d::Identity() / q32);
  if (f.swirl != 0.0) {
    const Eigen::Vector3d p = -d - (-d).dot(f.axis) * f.axis;
    const double qp = p.squaredNorm() + eps2;
    Eigen::Matrix3d K;
    K << 0, -f.axis.z(), f.axis.y(), f.axis.z(), 0, -f.axis.x(), -f.axis.y(), f.axis.x(), 0;
    J += f.swirl * (K / qp - 2.0 * f.axis.cross(p) * p.transpose() / (qp * qp));
  }
  return J;
}

// Potential energy per unit mass of the pull (the swirl has none).
inline double field_potential(const Attractor& f, const Eigen::Vector3d& x) {
  return -f.strength / std::sqrt((f.center - x).squaredNorm() + f.softening * f.softening);
}

}  // namespace springlab
