// The spring force and its Jacobians: derivatives against central finite differences, the
// definite form's symmetry and sign, degenerate springs, and damping's indifference to rigid
// motion.
#include "springlab/spring_kernel.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <random>

#include "springlab/forces.hpp"
#include "support.hpp"

namespace springlab {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

struct Config {
  Vector3d xa, xb, va, vb;
  double ks, kd, rest;
};

std::vector<Config> random_configs(int count) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto vec = [&] { return Vector3d(u(rng), u(rng), u(rng)); };
  std::vector<Config> out;
  for (int k = 0; k < count; ++k) {
    Config c{vec(), vec(), vec(), vec(), 50.0 + 50.0 * u(rng), 1.0 + u(rng), 0.0};
    const double l = (c.xb - c.xa).norm();
    // Stretched, compressed, and the idealised zero-length spring of the lecture notes.
    c.rest = k % 3 == 0 ? 0.5 * l : k % 3 == 1 ? 1.7 * l : 0.0;
    out.push_back(c);
  }
  return out;
}

TEST(SpringKernel, ForceFollowsHookeAndDampsOnlyAlongTheSpring) {
  const Vector3d xa(0, 0, 0), xb(2, 0, 0);
  // Stretched by 1 with k_s = 10: 10 N on a towards b.
  EXPECT_TRUE(spring_force(xa, xb, Vector3d::Zero(), Vector3d::Zero(), 10, 0, 1)
                  .isApprox(Vector3d(10, 0, 0)));
  // b moving away at 3 m/s with k_d = 2: 6 N more on a towards b; sideways motion is not damped.
  EXPECT_TRUE(spring_force(xa, xb, Vector3d::Zero(), Vector3d(3, 0, 0), 10, 2, 1)
                  .isApprox(Vector3d(16, 0, 0)));
  EXPECT_TRUE(spring_force(xa, xb, Vector3d::Zero(), Vector3d(0, 3, 0), 10, 2, 1)
                  .isApprox(Vector3d(10, 0, 0)));
}

TEST(SpringKernel, JacobiansMatchFiniteDifferences) {
  const double eps = 1e-6;
  for (const Config& c : random_configs(30)) {
    const SpringJacobian J = spring_jacobian(c.xa, c.xb, c.va, c.vb, c.ks, c.kd, c.rest, false);
    Matrix3d fd_x, fd_v;
    for (int k = 0; k < 3; ++k) {
      const Vector3d e = Vector3d::Unit(k) * eps;
      fd_x.col(k) = (spring_force(c.xa, c.xb + e, c.va, c.vb, c.ks, c.kd, c.rest) -
                     spring_force(c.xa, c.xb - e, c.va, c.vb, c.ks, c.kd, c.rest)) /
                    (2 * eps);
      fd_v.col(k) = (spring_force(c.xa, c.xb, c.va, c.vb + e, c.ks, c.kd, c.rest) -
                     spring_force(c.xa, c.xb, c.va, c.vb - e, c.ks, c.kd, c.rest)) /
                    (2 * eps);
    }
    EXPECT_LT((J.dfdx - fd_x).norm(), 1e-6 * (1 + fd_x.norm())) << "rest " << c.rest;
    EXPECT_LT((J.dfdv - fd_v).norm(), 1e-6 * (1 + fd_v.norm()));
    // d f_a / d x_a = -dfdx: the force depends on differences only.
    Matrix3d fd_xa;
    for (int k = 0; k < 3; ++k) {
      const Vector3d e = Vector3d::Unit(k) * eps;
      fd_xa.col(k) = (spring_force(c.xa + e, c.xb, c.va, c.vb, c.ks, c.kd, c.rest) -
                      spring_force(c.xa - e, c.xb, c.va, c.vb, c.ks, c.kd, c.rest)) /
                     (2 * eps);
    }
    EXPECT_LT((J.dfdx + fd_xa).norm(), 1e-6 * (1 + fd_x.norm()));
  }
}

TEST(SpringKernel, DefiniteJacobianIsSymmetricPositiveAndExactAlongTheSpring) {
  for (const Config& c : random_configs(30)) {
    const SpringJacobian def = spring_jacobian(c.xa, c.xb, c.va, c.vb, c.ks, c.kd, c.rest, true);
    EXPECT_LT((def.dfdx - def.dfdx.transpose()).norm(), 1e-12 * def.dfdx.norm());
    Eigen::SelfAdjointEigenSolver<Matrix3d> eig(def.dfdx);
    EXPECT_GE(eig.eigenvalues().minCoeff(), -1e-9 * c.ks);
    const Vector3d u = (c.xb - c.xa).normalized();
    // Along u both agree when there is no damping term; k_s exactly.
    const SpringJacobian plain = spring_jacobian(c.xa, c.xb, c.va, c.vb, c.ks, 0.0, c.rest, false);
    EXPECT_NEAR(u.dot(plain.dfdx * u), u.dot(def.dfdx * u), 1e-9 * c.ks);
    EXPECT_NEAR(u.dot(def.dfdx * u), c.ks, 1e-9 * c.ks);
  }
}

// The balance's relaxation takes one step for all its states on this (equilibrium.cpp): a
// spring's stiffness, the potential's own (compressed: a negative sideways term) or the definite
// one, has no eigenvalue above k_s, so every state's stiffness is at most the springs' Laplacian.
TEST(SpringKernel, NoStateStiffensASpringBeyondKs) {
  for (const Config& c : random_configs(30))
    for (const bool definite : {false, true}) {
      const SpringJacobian J = spring_jacobian(c.xa, c.xb, c.va, c.vb, c.ks, 0.0, c.rest, definite);
      const Eigen::SelfAdjointEigenSolver<Matrix3d> eig(J.dfdx);
      EXPECT_LE(eig.eigenvalues().maxCoeff(), c.ks * (1.0 + 1e-12))
          << "rest " << c.rest << " definite " << definite;
      EXPECT_NEAR(eig.eigenvalues().maxCoeff(), c.ks,
                  1e-9 * c.ks);  // along the spring: the bound is reached
    }
}

TEST(SpringKernel, CompactDefiniteJacobianIsTheDefiniteJacobian) {
  // dfdx = stiff_along d d^T + stiff_across I and dfdv = damp_along d d^T, d = x_b - x_a.
  for (const Config& c : random_configs(30)) {
    const SpringJacobian J = spring_jacobian(c.xa, c.xb, c.va, c.vb, c.ks, c.kd, c.rest, true);
    const Vector3d d = c.xb - c.xa;
    const DefiniteSpringJacobian K = definite_spring_jacobian(d.squaredNorm(), c.ks, c.kd, c.rest);
    const Matrix3d dfdx = K.stiff_along * d * d.transpose() + K.stiff_across * Matrix3d::Identity();
    EXPECT_LT((dfdx - J.dfdx).norm(), 1e-12 * J.dfdx.norm()) << "rest " << c.rest;
    EXPECT_LT((K.damp_along * d * d.transpose() - J.dfdv).norm(), 1e-12 * J.dfdv.norm());
  }
  // Coincident ends: k_s I for the zero-length spring, zero for any other, and no NaN.
  for (double rest : {0.0, 1.0}) {
    const DefiniteSpringJacobian K = definite_spring_jacobian(0.0, 100, 5, rest);
    EXPECT_EQ(K.stiff_along, 0.0);
    EXPECT_EQ(K.stiff_across, rest == 0.0 ? 100.0 : 0.0);
    EXPECT_EQ(K.damp_along, 0.0);
  }
}

TEST(SpringKernel, CoincidentEndsGiveNoNaN) {
  const Vector3d p(0.3, -1.0, 2.0), v(1, 2, 3);
  for (double rest : {0.0, 1.0}) {
    const Vector3d f = spring_force(p, p, v, -v, 100, 5, rest);
    EXPECT_TRUE(f.allFinite());
    EXPECT_EQ(f, Vector3d::Zero());
    const SpringJacobian J = spring_jacobian(p, p, v, -v, 100, 5, rest, false);
    EXPECT_TRUE(J.dfdx.allFinite() && J.dfdv.allFinite());
  }
  // A zero-length spring is linear, f_a = k_s d, so its Jacobian is k_s I even at d = 0.
  EXPECT_TRUE(
      spring_jacobian(p, p, v, v, 100, 0, 0.0, false).dfdx.isApprox(100 * Matrix3d::Identity()));

  // In a simulation: two free particles on top of each other, joined by a spring.
  const Scene pair = test::coincident_pair(false, 100, 1);
  const Model& m = pair.model;
  const State& s = pair.state;
  for (Method method : {Method::Euler, Method::RK4, Method::ImplicitEuler, Method::Verlet}) {
    SimulationSettings settings;
    settings.method = method;
    Simulation sim(m, s, settings);
    EXPECT_EQ(sim.advance(100), 100) << method_info(method).name;
    EXPECT_TRUE(all_finite(sim.state()));
  }
}

// The force pass (blocks and their chunks, spans updated in place or kept for a later block,
// neighbours as chains, partial vectors masked) against the plain sum of spring_force() over the
// springs, on a jelly (one block), a cloth of several blocks (springs 1 to 2 x 48 particles apart),
// a long rope (neighbours only) and a tall narrow cloth (hundreds of row spans a block, each
// chunk's own listed in the plan).
TEST(SpringKernel, AssembledForcesAreTheSumOfTheKernels) {
  const Scene scenes[] = {test::shipped("jelly"),
                          test::shipped("cloth", {"cloth.width=48", "cloth.height=48"}),
                          test::shipped("rope", {"rope.nodes=3000"}),
                          test::shipped("cloth", {"cloth.width=7", "cloth.height=700"})};
  for (const Scene& scene : scenes) {
    const Model& m = scene.model;
    State s = scene.state;
    test::jitter(s, 0.05, 0.05, 3);
    Points f;
    SpringForces buffer;
    evaluate_forces(m, s.x, s.v, f, buffer, ForceOutput::Force);
    Points expected = Points::Zero(s.particle_count(), 3);
    for (int i = 0; i < s.particle_count(); ++i)
      expected.row(i) = m.mass[i] * m.gravity.transpose() - m.drag * s.v.row(i);
    for (int k = 0; k < m.spring_count(); ++k) {
      const int a = m.spring_a[k], b = m.spring_b[k];
      const Vector3d fa =
          spring_force(s.x.row(a).transpose(), s.x.row(b).transpose(), s.v.row(a).transpose(),
                       s.v.row(b).transpose(), m.ks(k), m.kd(k), m.rest_length[k]);
      expected.row(a) += fa.transpose();
      expected.row(b) -= fa.transpose();
    }
    // Per particle: the sums differ only in their order.
    const Eigen::ArrayXd error = (f - expected).rowwise().norm().array();
    const Eigen::ArrayXd size = expected.rowwise().norm().array() + 1.0;
    EXPECT_LT((error / size).maxCoeff(), 1e-12) << m.particle_count() << " particles";
    EXPECT_GT(buffer.plan.own.size(), scene.model.particle_count() > 2000 ? 1u : 0u);
    // The chunks' lists hold every spring of their blocks' pieces, once.
    long in_blocks = 0, in_chunks = 0;
    for (const auto& pieces : buffer.plan.own)
      for (const ForcePlan::Piece& piece : pieces) in_blocks += piece.hi - piece.lo;
    for (const auto& pieces : buffer.plan.chunk_own)
      for (const ForcePlan::Piece& piece : pieces) in_chunks += piece.hi - piece.lo;
    EXPECT_EQ(in_chunks, in_blocks);
    EXPECT_EQ(in_blocks, m.spring_count());
  }
}

TEST(SpringKernel, DampingIgnoresRigidTranslationAndRotation) {
  // A jelly at rest shape, with no gravity or drag, moving as a rigid body: v = V + w x r.
  Scene scene = test::shipped("jelly");
  scene.model.gravity.setZero();
  scene.model.drag = 0.0;
  set_damping(scene.model, 50.0);  // strong damping: any leak would show
  const Vector3d V(0.3, -2.0, 1.0), w(1.5, -0.5, 2.0);
  const Vector3d center = scene.state.x.colwise().mean().transpose();
  State s = scene.state;
  for (int i = 0; i < s.particle_count(); ++i)
    s.v.row(i) = (V + w.cross(s.x.row(i).transpose() - center)).transpose();
  Points f;
  SpringForces buffer;
  evaluate_forces(scene.model, s.x, s.v, f, buffer, ForceOutput::Force);
  EXPECT_LT(f.cwiseAbs().maxCoeff(), 1e-10);

  // Whereas stretching the springs is damped: a radial velocity field meets resistance.
  for (int i = 0; i < s.particle_count(); ++i) s.v.row(i) = s.x.row(i) - center.transpose();
  evaluate_forces(scene.model, s.x, s.v, f, buffer, ForceOutput::Force);
  EXPECT_GT(f.cwiseAbs().maxCoeff(), 1.0);
}

}  // namespace
}  // namespace springlab
