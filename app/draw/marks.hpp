// Marks: a shape per method, drawn on a chart's points, along its lines and on its legend's
// swatches, so that lanes are told apart by more than colour (a colour-blind student, a grey
// print, a washed-out projector). Filled and hollow circles, squares, diamonds and triangles, a
// plus and a cross: twelve shapes, each method's given by its row (draw/row_styles.cpp).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "draw/row_styles.hpp"
#include "session/session.hpp"
#include "springlab/methods.hpp"

namespace springlab::draw {

inline bool hollow(Mark m) {
  switch (m) {
    case Mark::RingCircle:
    case Mark::RingSquare:
    case Mark::RingDiamond:
    case Mark::RingTriangleUp:
    case Mark::RingTriangleDown:
      return true;
    default:
      return false;
  }
}
inline bool strokes(Mark m) {
  return m == Mark::Plus || m == Mark::Cross;
}

// The outline of a shape of radius 1 about (0, 0), y down (a screen's): a circle as 16 sides;
// a plus or a cross as two segments (four points).
inline std::vector<std::array<float, 2>> mark_outline(Mark m) {
  switch (m) {
    case Mark::Square:
    case Mark::RingSquare:
      return {{-0.8f, -0.8f}, {0.8f, -0.8f}, {0.8f, 0.8f}, {-0.8f, 0.8f}};
    case Mark::Diamond:
    case Mark::RingDiamond:
      return {{0.0f, -1.1f}, {1.1f, 0.0f}, {0.0f, 1.1f}, {-1.1f, 0.0f}};
    case Mark::TriangleUp:
    case Mark::RingTriangleUp:
      return {{0.0f, -1.15f}, {1.05f, 0.7f}, {-1.05f, 0.7f}};
    case Mark::TriangleDown:
    case Mark::RingTriangleDown:
      return {{0.0f, 1.15f}, {-1.05f, -0.7f}, {1.05f, -0.7f}};
    case Mark::Plus:
      return {{-1.1f, 0.0f}, {1.1f, 0.0f}, {0.0f, -1.1f}, {0.0f, 1.1f}};
    case Mark::Cross:
      return {{-0.85f, -0.85f}, {0.85f, 0.85f}, {-0.85f, 0.85f}, {0.85f, -0.85f}};
    case Mark::None:
      return {};
    default: {
      std::vector<std::array<float, 2>> circle;
      for (int k = 0; k < 16; ++k) {
        const float a = 0.39269908f * static_cast<float>(k);
        circle.push_back({0.9f * std::cos(a), 0.9f * std::sin(a)});
      }
      return circle;
    }
  }
}

// A method's mark: its row's (draw/row_styles.cpp).
inline Mark method_mark(Method m) {
  return method_style(m).mark;
}

// A lane's: its row's (a method's or an IK solver's), or for a lane of one's own (homework) a cross
// or a plus (the reference lanes beside it are the Euler rows' and Verlet's).
inline Mark lane_mark(const app::Lane& lane) {
  if (!lane.own.empty()) return lane.own_index % 2 == 0 ? Mark::Cross : Mark::Plus;
  return row_style(app::lane_row(lane)).mark;
}

}  // namespace springlab::draw
