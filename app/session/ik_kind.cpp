#include "session/ik_kind.hpp"

#include <algorithm>

#include "session/session.hpp"

namespace springlab::app {

namespace {
IkLane& part(Lane& lane) {
  return dynamic_cast<IkLane&>(*lane.part);
}
}  // namespace

const IkLane& ik_lane(const Lane& lane) {
  if (!lane.part) throw std::bad_cast();
  return dynamic_cast<const IkLane&>(*lane.part);
}

int IkKind::row_count() const {
  return static_cast<int>(ik_solvers().size());
}

LaneRow IkKind::row(int k) const {
  const IkSolverInfo& s = ik_solvers()[static_cast<std::size_t>(k)];
  return {s.name, s.label, LaneRow::Table::IkSolver, static_cast<int>(s.id)};
}

std::string IkKind::choices() const {
  return "this is an inverse-kinematics scene; solvers: " + ik_solver_names();
}

int IkKind::row_of(const Lane& lane) const {
  return static_cast<int>(ik_lane(lane).solver);
}

std::vector<int> IkKind::compared_first() const {
  std::vector<int> rows;
  for (IkSolver s : ik_.solvers) rows.push_back(static_cast<int>(s));
  return rows;
}

void IkKind::start(Lane& lane, int row) const {
  auto ik = std::make_unique<IkLane>();
  ik->solver = static_cast<IkSolver>(row);
  ik->chain = ik_.chain;
  ik->target = lane.sim.state().x.row(ik_.target).head<2>().transpose();
  ik->status = ik_status(ik->chain, ik->target, ik_.settings);
  lane.part = std::move(ik);
}

void IkKind::switch_to(Lane& lane, int row) const {
  IkLane& ik = part(lane);
  ik.solver = static_cast<IkSolver>(
      row);  // from the pose it has reached: a new solver takes over from there
  ik.status = ik_status(ik.chain, ik.target, ik_.settings);
}

void IkKind::after_steps(Lane& lane, Steps steps) const {
  iterate(lane, steps == Steps::Paused ? 0 : steps == Steps::One ? 1 : per_frame_);
}

void IkKind::iterate(Lane& lane, int iterations) const {
  IkLane& ik = part(lane);
  const IkSettings& settings = ik_.settings;
  const Eigen::Vector2d target = lane.sim.state().x.row(ik_.target).head<2>().transpose();
  // Moved (by more than rounding: a held target creeps by ulps): the count starts again.
  if ((target - ik.target).norm() > 1e-9 * ik.chain.reach()) {
    ik.target = target;
    ik.status = ik_status(ik.chain, target, settings);
  }
  for (int k = 0; k < iterations && !ik.status.converged && !ik.status.stalled; ++k) {
    const std::vector<double> before = ik.chain.angles;
    ik_iterate(ik.solver, ik.chain, target, settings);
    const int done = ik.status.iterations + 1;
    ik.status = ik_status(ik.chain, target, settings);
    ik.status.iterations = done;
    ik.status.stalled = !ik.status.converged && ik.chain.angles == before;
  }
  const std::vector<Eigen::Vector2d> joints = ik.chain.positions();
  for (std::size_t j = 0; j < joints.size(); ++j)
    lane.sim.place(ik_.first_joint + static_cast<int>(j), Vec3(joints[j].x(), joints[j].y(), 0.0));
}

void IkKind::sample(Lane& lane, const Session&) const {
  part(lane).error.push(part(lane).status.error);
}

std::vector<GuideCircle> IkKind::guides() const {
  // The circles bounding what its end can reach: its reach, and the inner one, if any.
  std::vector<GuideCircle> circles;
  const Vec3 base(ik_.chain.base.x(), ik_.chain.base.y(), 0.0);
  for (double r : {ik_.chain.reach(), ik_.chain.inner_reach()})
    if (r > 0.0) circles.push_back({base, r});
  return circles;
}

void IkKind::set_iterations_per_frame(int iterations) {
  per_frame_ = std::clamp(iterations, 1, 10000);
}

}  // namespace springlab::app
