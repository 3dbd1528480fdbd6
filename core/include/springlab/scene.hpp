// Scenes: JSON files that declare only what they need (assets/scenes/README.md documents the
// format). Loading one checks every field and builds the Model and initial State, plus what the
// app and the renderer need: the methods to show, the default step, the camera, the surfaces.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "springlab/cells.hpp"
#include "springlab/ik.hpp"
#include "springlab/methods.hpp"
#include "springlab/model.hpp"
#include "springlab/state.hpp"

namespace springlab {

/// Most particles and springs a scene may have: checked before anything is allocated.
inline constexpr long kMaxParticles = 4'194'304;  ///< 2048 x 2048
inline constexpr long kMaxSprings = 33'554'432;

enum class View {
  Planar,  ///< 2D: orthographic, looking down -z at the x-y plane
  Orbit,   ///< 3D: perspective, orbiting a target
};

struct Camera {
  View view = View::Orbit;
  Vec3 target = Vec3::Zero();
  double distance = 5.0;  ///< m, orbit
  double yaw = 30.0;      ///< degrees about +y, orbit
  double pitch = 20.0;    ///< degrees above the horizon, orbit
  double fov = 45.0;      ///< degrees, vertical, orbit
  double height = 4.0;    ///< m of the x-y plane shown vertically, planar
};

/// A triangulated surface over particles (a cloth, the faces of a box), for drawing.
struct Surface {
  std::string name;
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise seen from outside
};

/// An inverse-kinematics scene: a planar chain whose end must reach a target (ik.hpp). Its model
/// holds the joints (pinned particles, base first) and the target (a pinned particle the user
/// drags), with the links drawn as springs of no stiffness: the physics leaves them still, and
/// the solvers place the joints.
struct IkScene {
  IkChain chain;                  ///< as it starts
  int first_joint = 0;            ///< particle of the base; the other joints follow it
  int target = 0;                 ///< particle
  std::vector<IkSolver> solvers;  ///< to show side by side; the first is the default
  IkSettings settings;
  int iterations_per_frame = 1;  ///< shown one at a time, so that convergence can be watched
};

/// A loaded scene: its Model and initial State, and what the app and the renderer need (the
/// methods to show, the step, the camera, the surfaces).
struct Scene {
  std::string name;  ///< "rope" for assets/scenes/rope.json
  std::string file;  ///< as given
  std::string description;
  Model model;
  State state;
  std::vector<Method> methods;  ///< to show side by side; the first is the default
  double dt = 0.01;
  int substeps = 0;     ///< 0: automatic (stability.hpp, choose_substeps)
  double safety = 0.5;  ///< the fraction of the limit automatic sub-steps keep h within
  double duration = 10.0;
  double tolerance = 1e-4;
  Camera camera;
  std::vector<Surface> surfaces;
  std::vector<Cell> cells;  ///< a box's lattice cells, whose inversion is counted (cells.hpp)
  std::vector<int> trails;  ///< particles whose paths are drawn
  /// Each generator's particles by name: first index and count ("rope:-1" in scripts).
  std::vector<std::pair<std::string, std::pair<int, int>>> named;
  std::optional<IkScene> ik;
};

/// Loads a scene file. `overrides` are "KEY=VALUE" strings (the --set option): KEY is a dotted
/// path into the document ("cloth.width", "gravity", "colliders.0.friction"), where a first
/// segment that is not a top-level field names a generator; VALUE is JSON ("64", "[0,-9.81,0]",
/// "true") or a comma-separated list of numbers ("0,-9.81,0"). Throws InputError.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

/// The same from text already read; `file` names it in messages.
Scene parse_scene(const std::string& text, const std::string& file,
                  const std::vector<std::string>& overrides = {});

}  // namespace springlab
