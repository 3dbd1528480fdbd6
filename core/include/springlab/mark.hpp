// A lane's mark: the shape drawn with its lines on charts and legends, a method's or an IK
// solver's (each row names its own).
#pragma once

namespace springlab {

/// The shape drawn with a lane's lines on charts and legends (the app's draw/marks.hpp), so
/// that they are told apart by more than colour: filled, hollow, or strokes.
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

}  // namespace springlab
