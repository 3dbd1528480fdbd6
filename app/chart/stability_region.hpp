// The stability-region chart: where a method is stable, with the scene's modes placed in it at
// the step h, a mode outside the region drawn red, and by how much h must shrink for all to be
// inside. Drawn live in the app (the dt slider moves the dots) and written by `compare`.
//
//   euler, midpoint, rk4, implicit-euler   the complex plane of z = h lambda: the region
//       |R(z)| <= 1 of the method's stability function, the eigenvalues lambda of the scene's
//       first-order system as dots (a large scene: the bounds of its spectrum, the boundary of
//       the joint numerical range mapped to eigenvalues, within which every one lies)
//   symplectic-euler, verlet, modified-euler   these are not Runge-Kutta methods on y' = A y:
//       they have no region in that plane. They have one in the plane of the damped oscillator
//       x'' = -w^2 x - c x', (h w, h c), where each mode of the scene is a point (w^2 and c its
//       stiffness and damping); the chart says so.
#pragma once

#include <string>
#include <vector>

#include "chart/chart.hpp"
#include "springlab/stability.hpp"

namespace springlab::chart {

enum class RegionPlane {
  Complex,     // z = h lambda
  Oscillator,  // (h w, h c)
};
RegionPlane region_plane(Method method);

struct RegionLane {
  Method method;
  double h = 0.0;  // the lane's integrator step
};

// One chart for the lanes whose methods share a plane (the first lane's plane decides; lanes of
// the other plane are left out: draw a second chart for them). `analysis` is the scene's.
Chart stability_region(const StabilityAnalysis& analysis, const std::vector<RegionLane>& lanes);

// "every mode inside: h may grow x1.6", "2 modes outside: h must shrink x0.62 (to 1.2e-4 s)".
std::string region_verdict(const StabilityAnalysis& analysis, const RegionLane& lane);

}  // namespace springlab::chart
