// The static balance a scene settles into (stability.hpp): by relaxation alone, or by
// relaxation and then Newton's method where a factorisation is cheap.
//
// Dynamic relaxation, for the large motions (a cloth held by two corners swinging from flat to
// hanging): the scene stepped with symplectic Euler at h = 1 / w_max (half its limit 2 / w_max),
// without damping, and every time its kinetic energy stops rising all velocities are set to
// zero (kinetic damping: the energy taken out is the most there is to take). A step costs one
// pass of the force loop, so thousands of them cost less than one factorisation of a large
// cloth's stiffness.
//
// Newton's method for the last digits: the springs' potential plus gravity's minimised with
// Levenberg-Marquardt damping,
//   (K + mu M) dx = f,   accepted when the potential falls (then mu shrinks, else it grows),
// K the definite stiffness (positive semidefinite: a pinned rope's sideways motions start with
// none, and mu M keeps the step finite), solved by a sparse LDL^T factorisation, or, once there is
// one, by conjugate gradients preconditioned with the last factorisation, only as accurately as
// the force is small (inexact Newton). Gravity acts on the particles joined by springs to a
// pinned one; a part with nothing pinned would fall forever (no balance), so it only relaxes its
// springs.
//
// Which, by the cost of a factorisation, known before making one
// (predicted_factorisation_work): a rope's or a small scene's is cheap, and Newton balances it
// to rounding (a long rope's sideways modes would take the relaxation hundreds of thousands of
// passes); a cloth's fills in (the 64 x 64 cloth's costs 0.15 s), and its relaxation alone goes
// on until every particle's force is a few per cent of its weight: the limits within 1e-3 of
// Newton's balance. Both have budgets, so that an analysis never stalls a run or the app: the
// relaxation a number of force passes, Newton an amount of factorisation (its preconditioned
// iterations counted in). equilibrium() below.
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "dynamics/force_pass.hpp"
#include "springlab/forces.hpp"
#include "springlab/simd.hpp"
#include "springlab/spring_kernel.hpp"
#include "springlab/stability.hpp"
#include "stability/cancel.hpp"
#include "stability/lanczos.hpp"
#include "stability/linearised.hpp"
#include "stability/parts.hpp"

namespace springlab {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Balance {
  const Model& model;
  std::vector<char> weighed;  // gravity acts on it
  std::vector<int> index;     // free coordinate block of each particle, -1 pinned
  int free = 0;

  explicit Balance(const Model& m)
      : model(m), weighed(m.particle_count(), 0), index(m.particle_count(), -1) {
    const int n = m.particle_count();
    Parts parts(m);
    for (int i = 0; i < n; ++i) {
      weighed[i] = !m.pinned(i) && parts.held_part(i);
      if (!m.pinned(i)) index[i] = free++;
    }
  }

  // Potential energy, and the force on each free particle.
  double potential(const Points& x) const {
    double e = 0.0;
    for (int s = 0; s < model.spring_count(); ++s)
      e += spring_energy(x.row(model.spring_a[s]).transpose(), x.row(model.spring_b[s]).transpose(),
                         model.ks(s), model.rest_length[s]);
    for (int i = 0; i < model.particle_count(); ++i)
      if (weighed[i]) e -= model.mass[i] * model.gravity.dot(x.row(i).transpose());
    return e;
  }
  Eigen::VectorXd force(const Points& x) const {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * free);
    for (int s = 0; s < model.spring_count(); ++s) {
      const int a = model.spring_a[s], b = model.spring_b[s];
      const Vec3 fa = spring_force(x.row(a).transpose(), x.row(b).transpose(), Vec3::Zero(),
                                   Vec3::Zero(), model.ks(s), 0.0, model.rest_length[s]);
      if (index[a] >= 0) f.segment<3>(3 * index[a]) += fa;
      if (index[b] >= 0) f.segment<3>(3 * index[b]) -= fa;
    }
    for (int i = 0; i < model.particle_count(); ++i)
      if (weighed[i]) f.segment<3>(3 * index[i]) += model.mass[i] * model.gravity;
    return f;
  }
  // K + mu M over the free coordinates, from the springs' blocks (blocks(), below).
  Eigen::SparseMatrix<double> system(const std::vector<Eigen::Matrix3d>& k, double mu) const {
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(static_cast<std::size_t>(model.spring_count()) * 36 + 3 * free);
    for (int s = 0; s < model.spring_count(); ++s) {
      const int ends[2] = {index[model.spring_a[s]], index[model.spring_b[s]]};
      for (int p = 0; p < 2; ++p)
        for (int q = 0; q < 2; ++q) {
          if (ends[p] < 0 || ends[q] < 0) continue;
          const double sign = p == q ? 1.0 : -1.0;
          for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
              t.emplace_back(3 * ends[p] + r, 3 * ends[q] + c, sign * k[s](r, c));
        }
    }
    for (int i = 0; i < model.particle_count(); ++i)
      if (index[i] >= 0)
        for (int c = 0; c < 3; ++c)
          t.emplace_back(3 * index[i] + c, 3 * index[i] + c, mu * model.mass[i]);
    Eigen::SparseMatrix<double> A(3 * free, 3 * free);
    A.setFromTriplets(t.begin(), t.end());
    return A;
  }
  // The springs' Hessian blocks at x: the potential's own (a compressed spring's negative
  // transverse term kept: near the balance Newton then converges quadratically; mu M covers
  // where it is indefinite). For system() and for products without assembly.
  std::vector<Eigen::Matrix3d> blocks(const Points& x) const {
    std::vector<Eigen::Matrix3d> out(static_cast<std::size_t>(model.spring_count()));
    for (int s = 0; s < model.spring_count(); ++s)
      out[s] = spring_jacobian(x.row(model.spring_a[s]).transpose(),
                               x.row(model.spring_b[s]).transpose(), Vec3::Zero(), Vec3::Zero(),
                               model.ks(s), 0.0, model.rest_length[s], false)
                   .dfdx;
    return out;
  }
  // (K + mu M) v from the blocks: one pass over the springs.
  Eigen::VectorXd product(const std::vector<Eigen::Matrix3d>& k, double mu,
                          const Eigen::VectorXd& v) const {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(v.size());
    for (int s = 0; s < model.spring_count(); ++s) {
      const int a = index[model.spring_a[s]], b = index[model.spring_b[s]];
      Vec3 d = Vec3::Zero();
      if (a >= 0) d += v.segment<3>(3 * a);
      if (b >= 0) d -= v.segment<3>(3 * b);
      const Vec3 g = k[s] * d;
      if (a >= 0) y.segment<3>(3 * a) += g;
      if (b >= 0) y.segment<3>(3 * b) -= g;
    }
    for (int i = 0; i < model.particle_count(); ++i)
      if (index[i] >= 0)
        y.segment<3>(3 * index[i]) += mu * model.mass[i] * v.segment<3>(3 * index[i]);
    return y;
  }
  void move(Points& x, const Eigen::VectorXd& dx, double scale) const {
    for (int i = 0; i < model.particle_count(); ++i)
      if (index[i] >= 0) x.row(i) += scale * dx.segment<3>(3 * index[i]).transpose();
  }
};

// The relaxation's step, h = 1 / w with w the highest frequency at `at` (tension raises it):
// Lanczos from below, to a few per cent, with a tenth more for what it may miss, and never above
// Gershgorin's bound; half the limit 2 / w_max (Gershgorin's bound alone is up to twice w_max on
// a cloth, and the relaxation would take that many more passes).
//
// It is stable in every state (`everywhere`) when h w_L < 2, w_L^2 = Gershgorin's bound on
// M^-1/2 L M^-1/2, L = sum over springs of k_s (e_a - e_b)(e_a - e_b)^T the springs' Laplacian
// (times I for x, y, z): a spring's Hessian k_s [u u^T + (1 - L_s / l) P] has no eigenvalue
// above k_s, stretched or compressed, so K(x) <= L (x) I for every x, and no state has a mode
// faster than w_L (a compressed spring's negative sideways term is a slow mode, not a fast one).
// Then one estimate serves the whole relaxation: it took eight, 6 ms each on a 64 x 64 cloth
// (every 2,000 passes), where w_max moves by a tenth of a per cent from flat to hanging (w_L is
// 1.44 times w_max, h w_L 1.37). Where h w_L >= 2 the step is estimated again every kRestep
// passes. What the step no longer follows is tension raising w_max as a scene stretches: the
// kinetic damping is then at h w_max above 0.95, and it stalls above about 1.4 (docs/decisions.md,
// "A larger relaxation step": a mode's speed falls on the second pass after the damping zeroes it
// when h w > 1, h f (2 - h^2 w^2) after h f). Measured: a 64 x 64 cloth of springs 200 times softer
// (k_s 2) stretches until w_max is a fifth higher, h w_max 1.16 at the end, and balances in 4,500
// passes, against 4,950 estimating again every 2,000; a 48 x 48 cloth started at h w_max 1.38
// balances in fewer passes than at 0.95.
struct RelaxStep {
  double h = 0.0;
  bool everywhere = false;
};
constexpr int kRestep = 2000;

RelaxStep relax_step(const Model& model, const State& at) {
  RelaxStep step;
  const Linearised lin(model, at);
  const double bound = lin.stiffness_bound();
  if (!(bound > 0.0)) return step;
  const Linearised::Combined op = lin.combined(1.0 / bound, 0.0);
  const TopEigenpair top = top_eigenpair([&](const Points& x, Points& y) { op.apply(x, y); },
                                         lin.random_vector(0x2545F4914F6CDD1Dull), 60, 1e-3);
  step.h = 1.0 / std::sqrt(bound * std::min(1.0, 1.1 * top.value));
  std::vector<double> row(model.particle_count(), 0.0);  // Gershgorin's row sums of M^-1/2 L M^-1/2
  for (int s = 0; s < model.spring_count(); ++s) {
    const int a = model.spring_a[s], b = model.spring_b[s];
    const double ra = std::sqrt(model.inv_mass[a]), rb = std::sqrt(model.inv_mass[b]);
    row[a] += model.ks(s) * ra * (ra + rb);
    row[b] += model.ks(s) * rb * (ra + rb);
  }
  const double w_laplacian = std::sqrt(*std::max_element(row.begin(), row.end()));
  step.everywhere = step.h * w_laplacian < 2.0;
  return step;
}

// Dynamic relaxation with kinetic damping (above), until the largest force is below `tolerance`
// or after `budget` force passes. Returns the largest force at its last look (every 50 passes):
// at most `tolerance` where it stopped on reaching it, above it (or NaN, where the positions are
// no longer finite) otherwise. Each pass is one force pass whose threads turn their particles'
// forces into the new velocities and positions as soon as a chunk's forces are complete
// (force_pass.hpp's finish), and sum the chunk's kinetic energy and largest force: no further
// pass over memory, and the same bits on any number of threads (per-block sums, added in block
// order).
double relax(const Model& model, const Balance& balance, State& rest, RelaxStep& step,
             double tolerance, int budget) {
  Model springs = model;  // the springs alone: gravity is added where it has a balance
  springs.gravity.setZero();
  springs.drag = 0.0;
  springs.attractors.clear();
  // No damping (the velocities passed are zero): the force pass's elastic kernel, which reads no
  // velocities.
  for (SpringMaterial& material : springs.materials) material.kd = 0.0;
  const int n = model.particle_count();
  // Column by column: the weight of the particles that have a balance (0 for the others and the
  // pinned ones, whose inverse mass is 0 too: they stay where they are).
  Points weight = Points::Zero(n, 3);
  for (int i = 0; i < n; ++i)
    if (balance.weighed[i]) weight.row(i) = model.mass[i] * model.gravity.transpose();
  Points v = Points::Zero(n, 3), zero = Points::Zero(n, 3), f(n, 3), next(n, 3);
  SpringForces buffer;
  const std::size_t blocks = plan_for(springs, buffer).own.size();
  // Per block: twice its kinetic energy after the pass, and its largest force component squared
  // (free particles) before it.
  std::vector<double> block_kinetic(blocks), block_force(blocks);
  double* const F[3] = {f.col(0).data(), f.col(1).data(), f.col(2).data()};
  double kinetic = 0.0, largest = kInfinity;
  constexpr int kLook = 50;
  for (int k = 0; k < budget; ++k) {
    if (k % 64 == 0) check_cancel();
    if (k > 0 && k % kRestep == 0 && !step.everywhere) step = relax_step(model, rest);
    const double h = step.h;
    if (!(h > 0.0)) return largest;
    std::fill(block_kinetic.begin(), block_kinetic.end(), 0.0);
    std::fill(block_force.begin(), block_force.end(), 0.0);
    force_pass(springs, rest.x, zero, F, buffer, [&](int block, int begin, int end) {
      // Symplectic Euler without damping: v += h M^-1 (f + weight), x' = x + h v.
      using simd::f64x4;
      const double* inv_mass = model.inv_mass.data();
      const double* mass = model.mass.data();
      f64x4 energy{}, largest{};
      const auto particles = [&]<typename T>(int i, T& e, T& m) {
        const T w = simd::at<T>(inv_mass + i);
        for (int c = 0; c < 3; ++c) {
          // A pinned particle's force is held (zero here, so that not even a NaN moves it).
          const T force =
              w > 0.0 ? simd::at<T>(F[c] + i) + simd::at<T>(weight.col(c).data() + i) : T{};
          const T pulled = force * force;
          m = pulled <= m ? m : pulled;  // a NaN wins: a relaxation gone wrong is never balanced
          const T vel = simd::at<T>(v.col(c).data() + i) + h * w * force;
          simd::store(v.col(c).data() + i, vel);
          simd::store(next.col(c).data() + i, simd::at<T>(rest.x.col(c).data() + i) + h * vel);
          e += simd::at<T>(mass + i) * vel * vel;
        }
      };
      int i = begin;
      for (; i + simd::kLanes <= end; i += simd::kLanes)
        particles.template operator()<f64x4>(i, energy, largest);
      double e = 0.0, m = 0.0;
      for (; i < end; ++i) particles.template operator()<double>(i, e, m);
      block_kinetic[block] += simd::sum(energy) + e;
      for (const double lane : {largest[0], largest[1], largest[2], largest[3], m})
        if (!(lane <= block_force[block])) block_force[block] = lane;
    });
    double energy = 0.0, squared = 0.0;
    for (std::size_t b = 0; b < blocks; ++b) {
      energy += block_kinetic[b];
      if (!(block_force[b] <= squared)) squared = block_force[b];
    }
    if (k % kLook == 0) {
      largest = std::sqrt(squared);
      if (largest <= tolerance) return largest;  // the positions before this pass
    }
    if (energy < kinetic) {
      v.setZero();  // past a peak of the kinetic energy: take it all out, and stay where it was
      kinetic = 0.0;
      continue;
    }
    kinetic = energy;
    rest.x.swap(next);
  }
  return largest;
}

using Factor = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;

// What one factorisation of Newton's system would cost, before making one: the sum over the
// factor L's columns of their nonzeros squared (the measure of Newton's budget below), from the
// symbolic factorisation (fill-reducing ordering, elimination tree, column counts) of the
// particles' graph, nine times smaller than the coordinates'. A particle's column with c
// entries below the diagonal is three of the coordinates' with 3c + 2, 3c + 1 and 3c. A rope's
// graph is a path and its factor a band (the 7000-node rope: 3.5e5); a cloth's fills in
// (the 64 x 64 cloth: 4.6e8, 0.15 s a factorisation here).
double predicted_factorisation_work(const Model& model, const Balance& balance) {
  struct Symbolic : Factor {
    double work() const {
      const auto* column = m_matrix.outerIndexPtr();
      double sum = 0.0;
      for (Eigen::Index j = 0; j < m_matrix.outerSize(); ++j) {
        const double c = static_cast<double>(column[j + 1] - column[j]);
        sum += (3 * c + 2) * (3 * c + 2) + (3 * c + 1) * (3 * c + 1) + 9 * c * c;
      }
      return sum;
    }
  };
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(2 * static_cast<std::size_t>(model.spring_count()) + balance.free);
  for (int s = 0; s < model.spring_count(); ++s) {
    const int a = balance.index[model.spring_a[s]], b = balance.index[model.spring_b[s]];
    if (a >= 0 && b >= 0 && a != b) {
      t.emplace_back(a, b, 1.0);
      t.emplace_back(b, a, 1.0);
    }
  }
  for (int i = 0; i < balance.free; ++i) t.emplace_back(i, i, 1.0);
  Eigen::SparseMatrix<double> graph(balance.free, balance.free);
  graph.setFromTriplets(t.begin(), t.end());
  Symbolic symbolic;
  symbolic.analyzePattern(graph);
  return symbolic.work();
}

// (K + mu M) dx = f by conjugate gradients with an earlier factorisation of the system as the
// preconditioner: near the balance K changes little from one Newton step to the next, so the
// preconditioned system is the identity plus a small change and a few products (a pass over the
// springs and two triangular solves each) replace a factorisation. False when that fails: no
// convergence within the budget, or a direction of negative curvature (K indefinite where the
// LDL^T of the new system is needed).
// `iterations` counts the products made.
bool preconditioned_solve(const Balance& balance, const std::vector<Eigen::Matrix3d>& k, double mu,
                          const Factor& preconditioner, const Eigen::VectorXd& f, double tolerance,
                          Eigen::VectorXd& dx, int& iterations) {
  constexpr int kIterations = 10;
  dx = Eigen::VectorXd::Zero(f.size());
  Eigen::VectorXd r = f, z = preconditioner.solve(r), p = z;
  double rz = r.dot(z);
  const double goal = tolerance * f.norm();
  for (int it = 0; it < kIterations; ++it) {
    ++iterations;
    const Eigen::VectorXd ap = balance.product(k, mu, p);
    const double curvature = p.dot(ap);
    if (!(curvature > 0.0)) return false;
    const double alpha = rz / curvature;
    dx += alpha * p;
    r -= alpha * ap;
    if (r.norm() <= goal) return true;
    z = preconditioner.solve(r);
    const double next = r.dot(z);
    p = z + (next / rz) * p;
    rz = next;
  }
  return false;
}

// Newton's iterations for the last digits, from `rest` (relaxed): each step a Levenberg-
// Marquardt solve (damping mu, in units of k / m, never below mu_floor) of the held parts'
// stiffness, accepted when the potential does not rise, until the largest force is `tolerance`
// (force_scale its yardstick), a step moves less than 1e-13 of the scene's `size`, or the
// budget is spent.
void newton(const Balance& balance, State& rest, double mu, double mu_floor, double force_scale,
            double tolerance, double size) {
  // Newton's budget in floating-point work, known after the first factorisation from its factor
  // L: a factorisation costs about the sum over L's columns of their nonzeros squared, a
  // preconditioned iteration (two triangular solves) four times L's nonzeros. 1.5e10 is 750
  // factorisations of the costliest system Newton is given (kNewtonWork); a rope's banded factor
  // is far cheaper, and it gets what its swing from flat needs (the 7000-node rope: 70
  // factorisations and 850 iterations, 0.85 s).
  constexpr double kWork = 1.5e10;
  double factorisation_work = 0.0, iteration_work = 0.0;
  Factor solver;
  bool analysed = false, factored = false;
  double energy = balance.potential(rest.x);
  int factorisations = 0, iterations = 0;
  const auto spent = [&] {
    return factorisations * factorisation_work + iterations * iteration_work;
  };
  for (int iteration = 0; iteration < 200 && spent() < kWork; ++iteration) {
    check_cancel();
    const Eigen::VectorXd f = balance.force(rest.x);
    if (f.lpNorm<Eigen::Infinity>() <= tolerance) break;
    const std::vector<Eigen::Matrix3d> k = balance.blocks(rest.x);
    // Inexact Newton (Eisenstat and Walker): the linear solve only as accurate as the force is
    // small, relative to its yardstick; the convergence stays quadratic.
    const double forcing = std::clamp(f.lpNorm<Eigen::Infinity>() / force_scale, 1e-12, 0.1);
    bool moved = false;
    for (int attempt = 0; attempt < 40 && spent() < kWork; ++attempt) {
      Eigen::VectorXd dx;
      if (!factored || !preconditioned_solve(balance, k, mu, solver, f, forcing, dx, iterations)) {
        const Eigen::SparseMatrix<double> A = balance.system(k, mu);
        if (!analysed) {
          solver.analyzePattern(A);
          analysed = true;
        }
        solver.factorize(A);
        ++factorisations;  // every one counts against the budget, the accepted ones too
        factored = solver.info() == Eigen::Success;
        if (factored && factorisation_work == 0.0) {
          const auto& L = solver.matrixL().nestedExpression();
          for (Eigen::Index j = 0; j < L.outerSize(); ++j) {
            const double column = L.outerIndexPtr()[j + 1] - L.outerIndexPtr()[j];
            factorisation_work += column * column;
          }
          factorisation_work = std::max(factorisation_work, 1.0);
          iteration_work = 4.0 * static_cast<double>(L.nonZeros());
        }
        if (!factored) {
          mu = std::max(10.0 * mu, mu_floor);
          continue;
        }
        dx = solver.solve(f);
      }
      if (dx.lpNorm<Eigen::Infinity>() <= 1e-13 * size) break;  // nothing left to move
      State trial = rest;
      balance.move(trial.x, dx, 1.0);
      const double e = balance.potential(trial.x);
      // Accepted when the potential does not rise beyond its rounding (near the balance its
      // changes are below it, and the force decides when to stop).
      if (std::isfinite(e) && e <= energy + 1e-13 * std::abs(energy)) {
        rest = std::move(trial);
        energy = std::min(energy, e);
        mu = std::max(mu / 8.0, mu_floor);
        moved = true;
        break;
      }
      mu = std::max(8.0 * mu, mu_floor);
    }
    if (!moved) break;  // no step lowers the potential: as balanced as rounding allows
  }
}

}  // namespace

State equilibrium(const Model& model, const State& state) {
  const struct Release {  // the relaxation's Lanczos runs' memory, however this ends
    ~Release() { release_lanczos_memory(); }
  } release;
  State rest = state;
  rest.v.setZero();
  const Balance balance(model);
  if (balance.free == 0 || model.spring_count() == 0) return rest;

  // The force's yardstick: the largest spring force at 1 % strain, or weight.
  double strain_force = 0.0, weight = 0.0;
  for (int s = 0; s < model.spring_count(); ++s)
    strain_force =
        std::max(strain_force, 0.01 * model.ks(s) * std::max(model.rest_length[s], 1e-3));
  for (int i = 0; i < model.particle_count(); ++i)
    if (balance.weighed[i]) weight = std::max(weight, model.mass[i] * model.gravity.norm());
  const double force_scale = std::max(strain_force, weight);
  if (!(force_scale > 0.0)) return rest;
  // Balanced to a millionth of that: the tension it leaves is the springs' to 1e-8 strain.
  const double tolerance = 1e-8 * force_scale;
  double size = 0.0;  // the scene's extent: steps below 1e-13 of it are rounding
  for (int c = 0; c < 3; ++c)
    size = std::max(size, rest.x.col(c).maxCoeff() - rest.x.col(c).minCoeff());

  // mu in units of k / m: start small against the stiffest spring on the lightest particle.
  double k_over_m = 0.0;
  for (int s = 0; s < model.spring_count(); ++s)
    k_over_m = std::max(k_over_m, model.ks(s) * std::max(model.inv_mass[model.spring_a[s]],
                                                         model.inv_mass[model.spring_b[s]]));
  const double mu_floor = 1e-12 * std::max(k_over_m, 1e-300);
  double mu = 1e-6 * k_over_m;

  // A relaxation whose positions are no longer finite (a NaN in the scene, or a step its
  // estimate got wrong) balances nothing: the scene as it was is returned instead.
  State unbalanced = rest;
  RelaxStep step = relax_step(model, rest);

  // Where a factorisation costs more than kNewtonWork (a cloth from 26 x 26 up; 6 ms here),
  // relaxation alone, until the largest force is kLoadTolerance of the load: the heaviest held
  // particle's weight (the spring force at 1 % strain, if that is less).
  // Against the load because the limits' error follows the tension's, and a tension is the
  // weight it holds up: a fraction of a particle's weight left over at each particle is about
  // that fraction of the tension. Against the springs' force, a fine rope's weights (1/16 of the
  // 1e-3 of it that once counted as balanced, on a 7000-node rope) passed before the rope had
  // moved, and its explicit Euler limit was 18 % above the hanging rope's. Measured on cloths of
  // 37 x 37 to 80 x 80 and 128 x 128 against Newton's balance: explicit and modified Euler's
  // limits within 8.3e-4 (they follow the sideways stiffness the tension gives, which no damping
  // matches; 4.3e-5 on the 128 x 128 cloth), the other methods' within 1.5e-5. At 1e-2 within
  // 3.4e-4, for 28 % more passes on the 64 x 64 cloth (12,400 against 9,700) and 73 % more on
  // the 128 x 128 (32,400 against 18,700). Past kRelaxedBudget passes it stops where it is.
  constexpr double kNewtonWork = 2e7, kLoadTolerance = 4e-2;
  constexpr int kRelaxation = 20000, kRelaxedBudget = 60000;
  if (predicted_factorisation_work(model, balance) > kNewtonWork) {
    // With no weight to hold (nothing pinned, or no gravity) the tensions are whatever pins
    // stretch the springs to, perhaps none: to a spring's force at 1e-7 strain, a hundred times
    // tighter than the relaxation before Newton (1e-5).
    const double load =
        weight > 0.0 ? kLoadTolerance * std::min(weight, strain_force) : 1e-5 * strain_force;
    relax(model, balance, rest, step, load, kRelaxedBudget);
    return rest.x.allFinite() ? rest : unbalanced;
  }
  // Else relaxation for the large motions, cheaply, and Newton for the last digits.
  relax(model, balance, rest, step, 1e-3 * force_scale, kRelaxation);
  if (!rest.x.allFinite()) return unbalanced;

  newton(balance, rest, mu, mu_floor, force_scale, tolerance, size);
  return rest;
}

// The held parts' potential is least at their balance (for the motions about it the audit
// weighs); a part held by nothing keeps its springs' potential >= 0, and its weight is bounded by
// the lowest floor facing up against gravity (a particle stays on its positive side, its centre a
// radius above). With no such floor it can fall forever, and a field's potential has no least
// value the audit could use: no bound.
double lowest_energy(const Model& model, const State& rest) {
  constexpr double kMinusInf = -std::numeric_limits<double>::infinity();
  if (!model.attractors.empty()) return kMinusInf;
  const Balance balance(model);
  const double g = model.gravity.norm();
  double floor = std::numeric_limits<double>::infinity();  // height against gravity
  if (g > 0.0) {
    const Vec3 up = -model.gravity / g;
    for (const PlaneCollider& p : model.planes)
      if (p.normal.dot(up) >= 1.0 - 1e-9)
        floor = std::min(floor, p.point.dot(up) + model.particle_radius);
  }
  std::vector<char> held(model.particle_count(), 0);
  for (int i = 0; i < model.particle_count(); ++i) held[i] = model.pinned(i) || balance.weighed[i];
  double e = 0.0;
  for (int s = 0; s < model.spring_count(); ++s) {
    const int a = model.spring_a[s], b = model.spring_b[s];
    if (held[a] && held[b])
      e += spring_energy(rest.x.row(a).transpose(), rest.x.row(b).transpose(), model.ks(s),
                         model.rest_length[s]);
  }
  for (int i = 0; i < model.particle_count(); ++i) {
    if (model.pinned(i) || !(g > 0.0)) continue;
    if (held[i])
      e -= model.mass[i] * model.gravity.dot(rest.x.row(i).transpose());
    else if (std::isfinite(floor))
      e += model.mass[i] * g * floor;
    else
      return kMinusInf;
  }
  return e;
}

}  // namespace springlab
