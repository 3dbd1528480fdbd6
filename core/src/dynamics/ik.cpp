#include "springlab/ik.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "springlab/text.hpp"

namespace springlab {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;

// Below this length (relative to the chain's reach) a vector has no usable direction: the
// effector on a joint, the target on a joint, two FABRIK points on top of each other. A solver
// then leaves that joint as it is rather than turning it by atan2(0, 0).
constexpr double kNoDirection = 1e-12;

// (How each solver's lanes are shown, its colour and mark, is the app's: app/draw/row_styles.cpp.)
const IkSolverInfo kSolvers[] = {
    {IkSolver::CCD, "ccd", N_("Cyclic coord. descent")},
    {IkSolver::FABRIK, "fabrik", N_("FABRIK")},
    {IkSolver::DLS, "dls", N_("Damped least squares")},
};

Eigen::Vector2d direction(double phi) {
  return {std::cos(phi), std::sin(phi)};
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// x in [0, 2 pi).
double wrap_positive(double x) {
  return x - kTwoPi * std::floor(x / kTwoPi);
}

void check(const IkChain& chain, const IkSettings& settings) {
  if (!chain.limits.empty() && chain.limits.size() != chain.lengths.size())
    throw std::invalid_argument("IkChain: limits must be empty or one per link");
  if (settings.damping < 0.0 || !(settings.max_step > 0.0))
    throw std::invalid_argument("IkSettings: damping must be >= 0 and max_step > 0");
}

// Cyclic coordinate descent. Turning joint i moves only the joints beyond it, so p_i (from the
// positions at the start of the iteration) stays valid while the joints after it turn; only the
// effector needs following, by rotating it about p_i with each joint's applied turn.
void ccd(IkChain& chain, const Eigen::Vector2d& target) {
  const std::vector<Eigen::Vector2d> p = chain.positions();
  const double tiny = kNoDirection * chain.reach();
  Eigen::Vector2d end = p.back();
  for (int i = chain.size() - 1; i >= 0; --i) {
    const Eigen::Vector2d to_end = end - p[i], to_target = target - p[i];
    double& theta = chain.angles[i];
    const double before = theta;
    if (to_end.norm() > tiny && to_target.norm() > tiny)
      theta += std::atan2(cross(to_end, to_target), to_end.dot(to_target));
    theta = clamp_angle(theta, chain.limit(i));
    const double turn = theta - before;
    end = p[i] + Eigen::Vector2d(std::cos(turn) * to_end.x() - std::sin(turn) * to_end.y(),
                                 std::sin(turn) * to_end.x() + std::cos(turn) * to_end.y());
  }
}

// FABRIK on points, with each pass keeping link lengths and clamping relative angles as it goes:
// a link's direction is all a pass chooses, so each pass works in directions phi_i and places
// the points from them.
void fabrik(IkChain& chain, const Eigen::Vector2d& target) {
  const int n = chain.size();
  const double tiny = kNoDirection * chain.reach();
  std::vector<Eigen::Vector2d> p = chain.positions();
  std::vector<double> phi(n);  // link directions: the current pose, then the backward pass's
  for (int i = 0; i < n; ++i) phi[i] = (i ? phi[i - 1] : 0.0) + chain.angles[i];
  const auto heading = [tiny](const Eigen::Vector2d& d, double fallback) {
    return d.norm() > tiny ? std::atan2(d.y(), d.x()) : fallback;
  };

  // Forward pass: from the base, link i points from the new p_i at the old p_{i+1}; its angle
  // relative to the link before (to +x for link 0) is clamped to the joint's limits. This is
  // "points back to angles, clamp, angles back to points", done link by link so that a clamped
  // joint moves the points after it before they are aimed.
  const auto forward = [&](const auto& aim) {
    Eigen::Vector2d q = chain.base;
    double before = 0.0;  // direction of the previous link
    for (int i = 0; i < n; ++i) {
      const double theta = clamp_angle(heading(aim(i) - q, phi[i]) - before, chain.limit(i));
      chain.angles[i] = theta;
      before += theta;
      q += chain.lengths[i] * direction(before);
    }
  };

  if ((target - chain.base).norm() > chain.reach()) {
    // Out of reach (the paper's first test): every link in turn points at the target. Unlimited,
    // that is the straight chain along base -> target, the closest the effector can come. With
    // limits it is a pose as close as each joint allows in turn, not always the closest pose.
    forward([&](int) { return target; });
    return;
  }

  // Backward pass: the effector on the target, then each joint back along its link towards its
  // old position. The angle between link i and link i+1 is theta_{i+1}: clamping it here keeps
  // each joint but the base one (which the forward pass handles) within its limits.
  p[n] = target;
  for (int i = n - 1; i >= 0; --i) {
    double a = heading(p[i + 1] - p[i], phi[i]);
    if (i + 1 < n) a = phi[i + 1] - clamp_angle(phi[i + 1] - a, chain.limit(i + 1));
    phi[i] = a;
    p[i] = p[i + 1] - chain.lengths[i] * direction(a);
  }
  forward([&](int i) { return p[i + 1]; });
}

// Damped least squares (Wampler 1986; Buss 2004): minimises |J delta - e|^2 + lambda^2 |delta|^2,
// whose solution is delta = J^T (J J^T + lambda^2 I)^-1 e, a 2 x 2 solve whatever N is. Where
// J loses rank (a straight arm) the plain pseudo-inverse step grows without bound; lambda caps
// it at |e| / (2 lambda). lambda = 0 gives the pseudo-inverse method (see solve_symmetric).
//
// delta is a descent direction of |e|^2 (its gradient is -2 J^T e, and e^T J J^T A^-1 e >= 0),
// but the linearisation can overshoot: stretched towards an unreachable target, a bend of eps
// gives a step of about -eps L |e| / lambda^2, many times too far, and the chain would flap
// about the straight line for ever. So the step is halved until the error falls (at most
// kHalvings times; if it never does, the pose is a stationary point, or one the limits hold,
// and stays), which also makes the error shown iteration by iteration never grow.
constexpr int kHalvings = 40;

// A^+ e for the symmetric positive semi-definite 2 x 2 matrix A = J J^T + lambda^2 I, in closed
// form: A^-1 e = adj(A) e / det(A) when A is invertible (always, for lambda > 0: det >= lambda^4).
// With lambda = 0 and every joint on the line through the effector, J has rank 1 and A = t v v^T
// with t = trace(A) and |v| = 1, whose pseudo-inverse is A / t^2 (the minimum-norm step); with
// rank 0 (the effector on every joint) there is no step.
Eigen::Vector2d solve_symmetric(const Eigen::Matrix2d& A, const Eigen::Vector2d& e) {
  const double trace = A(0, 0) + A(1, 1);
  const double det = A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0);
  if (det > 1e-14 * trace * trace)
    return Eigen::Vector2d(A(1, 1) * e.x() - A(0, 1) * e.y(), A(0, 0) * e.y() - A(1, 0) * e.x()) /
           det;
  if (trace > 0.0) return A * e / (trace * trace);
  return Eigen::Vector2d::Zero();
}

// How much |e|^2 changes when the joints turn by `turn`: with d the effector's displacement,
// |e - d|^2 - |e|^2 = d . (d - 2 e). d is summed from each link's own turn,
//   dir(phi + a) - dir(phi) = 2 sin(a / 2) perp(dir(phi + a / 2)),
// rather than subtracted from a second forward kinematics: near a straight chain the error
// changes only at second order in the bend, and the difference of two distances would lose it
// in rounding once the bend is below about 1e-8, where this keeps it down to about 1e-15.
double squared_error_change(const IkChain& chain, const std::vector<double>& turn,
                            const Eigen::Vector2d& e) {
  Eigen::Vector2d d = Eigen::Vector2d::Zero();
  double phi = 0.0, dphi = 0.0;
  for (int i = 0; i < chain.size(); ++i) {
    phi += chain.angles[i] - turn[i];  // the direction before the step
    dphi += turn[i];
    const double mid = phi + 0.5 * dphi;
    d += chain.lengths[i] * 2.0 * std::sin(0.5 * dphi) *
         Eigen::Vector2d(-std::sin(mid), std::cos(mid));
  }
  return d.dot(d - 2.0 * e);
}

void dls(IkChain& chain, const Eigen::Vector2d& target, const IkSettings& settings) {
  const Eigen::Matrix2Xd J = ik_jacobian(chain);
  const Eigen::Vector2d e = target - chain.effector();
  const double lambda = settings.damping * chain.reach();
  const Eigen::Matrix2d A = J * J.transpose() + lambda * lambda * Eigen::Matrix2d::Identity();
  Eigen::VectorXd delta = J.transpose() * solve_symmetric(A, e);
  const double largest = delta.cwiseAbs().maxCoeff();
  if (largest > settings.max_step) delta *= settings.max_step / largest;

  const std::vector<double> start = chain.angles;
  std::vector<double> turn(start.size());
  for (int k = 0; k <= kHalvings; ++k, delta *= 0.5) {
    for (int i = 0; i < chain.size(); ++i) {
      chain.angles[i] = clamp_angle(start[i] + delta[i], chain.limit(i));
      turn[i] = wrap_angle(chain.angles[i] - start[i]);
    }
    if (squared_error_change(chain, turn, e) < 0.0) return;
  }
  for (int i = 0; i < chain.size(); ++i) chain.angles[i] = clamp_angle(start[i], chain.limit(i));
}

}  // namespace

std::span<const IkSolverInfo> ik_solvers() {
  return kSolvers;
}

const IkSolverInfo& ik_solver_info(IkSolver solver) {
  return kSolvers[static_cast<int>(solver)];
}

std::optional<IkSolver> find_ik_solver(std::string_view name) {
  for (const IkSolverInfo& s : kSolvers)
    if (name == s.name) return s.id;
  return std::nullopt;
}

std::string ik_solver_names() {
  std::string names;
  for (const IkSolverInfo& s : kSolvers) names += (names.empty() ? "" : ", ") + std::string(s.name);
  return names;
}

std::vector<Eigen::Vector2d> IkChain::positions() const {
  if (angles.size() != lengths.size())
    throw std::invalid_argument("IkChain: " + std::to_string(angles.size()) + " angles for " +
                                std::to_string(lengths.size()) + " links");
  std::vector<Eigen::Vector2d> p(lengths.size() + 1);
  p[0] = base;
  double phi = 0.0;
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    phi += angles[i];
    p[i + 1] = p[i] + lengths[i] * direction(phi);
  }
  return p;
}

Eigen::Vector2d IkChain::effector() const {
  return positions().back();
}

double IkChain::reach() const {
  double sum = 0.0;
  for (double l : lengths) sum += l;
  return sum;
}

double IkChain::inner_reach() const {
  const double longest = lengths.empty() ? 0.0 : *std::max_element(lengths.begin(), lengths.end());
  return std::max(0.0, 2.0 * longest - reach());
}

double wrap_angle(double a) {
  return std::remainder(a, kTwoPi);
}

double clamp_angle(double a, const std::optional<JointLimit>& limit) {
  a = wrap_angle(a);
  if (!limit || (a >= limit->min && a <= limit->max)) return a;
  // Outside the allowed arc: the nearer end of it, going round either way.
  const double past_max = wrap_positive(a - limit->max);
  const double short_of_min = wrap_positive(limit->min - a);
  return past_max <= short_of_min ? limit->max : limit->min;
}

Eigen::Matrix2Xd ik_jacobian(const IkChain& chain) {
  const std::vector<Eigen::Vector2d> p = chain.positions();
  Eigen::Matrix2Xd J(2, chain.size());
  for (int i = 0; i < chain.size(); ++i) {
    const Eigen::Vector2d r = p.back() - p[i];
    J.col(i) = Eigen::Vector2d(-r.y(), r.x());
  }
  return J;
}

IkStatus ik_status(const IkChain& chain, const Eigen::Vector2d& target,
                   const IkSettings& settings) {
  IkStatus status;
  status.error = (target - chain.effector()).norm();
  status.converged = status.error <= settings.tolerance;
  const double distance = (target - chain.base).norm();
  status.reachable = distance <= chain.reach() && distance >= chain.inner_reach();
  return status;
}

void ik_iterate(IkSolver solver, IkChain& chain, const Eigen::Vector2d& target,
                const IkSettings& settings) {
  check(chain, settings);
  if (chain.size() == 0) return;
  switch (solver) {
    case IkSolver::CCD:
      ccd(chain, target);
      break;
    case IkSolver::FABRIK:
      fabrik(chain, target);
      break;
    case IkSolver::DLS:
      dls(chain, target, settings);
      break;
  }
}

IkStatus ik_solve(IkSolver solver, IkChain& chain, const Eigen::Vector2d& target,
                  const IkSettings& settings) {
  IkStatus status = ik_status(chain, target, settings);
  int iterations = 0;
  bool stalled = false;
  while (!status.converged && !stalled && iterations < settings.max_iterations) {
    const std::vector<double> before = chain.angles;
    ik_iterate(solver, chain, target, settings);
    stalled = chain.angles == before;
    status = ik_status(chain, target, settings);
    status.iterations = ++iterations;
  }
  status.stalled = stalled && !status.converged;
  return status;
}

}  // namespace springlab
