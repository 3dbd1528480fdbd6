// What kind of scene a session shows, as a type: whatever the session, the drawing and the panels
// do differently for one kind of scene is asked of its kind, so that nothing else asks which kind
// a scene is (as polyscope's structures each draw and build their own UI).
//
//   mass-spring          a Model stepped by a method; particles, springs, cells, emitters,
//                        colliders and attractors are its data, not kinds of their own. A lane is
//                        a row of the method table (methods.hpp), with its trails and momentum
//                        (MassSpringLane). mass_spring_kind.hpp.
//   inverse kinematics   a scene with an "ik" part: solvers placing a chain's joints, a few
//                        iterations a frame, towards a target particle that the model moves. A lane
//                        is a row of the IK solvers' table (ik.hpp), with its own chain (IkLane).
//                        ik_kind.hpp.
//
// A session makes its kind once, from its scene (make_scene_kind), and asks it to make, follow,
// sample and reset its lanes, which particles may be held, what compare sets side by side and
// what the number keys choose. The kind's UI half (its controls, chart, words) is
// the panels registered under its kind_name() (ui/kind_panels.hpp). docs/architecture.md, "A scene
// kind", says how to add one.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "springlab/scene.hpp"
#include "springlab/simulation.hpp"

namespace springlab::app {

struct Lane;
class Session;

// A row a lane may be: a method's or an IK solver's. How it is shown (its colour and mark) is
// draw's, looked up by its table and its place there (draw/row_styles.hpp).
struct LaneRow {
  enum class Table { Method, IkSolver, Own };  // Own: a kind of one's own's rows
  std::string_view name;                       // as typed: "rk4", "fabrik"
  const char* label;                           // as shown to people (untranslated)
  Table table;
  int id;  // its Method or IkSolver, or its place among its kind's rows (Own)
};

// What a lane of a kind keeps besides its simulation (an IK lane: its solver, chain and progress;
// a mass-spring lane: its trails and momentum), and the series the kind samples into it beside
// the lane's History (an IK lane's distance to the target).
struct LanePart {
  virtual ~LanePart() = default;
  // Its series cleared, as the lane's History is (Session::watch); a reset makes a new part.
  virtual void clear_samples() {}
};

// A circle the scene view draws as a guide (an IK chain: the circles its end can reach).
struct GuideCircle {
  Vec3 centre;
  double radius;
};

class SceneKind {
 public:
  // What a lane has just done: a frame's steps (or none, paused), or one step (single-stepping).
  enum class Steps { Paused, Frame, One };

  virtual ~SceneKind() = default;
  // The kind's name ("mass-spring", "inverse-kinematics"): its UI half is the panels registered
  // under it (ui/kind_panels.hpp, add_kind_panels).
  virtual std::string_view kind_name() const = 0;

  // Rows: what a lane may be, in the order the number keys choose them (1, 2, ...).
  virtual int row_count() const = 0;
  virtual LaneRow row(int k) const = 0;
  virtual int row_of(const Lane& lane) const = 0;
  // The row named `name` ("rk4", "ccd"), or none. A mass-spring scene also takes a tableau's
  // name or file (`--method`'s), made a row as it is named.
  virtual std::optional<int> find(const std::string& name) const;
  // What a row is called, and what a message offers: "method", "methods: euler, ...; tableaux:
  // ..."; "solver", "solvers: ccd, fabrik, dls".
  virtual const char* row_noun() const = 0;
  virtual std::string choices() const = 0;
  // The lanes a list such as "euler,verlet" names, 2 to Session::kMaxLanes of them; throws
  // InputError naming `option` and what this kind's rows are.
  std::vector<int> lanes_named(const std::string& list, const char* option) const;
  // The row a session makes a lane of when none is asked for (its first lane; set_own_lanes given
  // none): the one `settings` were configured with (configure: a mass-spring scene's method, from
  // its options or the last chosen), or the kind's own first (an IK scene's first solver).
  virtual int initial_row(const SimulationSettings& settings) const = 0;
  // What compare sets side by side when nothing else is chosen: the scene's own list, else the
  // rows marked to be compared first.
  virtual std::vector<int> compared_first() const = 0;

  // Lanes.
  // The settings a lane of row k is made with (mass-spring: its method), and those the session
  // keeps for its next lanes when row k is chosen.
  virtual void configure(SimulationSettings& settings, int row) const = 0;
  // A new lane's part, as row k, from the scene's start (again on a reset).
  virtual void start(Lane& lane, int row) const = 0;
  // The single lane becomes row k from where it is: a method mid-motion, a solver from the pose
  // it has reached.
  virtual void switch_to(Lane& lane, int row) const = 0;
  // After a lane's steps: the kind's own work (an IK solver's iterations).
  virtual void after_steps(Lane& lane, Steps steps) const = 0;
  // Samples what only this kind has, into the lane's part (its series, its trails, ...), once a
  // frame after the session has sampled what every kind has into the lane's History (the scene
  // and the frame number are the session's).
  virtual void sample(Lane& lane, const Session& session) const = 0;

  // The scene.
  // A particle by which the user moves the scene (an IK target), drawn large and the only one
  // that may be held; -1: none, every particle may be held.
  virtual int handle() const { return -1; }
  bool holdable(int particle) const { return handle() < 0 || particle == handle(); }
  // Circles the view draws as guides.
  virtual std::vector<GuideCircle> guides() const { return {}; }
  // Whether springs are coloured by their strain (an IK chain's links are rigid: no strain).
  virtual bool strained() const { return true; }
};

// The kind of `scene`: the one place that asks (an "ik" part makes it inverse kinematics;
// scene_kind.cpp).
std::unique_ptr<SceneKind> make_scene_kind(const Scene& scene);

}  // namespace springlab::app
