// A soft body's cells, and which are inverted. A box's lattice (generators: "box") is made of
// hexahedral cells; springs alone cannot tell a cell turned inside out from a sound one (a spring
// pulls to its rest length whichever way it points), so a method that lets one through (a large
// step, an unfinished iteration) leaves it inverted for good. A cell is inverted where any corner's
// Jacobian, the three edges from that corner along the lattice's axes
//   J_c = [s_x (x_(c^1) - x_c), s_y (x_(c^2) - x_c), s_z (x_(c^4) - x_c)],  s = -1 where c's bit is
//   set,
// has det J_c <= 0 (the standard validity test of a trilinear hexahedron at its corners).
#pragma once

#include <array>
#include <vector>

#include "springlab/state.hpp"

namespace springlab {

/// A hexahedron's particles, corner c = i + 2 j + 4 k at lattice offset (i, j, k), right-handed.
using Cell = std::array<int, 8>;

/// How many of the cells are inverted in positions x.
int inverted_cells(const std::vector<Cell>& cells, const Points& x);

}  // namespace springlab
