// The mass-spring kind (scene_kind.hpp): a lane is a method's row. What only its lanes keep
// besides their simulation, sampled by the kind each frame (mass_spring_kind.cpp): the scene's
// trails, a free body's momentum and its change, the inverted cells.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "session/history.hpp"
#include "session/scene_kind.hpp"
#include "springlab/momentum.hpp"

namespace springlab::app {

// A mass-spring lane's part.
struct MassSpringLane : LanePart {
  static constexpr std::size_t kTrailLength = 240;  // frames

  std::vector<std::vector<Vec3>> trails;  // one per scene.trails particle, oldest first
  // A free body's momentum (momentum.hpp) since it last became free (a drag pins what it holds)
  // and moving, against which the gauge and the momentum chart measure what the method changes
  // of it; empty while not free, or at rest.
  std::optional<Momentum> free_since;
  // |P - P0| and |L - L0| against their scales since it became free (NaN while it is not): the
  // momentum chart's series, beside the lane's History.
  Series linear_change, angular_change;
  // How many of the scene's cells are inverted now (cells.hpp), counted as the lane is sampled.
  int inverted_cells = 0;

  void clear_samples() override {
    linear_change.clear();
    angular_change.clear();
  }
};

// A lane's mass-spring part, or none (a lane of another kind).
const MassSpringLane* mass_spring_lane(const Lane& lane);

// The mass-spring kind with these methods' rows first (the scene's own list to compare).
std::unique_ptr<SceneKind> make_mass_spring_kind(const std::vector<Method>& methods);

}  // namespace springlab::app
