// A Session: one scene being shown, in the window or headless. It owns the simulations (one, or
// two to four side by side in compare mode, each a "lane" with its own method), the frame clock,
// what the user holds with the mouse, the script being played and the charts' history. The UI
// and the headless renderer change it only through these functions, which the tests call too.
//
// Frames: frame k is shown at presentation time k / fps. Unless paused, a frame advances the
// simulated time by speed / fps, in whole steps of dt, so frame k shows the state after
// floor(simulated time / dt) steps: exactly k / fps at speed 1 whenever dt divides 1 / fps (the
// shipped scenes' steps do), and never more than one step short otherwise. Nothing depends on
// the wall clock, so the same inputs give the same frames.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "session/history.hpp"
#include "session/scene_kind.hpp"
#include "session/stability_job.hpp"
#include "springlab/exact.hpp"
#include "springlab/scene.hpp"
#include "springlab/script.hpp"
#include "springlab/simulation.hpp"

namespace springlab::app {

struct Lane {
  explicit Lane(Simulation simulation) : sim(std::move(simulation)) {}

  Simulation sim;
  History history;
  std::optional<ExactOscillator> exact;  // from the last change of the model
  // Its scene's kind (the session's: scene_kind.hpp), and what the kind keeps of it besides its
  // simulation and samples into it (an IK lane's chain: ik_kind.hpp; a mass-spring lane's trails,
  // momentum and inverted cells: mass_spring_kind.hpp), made by the kind's start().
  const SceneKind* kind = nullptr;
  std::unique_ptr<LanePart> part;
  // The stability analysis shown (the latest made, which may be of the scene as it was a moment
  // ago while a new one is made), and the job making the next, in the app's background mode.
  std::shared_ptr<const StabilityAnalysis> analysis;
  StabilityJob job;
  // The last state that looked sane (every particle within the scene's reach, scene_reach(), and
  // no spring stretched past twice its rest or starting length): what a diverged lane is drawn
  // as, never its blown-up geometry.
  State sane;
  // Blowing up before the divergence test says so (its energy not yet 1e6 times the scene's): a
  // spring past ten times its longest sane length on a step past the method's stability limit, no
  // particle held (Session::keep_if_sane). Drawn, as a diverged lane is, as its last sane state.
  bool blowing_up = false;
  // Whether it is drawn as its last sane state, and the state it is drawn as.
  bool wild() const { return blowing_up || sim.diverged(); }
  const State& shown() const { return wild() ? sane : sim.state(); }
  // A lane of one's own (a student's step: homework, app/homework/): its label, in place of its
  // row's ("Your simulateEuler"), and whether the homework checker found the row it is (the row
  // its simulation names, whose theory the gauge then reads) or none. Empty for a row's lane.
  std::string own;
  bool own_known = true;
  int own_index = 0;  // 0, 1, ...: its colour among the lanes of one's own
  // Whether the lane waits for its first analysis before it steps (automatic sub-steps, in the
  // session's background mode; otherwise the simulation makes it when it first steps).
  bool waiting() const { return !sim.ready(); }
};

// How far from its camera's target a scene's particles may be while it is sane: the
// half-diagonal of a 16:9 frame of its camera, or its farthest particle at the start if farther.
double scene_reach(const Scene& scene);

// A lane's row (a method's or an IK solver's: its kind's).
LaneRow lane_row(const Lane& lane);
// A lane's label as shown (translated): its row's, or its own.
std::string lane_label(const Lane& lane);
// Its short name (charts' series): its row's name ("verlet", "fabrik") or its own label.
std::string lane_name(const Lane& lane);

// A step of one's own as a lane (Session::set_own_lanes): the step, its label, the row it was found
// to be (`like`), or none (`known` false: the row is only a stand-in, named nowhere).
struct OwnLane {
  std::function<void(const Model&, const State&, State&, double, Workspace&)> step;
  std::string label;
  Method like = Method::SymplecticEuler;
  bool known = true;
};

// A row beside lanes of one's own, run with what the homework checker fitted to the student's
// step: where given, the lane's model takes the drag, the springs' damping and Verlet's factor.
struct BesideRow {
  Method method = Method::SymplecticEuler;
  std::optional<double> drag, kd, verlet_damping;
};

class Session {
 public:
  static constexpr std::size_t kMaxLanes = 4;

  Session(Scene scene, SimulationSettings settings, double fps = 60.0);
  // With a kind given (a test's own; none: the scene's, make_scene_kind).
  Session(Scene scene, SimulationSettings settings, double fps, std::unique_ptr<SceneKind> kind);

  // Background mode (the interactive window): each lane's stability analysis is made on a worker
  // thread when the scene changes, the lane stepping on with the sub-steps it had meanwhile (a
  // lane with automatic sub-steps starts at once with those of a quick bound, quick_limit(), and
  // waits only where that cannot tell). Off (render, the tests, `view --frames`),
  // an analysis is made where it is needed, and the same inputs give the same frames.
  void set_background_analysis(bool on);
  bool background_analysis() const { return background_; }
  // Collects finished analyses and starts the ones needed (done by advance_frame too).
  void update_analyses();
  // Whether any lane's analysis is being made.
  bool analysing() const;

  const Scene& scene() const { return scene_; }
  // Its kind (scene_kind.hpp): what its lanes are and do. Not const: a kind may have settings of
  // its own (IK's iterations a frame).
  const SceneKind& kind() const { return *kind_; }
  SceneKind& kind() { return *kind_; }
  std::span<Lane> lanes() { return lanes_; }
  std::span<const Lane> lanes() const { return lanes_; }
  const Lane& primary() const { return lanes_.front(); }

  // One frame: plays the script events due, moves what is held, steps every lane that has not
  // diverged, samples the history (what every kind has, then the kind's own: SceneKind::sample).
  void advance_frame();
  std::int64_t frame() const { return frame_; }
  double fps() const { return fps_; }
  double presentation_time() const { return static_cast<double>(frame_) / fps_; }
  double simulated_target() const { return target_; }

  // Compare mode: the same scene in 2 to 4 lanes at once (set_compare_rows, below).
  bool comparing() const { return lanes_.size() > 1; }
  // Lanes of one's own (homework) first, then the rows `beside` (4 lanes at most), each with its
  // own parameters. Every lane restarts from the initial state.
  void set_own_lanes(const std::vector<OwnLane>& own, const std::vector<BesideRow>& beside);

  // Rows, whatever the kind (a method's, an IK solver's: kind().row(k); a mass-spring scene's row
  // k is Method k). choose(): the single lane becomes row k from where it is (a method switched
  // mid-motion, a solver from the pose reached), and the session's next lanes are made as row k
  // (kind().configure); in compare mode the lanes keep theirs. chosen(): the first lane's row.
  // set_compare_rows(): the rows side by side (empty: back to one lane, of the first lane's row);
  // every lane restarts from the initial state.
  void choose(int row);
  int chosen() const { return kind_->row_of(lanes_.front()); }
  void set_compare_rows(const std::vector<int>& rows);

  // Parameters, for every lane.
  Method method() const { return lanes_.front().sim.settings().method; }
  void set_dt(double dt);
  void set_substeps(int substeps);  // fixes them
  void set_auto_substeps();         // chosen again from each lane's limit
  bool auto_substeps() const { return settings_.auto_substeps; }
  void set_tolerance(double tolerance);
  void set_iterations(int iterations);  // xpbd, local-global, vbd
  void set_stiffness(double ks);
  void set_damping(double kd);
  void set_gravity(const Vec3& g);
  void set_drag(double drag);
  void set_friction(double mu);
  void set_mass(double mass);
  void set_speed(double speed);  // 1/16 to 4
  double speed() const { return speed_; }
  void set_paused(bool paused) { paused_ = paused; }
  bool paused() const { return paused_; }
  void step_once();  // one step of dt in every lane, for single-stepping while paused
  void reset();      // every lane back to the initial state; the script's clock goes on

  // What the sliders show: the scene's first material, mass and collider, as now set.
  double stiffness() const;
  double damping() const;
  double mass() const;
  double friction() const;

  // Dragging. pick() returns the particle nearest a ray within `radius` (m), or -1.
  int pick(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double radius) const;
  int nearest(const Vec3& point) const;
  void grab(int particle);
  void drag_to(const Vec3& target);
  void release();
  int grabbed() const { return grabbed_; }
  std::optional<Vec3> drag_target() const { return drag_target_; }

  // Every drag: which particle, where it was grabbed and where it was let go (or is now, while
  // still held).
  struct DragRecord {
    int particle;
    Vec3 from, to;
  };
  const std::vector<DragRecord>& drags() const { return drags_; }

  // The particle whose position and phase the charts show.
  int watched() const { return watched_; }
  int watched_axis() const { return watched_axis_; }
  void watch(int particle);

  // Changes made through the functions above (parameters, methods, lanes, grabs; not pausing,
  // stepping or resetting): a lesson compares it around the user's input to see that the class
  // took over.
  std::uint64_t edits() const { return edits_; }
  // A number no other session of this process has had (a new scene, a lesson's step): what
  // watches a session, as the homework's lanes do, tells a new one by it, not by its address.
  std::uint64_t serial() const { return serial_; }

  // Scripts.
  void play(Script script);
  void stop_script();  // the script's remaining events are dropped; what is held stays held
  const std::optional<Script>& script() const { return script_; }

 private:
  void apply(const ScriptEvent& event);
  void model_changed(Lane& lane);
  void sample(Lane& lane);
  void keep_if_sane(Lane& lane);
  Lane make_lane(int row) const;
  void restart_lanes(const std::vector<int>& rows);

  std::uint64_t serial_;
  Scene scene_;
  std::unique_ptr<SceneKind> kind_;  // made once from scene_
  SimulationSettings settings_;
  std::vector<Lane> lanes_;
  double fps_;
  std::int64_t frame_ = 0;
  double target_ = 0.0;  // simulated time the lanes are to reach
  double speed_ = 1.0;
  bool paused_ = false;
  int grabbed_ = -1;
  std::optional<Vec3> drag_target_;
  std::vector<DragRecord> drags_;
  int watched_ = 0, watched_axis_ = 0;
  std::optional<Script> script_;
  std::size_t next_event_ = 0;
  std::optional<std::pair<double, std::vector<std::pair<double, Vec3>>>> path_;  // start, waypoints
  bool background_ = false;
  std::uint64_t edits_ = 0;
  double sane_reach_ = 0.0;  // scene_reach(scene_)
};

}  // namespace springlab::app
