#include "springlab/stability.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "springlab/spring_kernel.hpp"

namespace springlab {

namespace {

// y = K u with K = -df/dx assembled from the definite spring Jacobians; pinned particles are
// held (their rows and columns dropped).
void stiffness_product(const Model& model, const State& state, const Points& u, Points& y) {
  y.setZero(u.rows(), 3);
  for (int s = 0; s < model.spring_count(); ++s) {
    const int a = model.spring_a[s], b = model.spring_b[s];
    const Vec3 xa = state.x.row(a).transpose(), xb = state.x.row(b).transpose();
    const Eigen::Matrix3d J =
        spring_jacobian(xa, xb, Vec3::Zero(), Vec3::Zero(), model.ks(s), 0.0, model.rest_length[s], true)
            .dfdx;
    const Vec3 du = (u.row(a) - u.row(b)).transpose();
    const Vec3 Ju = J * du;
    y.row(a) += Ju.transpose();
    y.row(b) -= Ju.transpose();
  }
  for (int i = 0; i < model.particle_count(); ++i)
    if (model.pinned(i)) y.row(i).setZero();
}

// u^T C u with C = -df/dv (spring damping along each spring, and drag).
double damping_form(const Model& model, const State& state, const Points& u) {
  double sum = 0.0;
  for (int s = 0; s < model.spring_count(); ++s) {
    const int a = model.spring_a[s], b = model.spring_b[s];
    const Vec3 d = (state.x.row(b) - state.x.row(a)).transpose();
    const double l = d.norm();
    if (coincident(l, model.rest_length[s])) continue;
    const double along = (u.row(b) - u.row(a)).dot(d.transpose()) / l;
    sum += model.kd(s) * along * along;
  }
  for (int i = 0; i < model.particle_count(); ++i)
    if (!model.pinned(i)) sum += model.drag * u.row(i).squaredNorm();
  return sum;
}

// The oscillator: an anchor pinned at the origin, a unit mass at distance 1 along x, a spring of
// rest length 1, k_s = w^2, k_d = c. Motion along x is exactly linear.
Model oscillator(double w, double c, double verlet_damping) {
  Model m;
  add_particle(m, 1.0, true);
  add_particle(m, 1.0, false);
  add_spring(m, 0, 1, 1.0, add_material(m, {w * w, c}));
  m.verlet_damping = verlet_damping;
  finalize(m);
  return m;
}

}  // namespace

StabilityEstimate estimate_stability(const Model& model, const State& state) {
  StabilityEstimate e;
  const int n = model.particle_count();

  // Gershgorin on M^-1 K: row i sums to at most (2 / m_i) sum of k_s at i.
  std::vector<double> ks_sum(n, 0.0);
  for (int s = 0; s < model.spring_count(); ++s) {
    ks_sum[model.spring_a[s]] += model.ks(s);
    ks_sum[model.spring_b[s]] += model.ks(s);
  }
  double bound = 0.0;
  for (int i = 0; i < n; ++i)
    if (!model.pinned(i)) bound = std::max(bound, 2.0 * ks_sum[i] * model.inv_mass[i]);
  e.w_bound = std::sqrt(bound);
  if (bound == 0.0) return e;

  // Power iteration on B = M^-1/2 K M^-1/2 from a fixed pseudo-random start (deterministic).
  Points q(n, 3), u(n, 3), y(n, 3);
  std::uint64_t seed = 0x9E3779B97F4A7C15ull;
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      q(i, c) = model.pinned(i) ? 0.0 : static_cast<double>(seed >> 11) / 9007199254740992.0 - 0.5;
    }
  q /= q.norm();
  Eigen::VectorXd root_inv_mass(n);
  for (int i = 0; i < n; ++i) root_inv_mass[i] = std::sqrt(model.inv_mass[i]);
  double lambda = 0.0;
  constexpr int kMaxIterations = 2000;
  for (int k = 0; k < kMaxIterations; ++k) {
    u = q.array().colwise() * root_inv_mass.array();
    stiffness_product(model, state, u, y);
    y = y.array().colwise() * root_inv_mass.array();
    const double next = q.cwiseProduct(y).sum();  // Rayleigh quotient, |q| = 1
    const double norm = y.norm();
    e.iterations = k + 1;
    if (norm == 0.0) break;
    q = y / norm;
    const bool converged = std::abs(next - lambda) <= 1e-9 * next;
    lambda = next;
    if (converged) break;
  }
  e.w_max = std::sqrt(std::max(lambda, 0.0));

  // The damping rate of that mode, with u = M^-1/2 q its physical shape (q^T q = u^T M u = 1).
  u = q.array().colwise() * root_inv_mass.array();
  e.damping = damping_form(model, state, u) / q.squaredNorm();
  return e;
}

double amplification(Method method, double w, double c, double h, double verlet_damping) {
  const Model model = oscillator(w, c, verlet_damping);
  const StepSettings settings;
  // Motion along the spring is exactly linear whatever the offset, so the offset only has to be
  // large enough for (x - 1) / delta to keep its digits (1e-13 relative), and small enough that
  // no stage crosses the anchor near the limits (amplitudes grow like (h w)^4 per step).
  const double delta = 1e-3;
  double M[2][2];
  for (int column = 0; column < 2; ++column) {
    State in, out;
    in.resize(2);
    in.x.setZero();
    in.v.setZero();
    in.x(1, 0) = 1.0 + (column == 0 ? delta : 0.0);
    in.v(1, 0) = column == 1 ? delta : 0.0;
    out.resize(2);
    Workspace ws;
    step(method, model, in, out, h, settings, ws);
    M[0][column] = (out.x(1, 0) - 1.0) / delta;
    M[1][column] = out.v(1, 0) / delta;
  }
  const double trace = M[0][0] + M[1][1];
  const double det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
  const double disc = 0.25 * trace * trace - det;
  if (disc < 0.0) return std::sqrt(det);  // complex pair, |lambda|^2 = det
  const double root = std::sqrt(disc);
  return std::max(std::abs(0.5 * trace + root), std::abs(0.5 * trace - root));
}

double stable_step(Method method, double w, double c, double verlet_damping) {
  if (method_info(method).adaptive) return std::numeric_limits<double>::quiet_NaN();
  if (!(w > 0.0)) return std::numeric_limits<double>::infinity();
  const auto stable = [&](double hw) {
    const double rho = amplification(method, w, c, hw / w, verlet_damping);
    return std::isfinite(rho) && rho <= 1.0 + 1e-9;
  };
  // Growth below 1e-9 a step cannot be told from rounding, so the scan starts at h w = 0.01, where
  // the slowest-growing unstable method (midpoint, rho^2 = 1 + (h w)^4 / 4) already shows.
  constexpr double kFirst = 1e-2, kGrowth = 1.02, kScanEnd = 20.0;
  if (!stable(kFirst)) return 0.0;
  double lo = kFirst, hi = 0.0;
  for (double hw = kFirst * kGrowth; hw <= kScanEnd; hw *= kGrowth) {
    if (!stable(hw)) {
      hi = hw;
      break;
    }
    lo = hw;
  }
  if (hi == 0.0) {
    // Stable over the whole scan: either at any step (implicit) or the limit is further out.
    for (double hw = kScanEnd * 10.0; hw <= 1e8; hw *= 10.0) {
      if (!stable(hw)) {
        hi = hw;
        break;
      }
      lo = hw;
    }
    if (hi == 0.0) return std::numeric_limits<double>::infinity();
  }
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (stable(mid) ? lo : hi) = mid;
  }
  return lo / w;
}

}  // namespace springlab
