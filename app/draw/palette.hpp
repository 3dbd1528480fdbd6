// Colours used everywhere in springlab: one per method (the scene view, the charts, the legends
// and the SVG and PNG charts all agree), and the strain colour map of springs.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "draw/frame.hpp"
#include "session/session.hpp"
#include "springlab/ik.hpp"
#include "springlab/methods.hpp"

namespace springlab::draw {

// One colour per method, the same in the scene, the charts, the legends and the SVG and PNG
// charts: Okabe and Ito's palette for colour-blind viewers, on a dark background and a projector.
// The five compared most (every shipped scene's lanes are among explicit Euler, symplectic Euler,
// RK4, Verlet and implicit Euler) take its five most distinct hues, for protanopes and
// deuteranopes too: vermilion, sky blue, bluish green, yellow and reddish purple; the rest take
// orange, light grey, slate and a violet, and are seldom beside the ones they resemble; the
// iterative rows (what games use) salmon, lime and aquamarine, apart from the lecture's; the
// first rows made from tableaux six more. Measured (tests/app/palette_test.cpp): the five lecture
// rows stay 7.8 CIEDE2000 apart or more under simulated protanopia, deuteranopia and
// tritanopia; the lanes a lesson shows together 7.5; any two rows 4 (and each has its mark,
// draw/marks.hpp); each at least 4.5:1 as text on the panels. By the method's row in the table (methods()), in its order; a
// row past the lists takes a hue of its own, turned by the golden angle from the last.
inline Rgba method_color(Method m) {
  static constexpr Rgba kByRow[] = {
      {0.90f, 0.38f, 0.00f, 1},  // euler: vermilion  #E66100
      {0.34f, 0.71f, 0.91f, 1},  // symplectic-euler: sky blue   #56B4E9
      {0.90f, 0.62f, 0.00f, 1},  // midpoint: orange     #E69F00
      {0.78f, 0.78f, 0.78f, 1},  // modified-euler: light grey
      {0.00f, 0.66f, 0.48f, 1},  // rk4: bluish green #00A87A
      {0.50f, 0.60f, 0.60f, 1},  // adaptive-euler: slate #80999A
      {0.62f, 0.50f, 0.98f, 1},  // rk45: violet
      {0.85f, 0.52f, 0.78f, 1},  // implicit-euler: reddish purple #D985C7
      {0.94f, 0.89f, 0.26f, 1},  // verlet: yellow     #F0E442
      {1.00f, 0.50f, 0.50f, 1},  // xpbd: salmon #FF8080
      {0.65f, 0.85f, 0.33f, 1},  // local-global: lime #A6D854
      {0.00f, 1.00f, 0.90f, 1},  // vbd: aquamarine #00FFE6
  };
  // Rows made from tableaux (add_tableau_method): hues apart from the built-in rows'.
  static constexpr Rgba kAdded[] = {
      {0.00f, 0.85f, 0.95f, 1},  // cyan
      {1.00f, 0.78f, 0.55f, 1},  // peach (lesson 12 sets it beside implicit Euler: apart from its purple)
      {0.80f, 0.60f, 0.35f, 1},  // tan
      {0.55f, 0.62f, 1.00f, 1},  // periwinkle
      {0.60f, 1.00f, 0.80f, 1},  // mint
      {1.00f, 0.60f, 0.80f, 1},  // pink
  };
  const auto row = static_cast<std::size_t>(m);
  if (row < std::size(kByRow)) return kByRow[row];
  if (row - std::size(kByRow) < std::size(kAdded)) return kAdded[row - std::size(kByRow)];
  const float hue = std::fmod(0.61803398875f * static_cast<float>(row), 1.0f);
  const auto channel = [&](float offset) {
    return 0.55f + 0.35f * std::cos(6.28318530718f * (hue + offset));
  };
  return {channel(0.0f), channel(-1.0f / 3.0f), channel(1.0f / 3.0f), 1};
}

// A lane's colour: its row's, its IK solver's, or, for a lane of one's own (homework), one of two
// kept for those, apart from every row's: white and rose.
inline Rgba lane_color(const app::Lane& lane);

// The IK solvers, distinct from one another in compare mode (the same hues).
inline Rgba solver_color(IkSolver s) {
  switch (s) {
    case IkSolver::CCD: return {0.90f, 0.38f, 0.00f, 1};     // vermilion
    case IkSolver::FABRIK: return {0.34f, 0.71f, 0.91f, 1};  // sky blue
    case IkSolver::DLS: return {0.00f, 0.66f, 0.48f, 1};     // bluish green
  }
  return {1, 1, 1, 1};
}

// A lane that diverged is faded, its label in this red.
inline constexpr Rgba kDiverged{1.0f, 0.36f, 0.32f, 1};

inline std::string hex(const Rgba& c) {
  char s[8];
  const auto byte = [](float x) { return static_cast<int>(std::clamp(x, 0.0f, 1.0f) * 255.0f + 0.5f); };
  std::snprintf(s, sizeof s, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return s;
}

inline Rgba mix(const Rgba& a, const Rgba& b, float t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t, a.a + (b.a - a.a) * t};
}

// Strain (l - L) / L to colour: blue compressed, light grey at rest, red stretched; saturated
// at +-`scale`.
inline Rgba strain_color(double strain, double scale) {
  const Rgba rest{0.82f, 0.84f, 0.86f, 1}, compressed{0.25f, 0.55f, 1.0f, 1}, stretched{1.0f, 0.30f, 0.22f, 1};
  const float t = static_cast<float>(std::clamp(strain / scale, -1.0, 1.0));
  return t < 0 ? mix(rest, compressed, -t) : mix(rest, stretched, t);
}

inline constexpr Rgba kGrabbed{1.0f, 0.85f, 0.2f, 1};
inline constexpr Rgba kTarget{1.0f, 0.30f, 0.35f, 1};     // an IK chain's target
inline constexpr Rgba kReach{0.60f, 0.64f, 0.70f, 0.45f};  // the circles an IK chain can reach
inline constexpr Rgba kAttractor{0.62f, 0.45f, 0.95f, 1};
inline constexpr Rgba kParticle{0.92f, 0.93f, 0.95f, 1};
inline constexpr Rgba kClothFront{0.93f, 0.55f, 0.28f, 1};
inline constexpr Rgba kClothBack{0.28f, 0.60f, 0.72f, 1};
inline constexpr Rgba kCollider{0.55f, 0.58f, 0.64f, 1};

inline Rgba lane_color(const app::Lane& lane) {
  static constexpr Rgba kOwn[] = {{0.96f, 0.96f, 0.96f, 1}, {1.00f, 0.36f, 0.54f, 1}};  // white, rose #FF5C8A
  if (!lane.own.empty()) return kOwn[static_cast<std::size_t>(lane.own_index) % std::size(kOwn)];
  return lane.ik ? solver_color(lane.ik->solver) : method_color(lane.sim.settings().method);
}

}  // namespace springlab::draw
