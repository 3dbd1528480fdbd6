#include "springlab/exact.hpp"

#include <cmath>

namespace springlab {

std::optional<ExactOscillator> ExactOscillator::detect(const Model& model, const State& initial) {
  if (model.particle_count() != 2 || model.spring_count() != 1 || model.has_colliders() ||
      model.gravity.squaredNorm() != 0.0)
    return std::nullopt;
  const int a = model.spring_a[0], b = model.spring_b[0];
  if (model.pinned(a) == model.pinned(b)) return std::nullopt;
  ExactOscillator e;
  e.anchor_ = model.pinned(a) ? a : b;
  e.particle_ = model.pinned(a) ? b : a;
  if (initial.v.row(e.anchor_).squaredNorm() != 0.0) return std::nullopt;
  const Vec3 d = (initial.x.row(e.particle_) - initial.x.row(e.anchor_)).transpose();
  const double l = d.norm();
  if (l == 0.0) return std::nullopt;
  e.axis_ = d / l;
  const Vec3 v = initial.v.row(e.particle_).transpose();
  // Moving along the spring only (else the motion is a 2D orbit with no closed form here).
  if ((v - v.dot(e.axis_) * e.axis_).norm() > 1e-12 * (1.0 + v.norm())) return std::nullopt;
  const double m = model.mass[e.particle_];
  e.rest_ = model.rest_length[0];
  e.y0_ = l - e.rest_;
  e.v0_ = v.dot(e.axis_);
  e.w_ = std::sqrt(model.ks(0) / m);
  e.c_ = (model.kd(0) + model.drag) / m;
  if (e.w_ == 0.0) return std::nullopt;
  // A bound on |y(t)| from the closed forms below (damping only shrinks the envelope); it must
  // stay under the rest length so that the particle never reaches the anchor.
  const double half = 0.5 * e.c_, disc = half * half - e.w_ * e.w_;
  double amplitude;
  if (disc < 0.0) {
    const double B = (e.v0_ + half * e.y0_) / std::sqrt(-disc);
    amplitude = std::sqrt(e.y0_ * e.y0_ + B * B);
  } else if (disc <= 1e-12 * e.w_ * e.w_) {  // critical: |(A + B t) e^(-w t)| <= |A| + |B| / (e w)
    amplitude = std::abs(e.y0_) + std::abs(e.v0_ + e.w_ * e.y0_) / (std::exp(1.0) * e.w_);
  } else {  // overdamped: |A e^(r1 t) + B e^(r2 t)| <= |A| + |B|
    const double root = std::sqrt(disc), r1 = -half - root, r2 = -half + root;
    const double B = (e.v0_ - r1 * e.y0_) / (r2 - r1);
    amplitude = std::abs(e.y0_ - B) + std::abs(B);
  }
  if (!(amplitude < e.rest_)) return std::nullopt;
  e.initial_ = initial;
  return e;
}

State ExactOscillator::at(double time) const {
  const double t = time - initial_.t;
  double y, v;
  const double half = 0.5 * c_;
  const double disc = half * half - w_ * w_;
  if (std::abs(disc) <= 1e-12 * w_ * w_) {  // critical
    const double A = y0_, B = v0_ + w_ * y0_;
    const double e = std::exp(-w_ * t);
    y = e * (A + B * t);
    v = e * (B - w_ * (A + B * t));
  } else if (disc < 0.0) {  // underdamped
    const double wd = std::sqrt(-disc);
    const double A = y0_, B = (v0_ + half * y0_) / wd;
    const double e = std::exp(-half * t), cs = std::cos(wd * t), sn = std::sin(wd * t);
    y = e * (A * cs + B * sn);
    v = e * ((-half * A + wd * B) * cs + (-half * B - wd * A) * sn);
  } else {  // overdamped
    const double root = std::sqrt(disc);
    const double r1 = -half - root, r2 = -half + root;
    const double B = (v0_ - r1 * y0_) / (r2 - r1), A = y0_ - B;
    y = A * std::exp(r1 * t) + B * std::exp(r2 * t);
    v = A * r1 * std::exp(r1 * t) + B * r2 * std::exp(r2 * t);
  }
  State s = initial_;
  s.t = time;
  s.x.row(particle_) = s.x.row(anchor_) + ((rest_ + y) * axis_).transpose();
  s.v.row(particle_) = (v * axis_).transpose();
  return s;
}

}  // namespace springlab
