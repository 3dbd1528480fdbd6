// Planar inverse kinematics: a chain of rigid links from a fixed base, whose end (the effector)
// must reach a target, and three solvers that each run one iteration at a time so that the app
// can animate them: cyclic coordinate descent (CCD), FABRIK, and damped least squares (DLS).
//
// The chain lies in the x-y plane. Its state is N relative joint angles theta_i (theta_0 from
// the +x axis, theta_i from link i-1), so forward kinematics is
//   phi_i = theta_0 + ... + theta_i,    p_0 = base,    p_{i+1} = p_i + L_i (cos phi_i, sin phi_i),
// and the effector is p_N. Every solver writes angles and positions are always derived from
// them, so the link lengths are exact by construction (FABRIK, which moves points, turns its
// points back into angles as it places them, clamped to the limits).
//
// Inverse kinematics is hard: there may be no solution (the target out of reach: every solver
// then stretches the chain straight towards it), or infinitely many (a 3-link arm can reach a
// point in a one-parameter family of poses; a 2-link arm, elbow up or elbow down). Which one a
// solver finds depends on the solver and on the pose it starts from.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace springlab {

enum class IkSolver { CCD, FABRIK, DLS };

struct IkSolverInfo {
  IkSolver id;
  const char* name;   // as typed in a scene or on the command line: "ccd", "fabrik", "dls"
  const char* label;  // as shown to people
};

std::span<const IkSolverInfo> ik_solvers();
const IkSolverInfo& ik_solver_info(IkSolver solver);
std::optional<IkSolver> find_ik_solver(std::string_view name);
// "ccd, fabrik, dls" for messages.
std::string ik_solver_names();

// The allowed range of one relative joint angle, in radians, min < max, within [-pi, pi].
struct JointLimit {
  double min, max;
};

struct IkChain {
  Eigen::Vector2d base = Eigen::Vector2d::Zero();
  std::vector<double> lengths;  // m, each > 0
  std::vector<double> angles;   // rad, relative; one per link
  // Empty (no joint limited) or one per link; nullopt = that joint unlimited.
  std::vector<std::optional<JointLimit>> limits;

  int size() const { return static_cast<int>(lengths.size()); }
  std::optional<JointLimit> limit(int i) const {
    return limits.empty() ? std::nullopt : limits[static_cast<std::size_t>(i)];
  }
  // The N + 1 joint positions, base first, effector last.
  std::vector<Eigen::Vector2d> positions() const;
  Eigen::Vector2d effector() const;
  double reach() const;  // L_0 + ... + L_{N-1}: the farthest the effector can be from the base
  // Without limits the effector can reach exactly the annulus inner_reach() <= |p - base| <=
  // reach(), with inner_reach() = max(0, 2 L_max - reach()): the longest link folded back by
  // all the others.
  double inner_reach() const;
};

struct IkSettings {
  // ik_solve's cap. Generous because CCD is slow near the edge of reach: a 20-link chain can
  // need over a thousand iterations for a target at 95% of its reach (each costs O(N)).
  int max_iterations = 1000;
  double tolerance = 1e-4;  // m: converged when |effector - target| <= tolerance
  // DLS: the damping lambda as a fraction of the chain's reach (lambda is a length, since J J^T
  // is in m^2), so one setting suits a 1 m arm and a 20 m tentacle alike. Larger is steadier
  // near singular poses (a straight arm) and slower everywhere.
  double damping = 0.1;
  // DLS: the largest change of any joint angle in one iteration (rad); a larger step is scaled
  // down as a whole, keeping its direction. The linearisation behind the step is only good for
  // small rotations.
  double max_step = 0.5;
};

struct IkStatus {
  int iterations = 0;
  double error = 0.0;      // m: |effector - target|
  bool converged = false;  // error <= tolerance
  // inner_reach() <= |target - base| <= reach(). Joint limits are not considered: a limited
  // chain may fail to reach a "reachable" target and then simply does not converge.
  bool reachable = true;
  // ik_solve stopped early, off the target, because an iteration left every angle exactly as
  // it was: an iteration depends only on the angles, so every further one would too. A fixed
  // point of the solver: stretched towards an unreachable target, held by a limit, or a singular
  // pose where the DLS step is zero.
  bool stalled = false;
};

// An angle wrapped to [-pi, pi] (the same direction).
double wrap_angle(double a);
// The angle a (any value) as the nearest allowed angle: wrapped to [-pi, pi], then, if outside
// [min, max], whichever limit is angularly closer to it (going round either way). For a CCD
// joint that is the best allowed angle: the effector's distance to the target grows with the
// angle between the direction the joint would take and the one it does take.
double clamp_angle(double a, const std::optional<JointLimit>& limit);

// J = d effector / d theta, 2 x N: moving theta_i turns everything beyond joint i about p_i, so
// column i is perp(effector - p_i), perp(x, y) = (-y, x).
Eigen::Matrix2Xd ik_jacobian(const IkChain& chain);

// The current error and flags of `chain` for `target` (iterations left at 0).
IkStatus ik_status(const IkChain& chain, const Eigen::Vector2d& target, const IkSettings& settings);

// One iteration of `solver`, in place; afterwards every angle lies within its limits (and in
// [-pi, pi]). Throws std::invalid_argument when the chain's vectors do not match in size.
//   CCD: for joints N-1 down to 0, turn joint i so that the ray p_i -> effector points at the
//        target, clamped to the joint's limits.
//   FABRIK (Aristidou and Lasenby 2011): a backward pass placing the effector on the target and
//        each joint back towards the base, then a forward pass from the base; limits clamp each
//        relative angle during both passes. A target out of reach (|target - base| > reach) is
//        handled as in the paper: each link in turn points at the target, which is the straight
//        chain when unlimited.
//   DLS: delta = J^T (J J^T + lambda^2 I)^-1 e with e = target - effector, scaled down to
//        max_step, clamped to the limits, and halved until the error falls (so it never grows;
//        a pose where no halving helps is left as it is).
// With limits, CCD and FABRIK may stop at a pose short of a target that the limits allow
// (each joint does its best in turn and a joint pinned at its limit can block the rest); the
// best pose they find is then what they report, unconverged.
void ik_iterate(IkSolver solver, IkChain& chain, const Eigen::Vector2d& target,
                const IkSettings& settings);

// Iterates until converged, stalled or max_iterations; returns the final status. A chain
// already on the target is left as it is, after 0 iterations.
IkStatus ik_solve(IkSolver solver, IkChain& chain, const Eigen::Vector2d& target,
                  const IkSettings& settings);

}  // namespace springlab
