// The inverse-kinematics kind (scene_kind.hpp): a scene with an "ik" part. Each lane is an IK
// solver working on its own copy of the chain, towards the target particle of the lane's
// simulation, a few iterations a frame; the joints are placed in the simulation's state for
// drawing. The target is the one particle that may be held.
#pragma once

#include <Eigen/Core>

#include "session/history.hpp"
#include "session/scene_kind.hpp"
#include "springlab/ik.hpp"
#include "springlab/text.hpp"

namespace springlab::app {

// An IK lane's part: its solver, its chain as the solver left it, its progress, and the series
// the kind samples (its chart's).
struct IkLane : LanePart {
  IkSolver solver = IkSolver::CCD;
  IkChain chain;
  IkStatus status;  // status.iterations: since the target last moved
  Eigen::Vector2d target = Eigen::Vector2d::Zero();
  Series error;  // the distance from the chain's end to the target (m), a frame, as History's t

  void clear_samples() override { error.clear(); }
};

// A lane's IK part (throws std::bad_cast for a lane of another kind).
const IkLane& ik_lane(const Lane& lane);

class IkKind final : public SceneKind {
 public:
  explicit IkKind(IkScene ik) : ik_(std::move(ik)), per_frame_(ik_.iterations_per_frame) {}

  std::string_view kind_name() const override { return "inverse-kinematics"; }
  int row_count() const override;
  LaneRow row(int k) const override;
  int row_of(const Lane& lane) const override;
  const char* row_noun() const override { return N_("solver"); }
  std::string choices() const override;
  int initial_row(const SimulationSettings&) const override {
    return static_cast<int>(ik_.solvers.front());
  }
  std::vector<int> compared_first() const override;

  void configure(SimulationSettings&, int) const override {}
  void start(Lane& lane, int row) const override;
  void switch_to(Lane& lane, int row) const override;
  void after_steps(Lane& lane, Steps steps) const override;
  void sample(Lane& lane, const Session& session) const override;

  int handle() const override { return ik_.target; }
  std::vector<GuideCircle> guides() const override;
  bool strained() const override { return false; }

  const IkScene& scene() const { return ik_; }
  // Solver iterations a frame (1 to 10000), set live.
  int iterations_per_frame() const { return per_frame_; }
  void set_iterations_per_frame(int iterations);

 private:
  void iterate(Lane& lane, int iterations) const;

  IkScene ik_;
  int per_frame_;
};

}  // namespace springlab::app
