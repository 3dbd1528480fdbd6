// The implicit Euler solver: the matrix-free system it solves equals the matrix assembled from
// the spring kernel's 3x3 blocks; its solve meets the stated tolerance; pinned particles keep
// dv = 0; and cloth at one step a frame gives the same bits on any number of threads.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <string>
#include <utility>

#include "methods/implicit_euler.hpp"
#include "methods/stage_newton.hpp"
#include "springlab/forces.hpp"
#include "springlab/methods.hpp"
#include "springlab/spring_kernel.hpp"
#include "support.hpp"

namespace springlab {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// A cloth with its corners pinned, shaken: random displacements (some springs compressed, some
// stretched) and velocities, and the pinned corners moving too.
State shaken(const Scene& scene, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  State s = scene.state;
  const double spacing = (s.x.row(1) - s.x.row(0)).norm();
  for (int i = 0; i < s.particle_count(); ++i)
    for (int c = 0; c < 3; ++c) {
      s.x(i, c) += 0.3 * spacing * n(rng);
      s.v(i, c) = n(rng);
    }
  return s;
}

VectorXd flat(const Points& p) {
  VectorXd out(3 * p.rows());
  for (int i = 0; i < p.rows(); ++i) out.segment<3>(3 * i) = p.row(i).transpose();
  return out;
}

// A = M - h df/dv - h^2 df/dx and b = h (f + h df/dx v), assembled block by block from
// spring_jacobian (the definite form); pinned rows and columns are the identity's.
void assemble(const Model& m, const State& s, double h, MatrixXd& A, VectorXd& b) {
  const int n = m.particle_count();
  A = MatrixXd::Zero(3 * n, 3 * n);
  Points f;
  SpringForces buffer;
  evaluate_forces(m, s.x, s.v, f, buffer, ForceOutput::Force);
  b = h * flat(f);
  for (int i = 0; i < n; ++i)
    A.block<3, 3>(3 * i, 3 * i).diagonal().setConstant(m.mass[i] + h * m.drag);
  for (int k = 0; k < m.spring_count(); ++k) {
    const int a = m.spring_a[k], c = m.spring_b[k];
    const Vec3 xa = s.x.row(a).transpose(), xb = s.x.row(c).transpose();
    const Vec3 va = s.v.row(a).transpose(), vb = s.v.row(c).transpose();
    const SpringJacobian J =
        spring_jacobian(xa, xb, va, vb, m.ks(k), m.kd(k), m.rest_length[k], true);
    const Eigen::Matrix3d B = h * J.dfdv + h * h * J.dfdx;
    A.block<3, 3>(3 * a, 3 * a) += B;
    A.block<3, 3>(3 * c, 3 * c) += B;
    A.block<3, 3>(3 * a, 3 * c) -= B;
    A.block<3, 3>(3 * c, 3 * a) -= B;
    const Vec3 Kv = h * h * J.dfdx * (vb - va);
    b.segment<3>(3 * a) += Kv;
    b.segment<3>(3 * c) -= Kv;
  }
  for (int i = 0; i < n; ++i)
    if (m.pinned(i)) {
      A.middleRows<3>(3 * i).setZero();
      A.middleCols<3>(3 * i).setZero();
      A.block<3, 3>(3 * i, 3 * i).setIdentity();
      b.segment<3>(3 * i).setZero();
    }
}

TEST(ImplicitEuler, MatrixFreeSystemIsTheAssembledOne) {
  // One block of particles, then two: springs reach from one block into the next.
  for (auto [width, height] : {std::pair{9, 7}, std::pair{24, 20}}) {
    const Scene scene = test::shipped("cloth", {"cloth.width=" + std::to_string(width),
                                                "cloth.height=" + std::to_string(height)});
    const Model& m = scene.model;
    const double h = 1.0 / 60.0;
    for (unsigned seed : {1u, 2u, 3u}) {
      const State s = shaken(scene, seed);
      MatrixXd A;
      VectorXd b;
      assemble(m, s, h, A, b);
      if (m.particle_count() < 100) {  // what conjugate gradients need
        EXPECT_LT((A - A.transpose()).norm(), 1e-14 * A.norm());
        EXPECT_GT(Eigen::SelfAdjointEigenSolver<MatrixXd>(A).eigenvalues().minCoeff(), 0.0);
      }
      std::mt19937 rng(seed);
      std::normal_distribution<double> n(0.0, 1.0);
      Points p(m.particle_count(), 3);
      for (int i = 0; i < p.rows(); ++i)
        for (int c = 0; c < 3; ++c) p(i, c) = m.pinned(i) ? 0.0 : n(rng);
      Points Ap, b_free;
      implicit_euler_system::evaluate(m, s, h, p, Ap, b_free);
      EXPECT_LT((flat(Ap) - A * flat(p)).norm(), 1e-13 * A.norm() * flat(p).norm())
          << width << " " << seed;
      EXPECT_LT((flat(b_free) - b).norm(), 1e-13 * b.norm()) << width << " " << seed;
    }
  }
}

TEST(ImplicitEuler, SystemIsTheSameBitsOnAnyNumberOfThreads) {
  // Big enough for the solver's loops to run in parallel.
  const Scene scene = test::shipped("cloth", {"cloth.width=40", "cloth.height=40"});
  const State s = shaken(scene, 4);
  Points p = s.v;
  Points Ap[3], b[3];
  for (int threads : {1, 2, 3}) {
    set_thread_count(threads);
    implicit_euler_system::evaluate(scene.model, s, 1.0 / 60.0, p, Ap[threads - 1], b[threads - 1]);
  }
  set_thread_count(0);
  for (int k : {1, 2}) {
    EXPECT_TRUE((Ap[k].array() == Ap[0].array()).all());
    EXPECT_TRUE((b[k].array() == b[0].array()).all());
  }
}

TEST(ImplicitEuler, SolvesToTheStatedToleranceAndKeepsPinnedParticlesStill) {
  const Scene scene = test::shipped("cloth", {"cloth.width=12", "cloth.height=12"});
  const Model& m = scene.model;
  const double h = 1.0 / 60.0;
  const State s = shaken(scene, 5);
  for (double tolerance : {1e-4, 1e-6, 1e-9}) {
    StepSettings settings;
    settings.solver_tolerance = tolerance;
    Workspace ws;
    State out;
    step(Method::ImplicitEuler, m, s, out, h, settings, ws);
    EXPECT_EQ(ws.counters.linear_solves, 1);
    EXPECT_EQ(ws.counters.unconverged_solves, 0);
    EXPECT_GT(ws.counters.solver_iterations, 0);
    MatrixXd A;
    VectorXd b;
    assemble(m, s, h, A, b);
    const VectorXd dv = flat(out.v) - flat(s.v);
    // The solver's own residual is recurred; the true one differs from it by rounding only.
    EXPECT_LE((A * dv - b).norm(), 1.01 * tolerance * b.norm()) << tolerance;
    for (int i = 0; i < m.particle_count(); ++i)
      if (m.pinned(i)) {
        EXPECT_EQ(out.v.row(i), s.v.row(i));
        EXPECT_EQ(out.x.row(i), s.x.row(i) + h * s.v.row(i));
      }
  }
}

TEST(ImplicitEuler, ClothAtOneStepAFrameIsTheSameBitsOnAnyNumberOfThreads) {
  // The case the solver is tuned for (cloth 64 x 64, h = 1/60), long enough for the cloth to fold.
  const Scene scene = test::shipped("cloth", {"cloth.width=64", "cloth.height=64"});
  std::uint64_t hashes[3];
  std::int64_t iterations[3];
  for (int threads : {1, 2, 3}) {
    set_thread_count(threads);
    Simulation sim = test::simulation(scene, Method::ImplicitEuler, 1.0 / 60.0);
    EXPECT_EQ(sim.advance(12), 12);
    hashes[threads - 1] = state_hash(sim.state());
    iterations[threads - 1] = sim.counters().solver_iterations;
    EXPECT_EQ(sim.counters().unconverged_solves, 0);
  }
  set_thread_count(0);
  EXPECT_EQ(hashes[1], hashes[0]);
  EXPECT_EQ(hashes[2], hashes[0]);
  EXPECT_EQ(iterations[1], iterations[0]);
  EXPECT_EQ(iterations[2], iterations[0]);
}

// `implicit-euler` is one linearised Newton step (Baraff and Witkin), not the converged
// backward-Euler step; steps::backward_euler_converged (the DIRK stages' solve) is that step:
// m (v1 - v) = h f(x1, v1) to 1e-12, and vertex block descent run long from the same state lands
// on it (VBD, like local-global, tends to the converged step, not to the linearised one). On the
// heavy chain at one step a frame (h = 1/30 s, 150 steps) the linearised step's positions are up
// to 17.6 % of the step's motion away from the converged step's (mean 1.3 %).
TEST(ImplicitEuler, TheLinearisedStepIsNotTheConvergedOneWhichVbdTendsTo) {
  const Scene scene = test::shipped("chain");
  const double h = 1.0 / 30.0;
  Simulation sim = test::simulation(scene, Method::ImplicitEuler, h);
  const auto rms = [&](const Points& a, const Points& b) {
    return test::rms_over_free(scene.model, a, b);
  };
  double worst = 0.0;
  StepSettings settings;
  settings.solver_tolerance = 1e-10;
  for (int k = 0; k < 150; ++k) {
    const State start = sim.state();
    State linearised, converged;
    Workspace a, b;
    steps::NewtonSolver newton;
    step(Method::ImplicitEuler, scene.model, start, linearised, h, settings, a);
    steps::backward_euler_converged(scene.model, start, converged, h, settings, b, newton);
    // The converged step's residual, against the forces at its end (the force pass's own), to 1e-9
    // of h times the largest tension or weight.
    const double residual = test::backward_euler_residual(scene.model, start, converged, h).worst;
    double scale = 0.0;
    for (int i = 0; i < scene.model.particle_count(); ++i)
      if (!scene.model.pinned(i))
        scale = std::max(scale, scene.model.mass[i] * scene.model.gravity.norm());
    for (int s = 0; s < scene.model.spring_count(); ++s)  // the largest tension
      scale =
          std::max(scale, scene.model.ks(s) * std::abs((converged.x.row(scene.model.spring_b[s]) -
                                                        converged.x.row(scene.model.spring_a[s]))
                                                           .norm() -
                                                       scene.model.rest_length[s]));
    ASSERT_LE(residual, 1e-9 * h * scale) << "step " << k;
    worst = std::max(worst, rms(linearised.x, converged.x) / rms(converged.x, start.x));
    if (k == 100) {  // VBD to convergence from the same state: the converged step
      StepSettings many;
      many.iterations = 4096;
      State vbd;
      Workspace c;
      step(Method::VBD, scene.model, start, vbd, h, many, c);
      EXPECT_LT(rms(vbd.x, converged.x), 1e-6 * rms(converged.x, start.x));
      EXPECT_GT(rms(linearised.x, converged.x), 1e3 * rms(vbd.x, converged.x));
    }
    sim.step();
  }
  EXPECT_GT(worst, 0.1);
  EXPECT_LT(worst, 0.25);
}

// The stages' Newton iteration (methods/stage_newton.hpp) uses G's true Jacobian: against central
// differences of G(V) = M (V - v) - h f(x + h V, V), on a cloth crumpled at random (compressed
// springs, whose transverse stiffness is negative; damping, whose direction turns with the
// springs) and on the vortex (an attractor's pull and swirl, not symmetric), to 1e-6 of |J e|.
TEST(StageNewton, TheJacobianIsTheResidualsDerivative) {
  for (const auto& [name, sets] :
       {std::pair<const char*, std::vector<std::string>>{"cloth",
                                                         {"cloth.width=8", "cloth.height=8"}},
        std::pair<const char*, std::vector<std::string>>{"vortex", {}}}) {
    SCOPED_TRACE(name);
    const Scene scene = test::shipped(name, sets);
    const Model& m = scene.model;
    const int n = m.particle_count();
    std::mt19937 random(7);
    std::normal_distribution<double> normal(0.0, 1.0);
    Points x = scene.state.x, V = scene.state.v;
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) {
        x(i, c) += 0.05 * normal(random);
        V(i, c) = normal(random);
      }
    const double h = 1.0 / 60.0;
    const auto G = [&](const Points& v) {
      Points f;
      SpringForces buffer;
      evaluate_forces(m, x + h * v, v, f, buffer, ForceOutput::Force);
      Eigen::VectorXd g(3 * n);
      for (int i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c)
          g(3 * i + c) =
              m.pinned(i) ? 0.0 : m.mass[i] * (v(i, c) - scene.state.v(i, c)) - h * f(i, c);
      return g;
    };
    const Eigen::SparseMatrix<double> J = steps::stage_jacobian(m, x + h * V, V, h);
    for (int trial = 0; trial < 4; ++trial) {
      Points e(n, 3);
      Eigen::VectorXd flat(3 * n);
      for (int i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) flat(3 * i + c) = e(i, c) = m.pinned(i) ? 0.0 : normal(random);
      const double eps = 1e-6;
      const Eigen::VectorXd difference = (G(V + eps * e) - G(V - eps * e)) / (2.0 * eps);
      const Eigen::VectorXd product = J * flat;
      EXPECT_LE((difference - product).norm(), 1e-6 * product.norm());
    }
  }
}

}  // namespace
}  // namespace springlab
