// How a lane's row is shown: its colour and its mark, the app's own table keyed by the row (a
// method's or an IK solver's), so that the core says what a method is and never how it looks. The
// scene, the charts, the legends and the SVG and PNG charts all read it; tests/app/palette_test.cpp
// holds the colours apart under colour blindness and as text on the panels.
#pragma once

#include <array>

#include "session/scene_kind.hpp"
#include "springlab/ik.hpp"
#include "springlab/methods.hpp"

namespace springlab::draw {

// The shape drawn with a lane's lines on charts and legends (draw/marks.hpp), so that lanes are
// told apart by more than colour: filled, hollow, or strokes.
enum class Mark {
  None,
  Circle,
  Square,
  Diamond,
  TriangleUp,
  TriangleDown,  // filled
  RingCircle,
  RingSquare,
  RingDiamond,
  RingTriangleUp,
  RingTriangleDown,  // hollow
  Plus,
  Cross,  // strokes
};

struct RowStyle {
  std::array<float, 3> colour;  // sRGB, each channel in [0, 1]
  Mark mark;
};

// A method's: a built-in row's from the table in row_styles.cpp; a row added at run time
// (add_method, add_tableau_method) one of the added rows' colours in turn and a built-in row's
// mark again.
RowStyle method_style(Method method);
// An IK solver's: the lecture's hues, apart from one another, a mark each.
RowStyle ik_solver_style(IkSolver solver);
// A lane row's: its table's (a kind of one's own's rows take the added rows' styles in turn).
RowStyle row_style(const app::LaneRow& row);

}  // namespace springlab::draw
