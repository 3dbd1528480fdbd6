#include "springlab/cells.hpp"

#include <Eigen/Dense>

namespace springlab {

int inverted_cells(const std::vector<Cell>& cells, const Points& x) {
  int inverted = 0;
  for (const Cell& cell : cells) {
    for (int c = 0; c < 8; ++c) {
      const Eigen::Vector3d p = x.row(cell[c]).transpose();
      Eigen::Matrix3d J;
      for (int axis = 0; axis < 3; ++axis) {
        const int bit = 1 << axis;
        J.col(axis) = (c & bit ? -1.0 : 1.0) * (x.row(cell[c ^ bit]).transpose() - p);
      }
      if (!(J.determinant() > 0.0)) {
        ++inverted;
        break;
      }
    }
  }
  return inverted;
}

}  // namespace springlab
