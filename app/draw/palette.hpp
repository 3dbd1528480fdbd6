// Colours used everywhere in springlab: one per method (the scene view, the charts, the legends
// and the SVG and PNG charts all agree), and the strain colour map of springs.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "draw/frame.hpp"
#include "draw/row_styles.hpp"
#include "session/session.hpp"
#include "springlab/methods.hpp"

namespace springlab::draw {

// A method's colour: its row's (draw/row_styles.cpp, chosen and measured there), the same in
// the scene, the charts, the legends and the SVG and PNG charts.
inline Rgba method_color(Method m) {
  const std::array<float, 3> c = method_style(m).colour;
  return {c[0], c[1], c[2], 1};
}

// A lane row's colour (a method's or an IK solver's: its table's).
inline Rgba row_color(const app::LaneRow& row) {
  const std::array<float, 3> c = row_style(row).colour;
  return {c[0], c[1], c[2], 1};
}

// A lane's colour: its row's, or, for a lane of one's own (homework), one of two kept for those,
// apart from every row's: white and rose.
inline Rgba lane_color(const app::Lane& lane);

// A lane that diverged is faded, its label in this red.
inline constexpr Rgba kDiverged{1.0f, 0.36f, 0.32f, 1};

inline std::string hex(const Rgba& c) {
  char s[8];
  const auto byte = [](float x) {
    return static_cast<int>(std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f));
  };
  std::snprintf(s, sizeof s, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return s;
}

inline Rgba mix(const Rgba& a, const Rgba& b, float t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t,
          a.a + (b.a - a.a) * t};
}

// Strain (l - L) / L to colour: blue compressed, light grey at rest, red stretched; saturated
// at +-`scale`.
inline Rgba strain_color(double strain, double scale) {
  const Rgba rest{0.82f, 0.84f, 0.86f, 1}, compressed{0.25f, 0.55f, 1.0f, 1},
      stretched{1.0f, 0.30f, 0.22f, 1};
  const float t = static_cast<float>(std::clamp(strain / scale, -1.0, 1.0));
  return t < 0 ? mix(rest, compressed, -t) : mix(rest, stretched, t);
}

inline constexpr Rgba kGrabbed{1.0f, 0.85f, 0.2f, 1};
inline constexpr Rgba kTarget{1.0f, 0.30f, 0.35f,
                              1};  // a scene kind's handle (an IK chain's target)
inline constexpr Rgba kReach{0.60f, 0.64f, 0.70f,
                             0.45f};  // a scene kind's guides (what an IK chain can reach)
inline constexpr Rgba kAttractor{0.62f, 0.45f, 0.95f, 1};
inline constexpr Rgba kParticle{0.92f, 0.93f, 0.95f, 1};
inline constexpr Rgba kClothFront{0.93f, 0.55f, 0.28f, 1};
inline constexpr Rgba kClothBack{0.28f, 0.60f, 0.72f, 1};
inline constexpr Rgba kCollider{0.55f, 0.58f, 0.64f, 1};

inline Rgba lane_color(const app::Lane& lane) {
  static constexpr Rgba kOwn[] = {{0.96f, 0.96f, 0.96f, 1},
                                  {1.00f, 0.36f, 0.54f, 1}};  // white, rose #FF5C8A
  if (!lane.own.empty()) return kOwn[static_cast<std::size_t>(lane.own_index) % std::size(kOwn)];
  return row_color(app::lane_row(lane));
}

}  // namespace springlab::draw
