// Planar inverse kinematics: forward kinematics and the Jacobian against independent
// computations (complex numbers, central differences); every solver reaches reachable targets,
// keeps link lengths exact, stretches straight towards unreachable targets and respects joint
// limits after every iteration; the 2-link arm's two analytic solutions (elbow up, elbow down)
// are both found; and bad chains in a scene fail with the JSON path named.
#include "springlab/ik.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <numbers>

#include "loading/ik_scene.hpp"
#include "springlab/error.hpp"

namespace springlab {
namespace {

using Eigen::Vector2d;
constexpr double kDeg = std::numbers::pi / 180.0;

// Forward kinematics as a product of unit complex numbers, independent of the library's
// summed angles: p_{i+1} = p_i + L_i e^{i (theta_0 + ... + theta_i)}.
std::vector<Vector2d> complex_positions(const IkChain& chain) {
  std::complex<double> p(chain.base.x(), chain.base.y()), turn(1.0, 0.0);
  std::vector<Vector2d> out{chain.base};
  for (int i = 0; i < chain.size(); ++i) {
    turn *= std::polar(1.0, chain.angles[i]);
    p += chain.lengths[i] * turn;
    out.emplace_back(p.real(), p.imag());
  }
  return out;
}

Vector2d complex_effector(const IkChain& chain) {
  return complex_positions(chain).back();
}

// A 3-link arm off the origin, bent as in a scene: links 1, 0.8, 0.6; angles 20, 10, -5 degrees.
IkChain arm() {
  IkChain c;
  c.base = Vector2d(0.3, -0.2);
  c.lengths = {1.0, 0.8, 0.6};
  c.angles = {20 * kDeg, 10 * kDeg, -5 * kDeg};
  return c;
}

// A 20-link tentacle of unequal links (reach 5.25), curled.
IkChain tentacle() {
  IkChain c;
  for (int i = 0; i < 20; ++i) {
    c.lengths.push_back(0.2 + 0.005 * i);
    c.angles.push_back(0.15);
  }
  return c;
}

Vector2d polar(const Vector2d& from, double r, double angle) {
  return from + r * Vector2d(std::cos(angle), std::sin(angle));
}

// |p_{i+1} - p_i| - L_i, the largest over the links, on the positions the app draws.
double worst_length_error(const IkChain& chain) {
  const auto p = chain.positions();
  double worst = 0.0;
  for (int i = 0; i < chain.size(); ++i)
    worst = std::max(worst, std::abs((p[i + 1] - p[i]).norm() - chain.lengths[i]));
  return worst;
}

std::string solver_name(IkSolver s) {
  return ik_solver_info(s).name;
}

TEST(IkChain, ForwardKinematicsByHand) {
  IkChain c;
  c.base = Vector2d(0.5, 0.5);
  c.lengths = {1.0, 2.0};
  c.angles = {90 * kDeg, -90 * kDeg};  // up 1, then right 2
  const auto p = c.positions();
  ASSERT_EQ(p.size(), 3u);
  EXPECT_NEAR((p[0] - Vector2d(0.5, 0.5)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((p[1] - Vector2d(0.5, 1.5)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((p[2] - Vector2d(2.5, 1.5)).norm(), 0.0, 1e-15);
  EXPECT_EQ(c.reach(), 3.0);
  EXPECT_EQ(c.inner_reach(), 1.0);  // the 2 m link folded back over the 1 m one

  // Relative angles add up: 30, 60, 90 degrees point the links at 30, 90 and 180 degrees.
  c.base = Vector2d::Zero();
  c.lengths = {1.0, 1.0, 1.0};
  c.angles = {30 * kDeg, 60 * kDeg, 90 * kDeg};
  const Vector2d expected(std::sqrt(3.0) / 2 - 1.0, 0.5 + 1.0);
  EXPECT_NEAR((c.effector() - expected).norm(), 0.0, 1e-15);
  EXPECT_EQ(c.inner_reach(), 0.0);

  // And any pose agrees with the complex product.
  for (const IkChain& chain : {arm(), tentacle()}) {
    const auto a = chain.positions(), b = complex_positions(chain);
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR((a[i] - b[i]).norm(), 0.0, 1e-13);
  }
}

TEST(IkChain, AnglesOutOfStepWithLinksAreRefused) {
  IkChain c = arm();
  c.angles.pop_back();
  EXPECT_THROW(c.positions(), std::invalid_argument);
  c = arm();
  c.limits.resize(2);
  EXPECT_THROW(ik_iterate(IkSolver::CCD, c, Vector2d(1, 1), {}), std::invalid_argument);
}

TEST(IkSolvers, TableAndNames) {
  ASSERT_EQ(ik_solvers().size(), 3u);
  for (const IkSolverInfo& s : ik_solvers()) {
    EXPECT_EQ(find_ik_solver(s.name), s.id);
    EXPECT_EQ(&ik_solver_info(s.id), &s);
  }
  EXPECT_EQ(find_ik_solver("ccd"), IkSolver::CCD);
  EXPECT_EQ(find_ik_solver("fabrik"), IkSolver::FABRIK);
  EXPECT_EQ(find_ik_solver("dls"), IkSolver::DLS);
  EXPECT_FALSE(find_ik_solver("CCD"));
  EXPECT_FALSE(find_ik_solver("jacobian"));
  EXPECT_EQ(ik_solver_names(), "ccd, fabrik, dls");
}

TEST(ClampAngle, WrapsThenTakesTheNearerEndOfTheAllowedArc) {
  const std::optional<JointLimit> none;
  EXPECT_NEAR(clamp_angle(270 * kDeg, none), -90 * kDeg, 1e-15);
  EXPECT_NEAR(clamp_angle(-450 * kDeg, none), -90 * kDeg, 1e-15);
  EXPECT_NEAR(clamp_angle(0.25, none), 0.25, 0.0);
  const std::optional<JointLimit> half = JointLimit{-90 * kDeg, 90 * kDeg};
  EXPECT_EQ(clamp_angle(45 * kDeg, half), 45 * kDeg);
  EXPECT_EQ(clamp_angle(100 * kDeg, half), 90 * kDeg);    // 10 past max, 170 short of min
  EXPECT_EQ(clamp_angle(170 * kDeg, half), 90 * kDeg);    // 80 past max, 100 short of min
  EXPECT_EQ(clamp_angle(-170 * kDeg, half), -90 * kDeg);  // 100 past max, 80 short of min
  EXPECT_EQ(clamp_angle(250 * kDeg, half), -90 * kDeg);   // = -110: 20 short of min
  const std::optional<JointLimit> narrow = JointLimit{10 * kDeg, 20 * kDeg};
  EXPECT_EQ(clamp_angle(0.0, narrow), 10 * kDeg);
  EXPECT_EQ(clamp_angle(-160 * kDeg, narrow), 10 * kDeg);  // 180 past max, 170 short of min
  EXPECT_EQ(clamp_angle(-170 * kDeg, narrow), 20 * kDeg);  // 170 past max, 180 short of min
}

TEST(IkJacobian, MatchesCentralDifferencesOfForwardKinematics) {
  IkChain bent = tentacle();
  for (int i = 0; i < bent.size(); ++i) bent.angles[i] = std::sin(1.7 * i + 0.3);  // a wiggle
  for (const IkChain& chain : {arm(), tentacle(), bent}) {
    const Eigen::Matrix2Xd J = ik_jacobian(chain);
    ASSERT_EQ(J.cols(), chain.size());
    const double h = 1e-6;
    for (int i = 0; i < chain.size(); ++i) {
      IkChain plus = chain, minus = chain;
      plus.angles[i] += h;
      minus.angles[i] -= h;
      const Vector2d column = (complex_effector(plus) - complex_effector(minus)) / (2 * h);
      EXPECT_NEAR((J.col(i) - column).norm(), 0.0, 1e-8 * chain.reach()) << "joint " << i;
    }
  }
}

// One DLS iteration near the target (where neither max_step nor halving acts) turns the joints
// by exactly delta = J^T (J J^T + lambda^2 I)^-1 e, checked here in its other form
// (J^T J + lambda^2 I)^-1 J^T e, an N x N solve; and with lambda = 0 by the minimum-norm
// solution of J delta = e.
TEST(Dls, StepIsTheDampedLeastSquaresSolution) {
  for (const IkChain& start : {arm(), tentacle()})
    for (double damping : {0.1, 0.02, 0.0}) {
      IkSettings settings;
      settings.damping = damping;
      IkChain chain = start;
      const Vector2d target = complex_effector(chain) + Vector2d(1e-3, -2e-3);
      const Eigen::MatrixXd J = ik_jacobian(chain);
      const Eigen::VectorXd e = target - complex_effector(chain);
      const double lambda = damping * chain.reach();
      Eigen::VectorXd expected;
      if (damping > 0) {
        const Eigen::MatrixXd normal =
            J.transpose() * J + lambda * lambda * Eigen::MatrixXd::Identity(J.cols(), J.cols());
        expected = normal.ldlt().solve(J.transpose() * e);
      } else {
        expected = J.completeOrthogonalDecomposition().solve(e);
        EXPECT_NEAR((J * expected - e).norm(), 0.0, 1e-15);
      }
      ik_iterate(IkSolver::DLS, chain, target, settings);
      for (int i = 0; i < chain.size(); ++i)
        EXPECT_NEAR(chain.angles[i] - start.angles[i], expected[i], 1e-12)
            << "joint " << i << " damping " << damping;
      EXPECT_LT((complex_effector(chain) - target).norm(), e.norm());
    }
}

class EverySolver : public ::testing::TestWithParam<IkSolver> {};

TEST_P(EverySolver, ReachesReachableTargets) {
  const IkSolver solver = GetParam();
  IkSettings settings;
  settings.max_iterations = 5000;
  settings.tolerance = 1e-4;
  int targets = 0;
  for (const IkChain& start : {arm(), tentacle()}) {
    const double R = start.reach();
    for (double fraction : {0.25, 0.6, 0.9})
      for (double direction : {0.4, 1.9, -2.6, 3.1}) {
        const Vector2d target = polar(start.base, fraction * R, direction);
        IkChain chain = start;
        const IkStatus status = ik_solve(solver, chain, target, settings);
        const double error = (complex_effector(chain) - target).norm();
        EXPECT_TRUE(status.converged) << fraction << " " << direction << ": error " << error;
        EXPECT_LE(error, settings.tolerance) << fraction << " " << direction;
        EXPECT_NEAR(status.error, error, 1e-12);
        EXPECT_TRUE(status.reachable);
        EXPECT_FALSE(status.stalled);
        EXPECT_GE(status.iterations, 1);
        EXPECT_LT(status.iterations, settings.max_iterations);
        ++targets;
      }
  }
  EXPECT_EQ(targets, 24);
}

TEST_P(EverySolver, KeepsLinkLengthsExactAfterEveryIteration) {
  const IkSolver solver = GetParam();
  for (const IkChain& start : {arm(), tentacle()})
    for (double fraction : {0.5, 0.95, 1.7}) {
      IkChain chain = start;
      const Vector2d target = polar(start.base, fraction * start.reach(), 2.2);
      for (int k = 0; k < 60; ++k) {
        ik_iterate(solver, chain, target, {});
        ASSERT_LE(worst_length_error(chain), 1e-12)
            << "iteration " << k << " fraction " << fraction;
      }
    }
}

TEST_P(EverySolver, StretchesStraightTowardsAnUnreachableTarget) {
  const IkSolver solver = GetParam();
  IkSettings settings;
  settings.max_iterations = 5000;
  for (const IkChain& start : {arm(), tentacle()})
    for (double fraction : {1.5, 3.0})
      for (double direction : {0.4, 1.9, -2.6, 3.1}) {
        const Vector2d target = polar(start.base, fraction * start.reach(), direction);
        IkChain chain = start;
        const IkStatus status = ik_solve(solver, chain, target, settings);
        EXPECT_FALSE(status.reachable);
        EXPECT_FALSE(status.converged);
        // Joint i at arc length s_i = L_0 + ... + L_{i-1} along the unit vector to the target.
        const Vector2d u = (target - start.base).normalized();
        const auto p = complex_positions(chain);
        double s = 0.0;
        for (int i = 0; i <= chain.size(); ++i) {
          EXPECT_NEAR((p[i] - (start.base + s * u)).norm(), 0.0, 1e-6)
              << "joint " << i << " of " << chain.size() << ", " << fraction << " " << direction;
          if (i < chain.size()) s += chain.lengths[i];
        }
        EXPECT_NEAR((p.back() - start.base).norm(), start.reach(), 1e-6);
        EXPECT_NEAR(status.error, (fraction - 1.0) * start.reach(), 1e-6);
      }
}

TEST_P(EverySolver, RespectsJointLimitsAfterEveryIteration) {
  const IkSolver solver = GetParam();
  IkChain limited_arm = arm();
  limited_arm.limits = {JointLimit{-30 * kDeg, 30 * kDeg}, JointLimit{0.0, 45 * kDeg},
                        JointLimit{-15 * kDeg, 15 * kDeg}};
  IkChain limited_tentacle = tentacle();
  limited_tentacle.limits.assign(20, JointLimit{-5 * kDeg, 12 * kDeg});
  limited_tentacle.limits[7] = std::nullopt;  // one free joint among them
  for (const IkChain& start : {limited_arm, limited_tentacle})
    for (double fraction : {0.3, 0.8, 2.0})
      for (double direction : {0.3, 2.5, -1.2}) {
        IkChain chain = start;
        const Vector2d target = polar(start.base, fraction * start.reach(), direction);
        for (int k = 0; k < 100; ++k) {
          ik_iterate(solver, chain, target, {});
          for (int i = 0; i < chain.size(); ++i)
            if (const auto limit = chain.limit(i)) {
              ASSERT_GE(chain.angles[i], limit->min) << "joint " << i << " iteration " << k;
              ASSERT_LE(chain.angles[i], limit->max) << "joint " << i << " iteration " << k;
            }
          ASSERT_LE(worst_length_error(chain), 1e-12);
        }
      }
}

INSTANTIATE_TEST_SUITE_P(Ik, EverySolver,
                         ::testing::Values(IkSolver::CCD, IkSolver::FABRIK, IkSolver::DLS),
                         [](const auto& info) { return solver_name(info.param); });

// CCD is coordinate descent: each joint takes the angle, within its limits, nearest the one
// pointing the effector at the target, and |e|^2 = |a|^2 + |b|^2 - 2 |a| |b| cos(angle between)
// grows with that angle, so no joint's turn can increase the error. DLS halves its step until
// the error falls. So for both the error never grows, with limits or without. (FABRIK's passes
// promise no such thing, and with limits it can end farther than it started.)
TEST(IkSolvers, CcdAndDlsNeverIncreaseTheError) {
  IkChain limited = arm();
  limited.limits = {JointLimit{-60 * kDeg, 60 * kDeg}, JointLimit{0.0, 90 * kDeg},
                    JointLimit{-45 * kDeg, 45 * kDeg}};
  IkChain wiggly = tentacle();
  for (int i = 0; i < wiggly.size(); ++i) wiggly.angles[i] = 0.5 * std::sin(1.7 * i + 0.3);
  for (IkSolver solver : {IkSolver::CCD, IkSolver::DLS})
    for (const IkChain& start : {arm(), limited, tentacle(), wiggly})
      for (double fraction : {0.2, 0.7, 1.0, 1.4})
        for (double direction : {0.5, 2.4, -2.0}) {
          IkChain chain = start;
          const Vector2d target = polar(start.base, fraction * start.reach(), direction);
          double error = (complex_effector(chain) - target).norm();
          for (int k = 0; k < 100; ++k) {
            ik_iterate(solver, chain, target, {});
            const double next = (complex_effector(chain) - target).norm();
            ASSERT_LE(next, error + 1e-13) << solver_name(solver) << " iteration " << k;
            error = next;
          }
        }
}

// The 2-link arm has exactly two solutions for a target strictly inside its annulus: by the law
// of cosines, cos theta_1 = (d^2 - L_0^2 - L_1^2) / (2 L_0 L_1), theta_1 = +-acos(...) (elbow
// one way or the other), and theta_0 = atan2(t) - atan2(L_1 sin theta_1, L_0 + L_1 cos theta_1).
TEST(NonUniqueness, ElbowUpAndElbowDownAreBothFound) {
  const double L0 = 1.0, L1 = 0.7;
  const Vector2d target(1.1, 0.5);
  const double d = target.norm();
  const double elbow = std::acos((d * d - L0 * L0 - L1 * L1) / (2 * L0 * L1));
  const auto solution = [&](double theta1) {
    return std::vector<double>{std::atan2(target.y(), target.x()) -
                                   std::atan2(L1 * std::sin(theta1), L0 + L1 * std::cos(theta1)),
                               theta1};
  };
  const std::vector<double> up = solution(elbow), down = solution(-elbow);
  EXPECT_GT(std::abs(up[0] - down[0]), 0.5);  // two genuinely different poses
  EXPECT_GT(up[1], 0.5);
  EXPECT_LT(down[1], -0.5);

  IkSettings settings;
  settings.tolerance = 1e-10;
  settings.max_iterations = 20000;
  const auto solve = [&](IkSolver solver, const std::vector<double>& start) {
    IkChain chain;
    chain.lengths = {L0, L1};
    chain.angles = start;
    const IkStatus status = ik_solve(solver, chain, target, settings);
    EXPECT_TRUE(status.converged) << solver_name(solver) << " " << status.error;
    return chain.angles;
  };
  // An effector error of 1e-10 allows angle errors of about 1e-10 / (L0 L1 sin theta_1).
  const auto expect_pose = [](const std::vector<double>& got, const std::vector<double>& want,
                              const std::string& what) {
    EXPECT_NEAR(got[0], want[0], 1e-8) << what;
    EXPECT_NEAR(got[1], want[1], 1e-8) << what;
  };
  for (IkSolver solver : {IkSolver::CCD, IkSolver::FABRIK, IkSolver::DLS}) {
    // The same solver from two starting poses, each 0.2 rad off one of the solutions: each
    // start leads to its own solution.
    expect_pose(solve(solver, {up[0] + 0.2, up[1] - 0.2}), up, solver_name(solver) + " up");
    expect_pose(solve(solver, {down[0] - 0.2, down[1] + 0.2}), down, solver_name(solver) + " down");
    // From farther away any solution may come out, but it is always one of the two.
    for (double start_elbow : {-50 * kDeg, 50 * kDeg}) {
      const auto got = solve(solver, {0.0, start_elbow});
      expect_pose(got, got[1] > 0 ? up : down, solver_name(solver) + " from the x axis");
    }
  }
  // From the elbow-down start on the x axis DLS keeps its elbow down while CCD (which turns
  // the last joint first) swings it up: different solvers, different answers.
  EXPECT_LT(solve(IkSolver::DLS, {0.0, -50 * kDeg})[1], 0.0);
  EXPECT_GT(solve(IkSolver::CCD, {0.0, -50 * kDeg})[1], 0.0);
}

TEST(NonUniqueness, DifferentSolversReachTheSameTargetInDifferentPoses) {
  const Vector2d target = polar(arm().base, 1.5, 2.0);
  std::vector<IkChain> solved;
  for (IkSolver solver : {IkSolver::CCD, IkSolver::FABRIK, IkSolver::DLS}) {
    IkChain chain = arm();
    const IkStatus status = ik_solve(solver, chain, target, {});
    ASSERT_TRUE(status.converged) << solver_name(solver);
    EXPECT_LE((complex_effector(chain) - target).norm(), 1e-4);
    solved.push_back(chain);
  }
  for (int a = 0; a < 3; ++a)
    for (int b = a + 1; b < 3; ++b) {
      double apart = 0.0;
      for (int i = 0; i < 3; ++i)
        apart = std::max(apart, std::abs(wrap_angle(solved[a].angles[i] - solved[b].angles[i])));
      EXPECT_GT(apart, 0.05) << a << " " << b;  // radians: visibly different poses
    }
}

TEST(IkSolvers, AStraightChainWithItsTargetOnItsLine) {
  // A straight arm with the target on its own line: every column of J is perpendicular to the
  // line and e lies along it, so J^T e = 0 and the DLS step is exactly zero. FABRIK places each
  // point along the line from the last, so it stays on the line too, where the arm (links 1,
  // 0.8, 0.6) reaches only 2.4, 1.2, 0.8 or 0.4 from the base, never 1.5.
  IkChain straight;
  straight.lengths = {1.0, 0.8, 0.6};
  straight.angles = {0.0, 0.0, 0.0};
  const Vector2d target(1.5, 0.0);
  EXPECT_EQ((ik_jacobian(straight).transpose() * (target - straight.effector())).norm(), 0.0);
  IkChain dls = straight;
  const IkStatus stuck = ik_solve(IkSolver::DLS, dls, target, {});
  EXPECT_TRUE(stuck.stalled);
  EXPECT_FALSE(stuck.converged);
  EXPECT_EQ(stuck.iterations, 1);
  EXPECT_EQ(dls.angles, straight.angles);
  IkChain fabrik = straight;
  for (int k = 0; k < 50; ++k) {
    ik_iterate(IkSolver::FABRIK, fabrik, target, {});
    for (const Vector2d& p : complex_positions(fabrik)) ASSERT_NEAR(p.y(), 0.0, 1e-12) << k;
  }
  EXPECT_NEAR((fabrik.effector() - target).norm(), 0.3, 1e-12);  // folded at 1.2
  // CCD turns by atan2(0, +-x) = 0 or pi, also along the line: it folds the last link back
  // (effector at 1.2). But that fold is unstable for CCD: a bend eps at the middle joint comes
  // back about five times larger each iteration, so the 1e-16 of rounding in sin(pi) carries
  // the arm off the line within some twenty iterations, and it then converges.
  IkChain ccd = straight;
  const IkStatus escaped = ik_solve(IkSolver::CCD, ccd, target, {});
  EXPECT_TRUE(escaped.converged);
  EXPECT_GT(escaped.iterations, 10);
  // A millimetre off the line, every solver reaches the target at once.
  for (IkSolver solver : {IkSolver::CCD, IkSolver::FABRIK, IkSolver::DLS}) {
    IkChain chain = straight;
    const IkStatus status = ik_solve(solver, chain, target + Vector2d(0.0, 1e-3), {});
    EXPECT_TRUE(status.converged) << solver_name(solver);
    EXPECT_LT(status.iterations, 50) << solver_name(solver);
  }
}

TEST(IkSolve, StopsAtOnceOnTheTargetAndReportsTheInnerHole) {
  IkChain chain = arm();
  const IkStatus there = ik_solve(IkSolver::DLS, chain, chain.effector(), {});
  EXPECT_EQ(there.iterations, 0);
  EXPECT_TRUE(there.converged);
  // A long first link leaves a hole of radius 2 L_max - reach = 0.6 around the base.
  chain.lengths = {2.0, 0.8, 0.6};
  EXPECT_FALSE(ik_status(chain, chain.base + Vector2d(0.5, 0.0), {}).reachable);
  EXPECT_TRUE(ik_status(chain, chain.base + Vector2d(0.7, 0.0), {}).reachable);
  EXPECT_FALSE(ik_status(chain, chain.base + Vector2d(3.41, 0.0), {}).reachable);
}

// Scene reading.

using json_reader::json;
using json_reader::ObjectReader;

IkChain read(const std::string& text) {
  const json j = json::parse(text);
  ObjectReader r(j, "/ik/0", "scene 'arm.json'");
  return read_ik_chain(r);
}

// The message of the InputError that reading `text` throws ("" when none).
std::string ik_error_of(const std::string& text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ReadIkChain, ReadsAValidChainInDegrees) {
  const json j = json::parse(R"({"base": [1, 2, 0], "links": [1.0, 0.8, 0.6],
      "angles": [20, 10, -5], "limits": [[-90, 90], null, [-120, 120]], "target": [2, 2, 0]})");
  ObjectReader r(j, "/ik/0", "scene 'arm.json'");
  const IkChain c = read_ik_chain(r);
  EXPECT_EQ(c.base, Vector2d(1, 2));
  EXPECT_EQ(c.lengths, (std::vector<double>{1.0, 0.8, 0.6}));
  ASSERT_EQ(c.angles.size(), 3u);
  EXPECT_NEAR(c.angles[0], 20 * std::numbers::pi / 180, 1e-15);
  EXPECT_NEAR(c.angles[1], 10 * std::numbers::pi / 180, 1e-15);
  EXPECT_NEAR(c.angles[2], -5 * std::numbers::pi / 180, 1e-15);
  ASSERT_EQ(c.limits.size(), 3u);
  ASSERT_TRUE(c.limits[0]);
  EXPECT_NEAR(c.limits[0]->min, -std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(c.limits[0]->max, std::numbers::pi / 2, 1e-15);
  EXPECT_FALSE(c.limits[1]);
  EXPECT_NEAR(c.limits[2]->min, -2 * std::numbers::pi / 3, 1e-15);
  EXPECT_NEAR(c.limits[2]->max, 2 * std::numbers::pi / 3, 1e-15);
  // "target" is left to the caller: unknown until it reads it.
  EXPECT_THROW(r.finish(), InputError);
  r.raw("target");
  EXPECT_NO_THROW(r.finish());
}

TEST(ReadIkChain, DefaultsToAStraightChainAtTheOrigin) {
  const IkChain c = read(R"({"links": [0.5, 0.25]})");
  EXPECT_EQ(c.base, Vector2d::Zero());
  EXPECT_EQ(c.angles, (std::vector<double>{0.0, 0.0}));
  EXPECT_TRUE(c.limits.empty());
  EXPECT_EQ(c.effector(), Vector2d(0.75, 0.0));
  // Without angles, a joint whose limits exclude 0 starts at its nearer limit.
  const IkChain bent = read(R"({"links": [1, 1], "limits": [null, [10, 90]]})");
  EXPECT_NEAR(bent.angles[1], 10 * kDeg, 1e-15);
}

TEST(ReadIkChain, BadValuesNameTheFileAndTheField) {
  const struct {
    const char* text;
    const char* path;
  } cases[] = {
      {R"({"links": [1.0, 0, 0.6]})", "/ik/0/links/1"},            // a zero length
      {R"({"links": [1.0, -0.5]})", "/ik/0/links/1"},              // a negative length
      {R"({"links": [1e4]})", "/ik/0/links/0"},                    // too long
      {R"({"links": [1.0, "0.5"]})", "/ik/0/links/1"},             // a string
      {R"({"links": 1.0})", "/ik/0/links:"},                       // not an array
      {R"({"links": {"a": 1}})", "/ik/0/links:"},                  // an object
      {R"({"links": []})", "/ik/0/links:"},                        // no links
      {R"({"angles": [0]})", "/ik/0/links:"},                      // links missing
      {R"({"links": [1, 1], "angles": [10]})", "/ik/0/angles:"},   // too few angles
      {R"({"links": [1], "angles": [10, 20]})", "/ik/0/angles:"},  // too many angles
      {R"({"links": [1, 1], "angles": [10, true]})", "/ik/0/angles/1"},
      {R"({"links": [1], "angles": [200]})", "/ik/0/angles/0"},
      {R"({"links": [1, 1], "limits": [[90, -90], null]})", "/ik/0/limits/0:"},  // min > max
      {R"({"links": [1, 1], "limits": [null, [30, 30]]})", "/ik/0/limits/1:"},   // min = max
      {R"({"links": [1], "limits": [[-190, 90]]})", "/ik/0/limits/0/0"},
      {R"({"links": [1], "limits": [[-90, "90"]]})", "/ik/0/limits/0/1"},
      {R"({"links": [1], "limits": [[-90, 0, 90]]})", "/ik/0/limits/0:"},
      {R"({"links": [1, 1], "limits": [[-90, 90]]})", "/ik/0/limits:"},  // too few limits
      {R"({"links": [1], "limits": [-90, 90]})", "/ik/0/limits:"},       // not one per link
      {R"({"links": [1], "limits": [[-90, 90]], "angles": [100]})", "/ik/0/angles/0"},
      {R"({"links": [1], "base": [0, 0, 1]})", "/ik/0/base/2"},  // off the plane
      {R"({"links": [1], "base": [0, 0]})", "/ik/0/base"},
  };
  for (const auto& c : cases) {
    const std::string message = ik_error_of(c.text);
    EXPECT_NE(message.find("scene 'arm.json': "), std::string::npos) << c.text << " -> " << message;
    EXPECT_NE(message.find(c.path), std::string::npos) << c.text << " -> " << message;
  }
  // 1000 links are allowed, 1001 are one too many.
  std::string links = R"({"links": [1)";
  for (int i = 1; i < kMaxIkLinks; ++i) links += ", 1";
  EXPECT_EQ(read(links + "]}").size(), kMaxIkLinks);
  EXPECT_NE(ik_error_of(links + ", 1]}").find("/ik/0/links: must be an array of 1 to 1000"),
            std::string::npos);
}

TEST(ReadIkChain, MessagesSayWhatIsAllowed) {
  EXPECT_EQ(ik_error_of(R"({"links": [1.0, 0]})"),
            "scene 'arm.json': /ik/0/links/1: must be in (0, 1000], got 0");
  EXPECT_EQ(ik_error_of(R"({"links": [1, 1], "limits": [[90, -90], null]})"),
            "scene 'arm.json': /ik/0/limits/0: must have min < max, got [90,-90]");
  EXPECT_EQ(ik_error_of(R"({"links": [1, 1], "angles": [10]})"),
            "scene 'arm.json': /ik/0/angles: must be an array of one angle per link (2) in "
            "degrees, each in [-180, 180], got 1 entries");
  EXPECT_EQ(ik_error_of(R"({"links": [1], "limits": [[-90, 90]], "angles": [100]})"),
            "scene 'arm.json': /ik/0/angles/0: must be within the joint's limits [-90, 90] "
            "(\"limits\"), got 100");
}

}  // namespace
}  // namespace springlab
