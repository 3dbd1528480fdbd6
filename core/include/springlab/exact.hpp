// Exact solutions, where a scene has one: a single free particle on a spring to a pinned anchor,
// moving along the spring, with no gravity or colliders. With y the stretch, w^2 = k_s / m and
// c = (k_d + k_drag) / m, the motion y'' = -w^2 y - c y' is solved in closed form:
//   underdamped  (c < 2w)  y = e^(-c t / 2) (A cos(w_d t) + B sin(w_d t)),  w_d = sqrt(w^2 - c^2/4)
//   critical     (c = 2w)  y = e^(-w t) (A + B t)
//   overdamped   (c > 2w)  y = A e^(r1 t) + B e^(r2 t),  r = -c/2 -+ sqrt(c^2/4 - w^2)
// The reference `spring` scene gives x(t) = 1 + 0.5 cos(10 t).
#pragma once

#include <optional>

#include "springlab/model.hpp"
#include "springlab/state.hpp"

namespace springlab {

class ExactOscillator {
 public:
  // The exact solution from `initial`, if the scene is such an oscillator (and the particle never
  // reaches the anchor, where the spring would flip).
  static std::optional<ExactOscillator> detect(const Model& model, const State& initial);

  State at(double t) const;  // every particle's position and velocity at time t (>= initial.t)

  double w() const { return w_; }
  double c() const { return c_; }

 private:
  State initial_;
  int anchor_ = 0, particle_ = 1;
  Vec3 axis_ = Vec3::UnitX();  // from the anchor to the particle
  double rest_ = 1.0, y0_ = 0.0, v0_ = 0.0, w_ = 0.0, c_ = 0.0;
};

}  // namespace springlab
