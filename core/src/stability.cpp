#include "springlab/stability.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "springlab/energy.hpp"
#include "springlab/spring_kernel.hpp"

namespace springlab {

namespace {

// y = K u with K = -df/dx from the definite spring Jacobians (spring_kernel.hpp), pinned
// particles held (their rows and columns dropped). Each spring's block in closed form,
//   K_s du = k_s ((u . du) u + beta (du - (u . du) u)),   beta = max(0, 1 - L / l),
// span by span over the coordinate arrays: Lanczos calls this hundreds of times.
void stiffness_product(const Model& model, const State& state, const Points& u, Points& y) {
  constexpr int kChunk = 256;
  y.setZero(u.rows(), 3);
  const double* X[3] = {state.x.col(0).data(), state.x.col(1).data(), state.x.col(2).data()};
  const double* U[3] = {u.col(0).data(), u.col(1).data(), u.col(2).data()};
  double* Y[3] = {y.col(0).data(), y.col(1).data(), y.col(2).data()};
  alignas(64) double out[3][kChunk];
  for (const SpringSpan& span : model.spans) {
    const double ks = model.materials[span.material].ks, rest = span.rest;
    const double coincident = kCoincident * std::max(rest, 1.0);
    const double at_zero = rest == 0.0 ? ks : 0.0;  // coincident ends: only L = 0 has k_s I
    for (int lo = 0; lo < span.count; lo += kChunk) {
      const int count = std::min(kChunk, span.count - lo);
      const int a = span.a0 + lo, b = span.b0 + lo;
      // Each spring's block times du = u_a - u_b, vectorised (no branches: both cases computed).
      for (int k = 0; k < count; ++k) {
        const double dx = X[0][b + k] - X[0][a + k], dy = X[1][b + k] - X[1][a + k], dz = X[2][b + k] - X[2][a + k];
        const double ux = U[0][a + k] - U[0][b + k], uy = U[1][a + k] - U[1][b + k], uz = U[2][a + k] - U[2][b + k];
        const double l2 = dx * dx + dy * dy + dz * dz;
        const double l = std::sqrt(l2);
        const bool apart = l > coincident;
        const double inv_l2 = apart ? 1.0 / l2 : 0.0;
        const double beta = apart ? std::max(0.0, 1.0 - rest / l) : 0.0;
        // k_s ((d . du) d / l^2 (1 - beta) + beta du), or k_s du at a zero-length spring's zero.
        const double along = ks * (1.0 - beta) * (dx * ux + dy * uy + dz * uz) * inv_l2;
        const double across = apart ? ks * beta : at_zero;
        out[0][k] = along * dx + across * ux;
        out[1][k] = along * dy + across * uy;
        out[2][k] = along * dz + across * uz;
      }
      for (int c = 0; c < 3; ++c) {
        for (int k = 0; k < count; ++k) Y[c][a + k] += out[c][k];
        for (int k = 0; k < count; ++k) Y[c][b + k] -= out[c][k];
      }
    }
  }
  for (int i = 0; i < model.particle_count(); ++i)
    if (model.pinned(i)) y.row(i).setZero();
}

// u^T C u with C = -df/dv: its spring damping part (along each spring) and its drag part.
struct DampingForm {
  double springs = 0.0, drag = 0.0;
};
DampingForm damping_form(const Model& model, const State& state, const Points& u) {
  DampingForm form;
  double& sum = form.springs;
  for (int s = 0; s < model.spring_count(); ++s) {
    const int a = model.spring_a[s], b = model.spring_b[s];
    const Vec3 d = (state.x.row(b) - state.x.row(a)).transpose();
    const double l = d.norm();
    if (coincident(l, model.rest_length[s])) continue;
    const double along = (u.row(b) - u.row(a)).dot(d.transpose()) / l;
    sum += model.kd(s) * along * along;
  }
  for (int i = 0; i < model.particle_count(); ++i)
    if (!model.pinned(i)) form.drag += model.drag * u.row(i).squaredNorm();
  return form;
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

// Gershgorin's radius of row i of the k x k symmetric tridiagonal T: |beta_(i-1)| + |beta_i|.
double radius(const std::vector<double>& beta, int k, int i) {
  return (i > 0 ? std::abs(beta[i - 1]) : 0.0) + (i + 1 < k ? std::abs(beta[i]) : 0.0);
}

// The largest eigenvalue of the k x k symmetric tridiagonal T (alpha on the diagonal, beta beside
// it), at least `floor`, by bisection on Sturm counts: the pivots of T - x I = L D L^T,
//   d_0 = alpha_0 - x,  d_i = alpha_i - x - beta_{i-1}^2 / d_{i-1},
// have as many negatives as T has eigenvalues below x: all of them (T - x I negative definite)
// exactly when x is above lambda_max. O(k) a probe, full precision in at most ~64 probes; a QR
// sweep of T (Eigen's tridiagonal solver) costs O(k^2) each time Lanczos asks: 1.3 s over a
// 1000-node rope's 1000 steps.
double largest_eigenvalue(const std::vector<double>& alpha, const std::vector<double>& beta, int k, double floor) {
  double lo = floor, hi = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < k; ++i) {
    lo = std::max(lo, alpha[i]);  // lambda_max >= any diagonal entry
    hi = std::max(hi, alpha[i] + radius(beta, k, i));
  }
  const auto all_below = [&](double x) {
    double d = alpha[0] - x;
    for (int i = 1; i < k && d < 0.0; ++i) d = alpha[i] - x - beta[i - 1] * beta[i - 1] / d;
    return d < 0.0;
  };
  while (hi > lo) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;  // adjacent doubles
    (all_below(mid) ? hi : lo) = mid;
  }
  return hi;
}

// The eigenvector of the k x k symmetric tridiagonal T (alpha on the diagonal, beta beside it)
// for its largest eigenvalue lambda, by inverse iteration: s <- (sigma I - T)^-1 s with sigma just
// above lambda. sigma I - T is then positive definite, so its LDL^T factors (O(k), no pivoting)
// are stable, and each solve shrinks the other components by delta / (lambda - lambda_j + delta).
// A full eigendecomposition of T costs O(k^3): 1.5 s at k = 1000 (a 1000-node rope).
Eigen::VectorXd top_eigenvector(const std::vector<double>& alpha, const std::vector<double>& beta, int k,
                                double lambda) {
  double scale = 0.0;  // |T| (a bound)
  for (int i = 0; i < k; ++i)
    scale = std::max(scale, std::abs(alpha[i]) + radius(beta, k, i));
  // T = 0 (no stiffness anywhere, e.g. coincident ends): every vector is an eigenvector.
  if (!(scale > 0.0)) return Eigen::VectorXd::Unit(k, 0);
  const double sigma = lambda + 1e-10 * scale;
  // sigma I - T = L D L^T, L unit lower bidiagonal with l[i] below the diagonal in row i.
  std::vector<double> d(k), l(k, 0.0);
  d[0] = sigma - alpha[0];
  for (int i = 1; i < k; ++i) {
    l[i] = -beta[i - 1] / d[i - 1];
    d[i] = (sigma - alpha[i]) + l[i] * beta[i - 1];
  }
  // A start with every component (alternating signs favour the top of a chain's spectrum).
  Eigen::VectorXd s(k);
  for (int i = 0; i < k; ++i) s[i] = (i % 2 == 0 ? 1.0 : -1.0) * (1.0 + 0.5 * std::sin(i + 1.0));
  for (int iteration = 0; iteration < 4; ++iteration) {
    for (int i = 1; i < k; ++i) s[i] -= l[i] * s[i - 1];          // L y = s
    for (int i = 0; i < k; ++i) s[i] /= d[i];                      // D z = y
    for (int i = k - 2; i >= 0; --i) s[i] -= l[i + 1] * s[i + 1];  // L^T s = z
    s /= s.cwiseAbs().maxCoeff();  // first to about 1: |s|^2 of a huge s would overflow
    s /= s.norm();
  }
  return s;
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

  // Lanczos on B = M^-1/2 K M^-1/2 (symmetric) from a fixed pseudo-random start (deterministic):
  // after k steps, the largest eigenvalue of the k x k tridiagonal T (alpha on the diagonal, beta
  // beside it) is a lower bound on lambda_max that converges in far fewer products than a power
  // iteration's Rayleigh quotient (tens to hundreds instead of thousands on a cloth, whose top
  // modes crowd together). No reorthogonalisation: lost orthogonality only repeats converged
  // eigenvalues, and the largest is still right.
  Points q(n, 3), q_prev(n, 3), u(n, 3), y(n, 3);
  const auto start = [&] {
    std::uint64_t seed = 0x9E3779B97F4A7C15ull;
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        q(i, c) = model.pinned(i) ? 0.0 : static_cast<double>(seed >> 11) / 9007199254740992.0 - 0.5;
      }
    q /= q.norm();
    q_prev.setZero();
  };
  Eigen::VectorXd root_inv_mass(n);
  for (int i = 0; i < n; ++i) root_inv_mass[i] = std::sqrt(model.inv_mass[i]);
  // One Lanczos step: y = B q - alpha q - beta_prev q_prev, then q_prev = q, q = y / |y|.
  const auto lanczos_step = [&](double beta_prev, double& alpha, double& beta) {
    u = q.array().colwise() * root_inv_mass.array();
    stiffness_product(model, state, u, y);
    y = y.array().colwise() * root_inv_mass.array();
    alpha = q.cwiseProduct(y).sum();
    y -= alpha * q + beta_prev * q_prev;
    beta = y.norm();
    std::swap(q_prev, q);
    if (beta > 0.0) q = y / beta;
  };
  // At most 1000 steps, and about 1e8 spring products (the mode's shape takes as many again): a
  // few seconds for a 512 x 512 cloth, which gets 63.
  const int max_steps =
      static_cast<int>(std::clamp<long>(100'000'000L / std::max(1, model.spring_count()), 50, 1000));
  std::vector<double> alpha, beta;
  double lambda = 0.0;
  start();
  for (int k = 0; k < max_steps; ++k) {
    double a = 0.0, b = 0.0;
    lanczos_step(beta.empty() ? 0.0 : beta.back(), a, b);
    alpha.push_back(a);
    beta.push_back(b);
    e.iterations = k + 1;
    // T's largest eigenvalue costs up to 64 passes over T: looked at every step at first, then
    // every eighth.
    if (k >= 16 && k % 8 != 7 && b > 0.0 && k + 1 < max_steps) continue;
    // T_k's largest eigenvalue is never below T_(k-1)'s (they interlace).
    const double next = largest_eigenvalue(alpha, beta, k + 1, lambda);
    // beta = 0: the steps so far span an invariant subspace, and T's eigenvalues are exact.
    e.converged = b <= 1e-14 * std::abs(next) || std::abs(next - lambda) <= 1e-12 * next;
    lambda = next;
    if (e.converged) break;
  }
  e.w_max = std::sqrt(std::max(lambda, 0.0));

  // The mode's shape, sum_j s_j q_j with s the top eigenvector of T: the same steps again (the
  // Lanczos vectors are not kept: a large scene would need hundreds of copies of its state).
  const int steps = e.iterations;
  const Eigen::VectorXd s = top_eigenvector(alpha, beta, steps, lambda);
  Points mode = Points::Zero(n, 3);
  start();
  for (int k = 0; k < steps; ++k) {
    mode += s[k] * q;
    if (k + 1 < steps) {
      double a = 0.0, b = 0.0;
      lanczos_step(k == 0 ? 0.0 : beta[k - 1], a, b);
    }
  }
  q = mode / mode.norm();

  // The damping rate of that mode, with u = M^-1/2 q its physical shape (q^T q = u^T M u = 1).
  u = q.array().colwise() * root_inv_mass.array();
  const DampingForm form = damping_form(model, state, u);
  e.spring_damping = form.springs / q.squaredNorm();
  e.drag_damping = form.drag / q.squaredNorm();
  e.damping = e.spring_damping + e.drag_damping;
  return e;
}

void StabilityEstimate::scale_stiffness(double factor) {
  w_max *= std::sqrt(factor);
  w_bound *= std::sqrt(factor);
}

void StabilityEstimate::scale_spring_damping(double factor) {
  spring_damping *= factor;
  damping = spring_damping + drag_damping;
}

void StabilityEstimate::scale_drag(double factor) {
  drag_damping *= factor;
  damping = spring_damping + drag_damping;
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
  // "Unstable at any step" means from h w = 0.05 up: there the slowest-growing unstable method
  // (midpoint, rho^2 = 1 + (h w)^4 / 4) already grows by 8e-7 a step, well above rounding.
  constexpr double kFirst = kNeverStableFrom, kGrowth = 1.02, kScanEnd = 20.0;
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

namespace springlab {

namespace {

// The free coordinates of a state as one vector (x then v of each free particle), and back.
struct FreeCoordinates {
  std::vector<int> particles;
  int size() const { return 6 * static_cast<int>(particles.size()); }
  void get(const State& s, Eigen::VectorXd& y) const {
    y.resize(size());
    for (std::size_t k = 0; k < particles.size(); ++k)
      for (int c = 0; c < 3; ++c) {
        y[6 * k + c] = s.x(particles[k], c);
        y[6 * k + 3 + c] = s.v(particles[k], c);
      }
  }
  void add(State& s, const Eigen::VectorXd& dy, double scale) const {
    for (std::size_t k = 0; k < particles.size(); ++k)
      for (int c = 0; c < 3; ++c) {
        s.x(particles[k], c) += scale * dy[6 * k + c];
        s.v(particles[k], c) += scale * dy[6 * k + 3 + c];
      }
  }
};

// J v by central differences of the step, with a perturbation small against the state's size.
class StepJacobian {
 public:
  StepJacobian(Method method, const Model& model, const State& state, double h, const StepSettings& settings)
      : method_(method), model_(model), state_(state), h_(h), settings_(settings) {
    for (int i = 0; i < model.particle_count(); ++i)
      if (!model.pinned(i)) free_.particles.push_back(i);
    const double size = std::max({1.0, state.x.cwiseAbs().maxCoeff(), state.v.cwiseAbs().maxCoeff()});
    epsilon_ = 1e-6 * size;
  }
  int dofs() const { return free_.size(); }

  void apply(const Eigen::VectorXd& v, Eigen::VectorXd& out) {
    State plus = state_, minus = state_;
    free_.add(plus, v, epsilon_);
    free_.add(minus, v, -epsilon_);
    Eigen::VectorXd yp, ym;
    step_of(plus, yp);
    step_of(minus, ym);
    out = (yp - ym) / (2.0 * epsilon_);
  }

 private:
  void step_of(const State& in, Eigen::VectorXd& y) {
    State out = in;
    Workspace ws;  // fresh: no history (Verlet starts from (x, v))
    step(method_, model_, in, out, h_, settings_, ws);
    free_.get(out, y);
  }

  Method method_;
  const Model& model_;
  const State& state_;
  double h_;
  StepSettings settings_;
  FreeCoordinates free_;
  double epsilon_ = 1e-6;
};

}  // namespace

// The largest eigenvalue modulus, leaving out the neutral cluster at 1: at rest a scene has
// directions of zero stiffness (a spring turning about its anchor, a slack chain moving
// sideways), each a Jordan block at exactly 1 whose computed eigenvalues scatter by the square
// root of the rounding error. An oscillating mode that close to 1 has h w below 1e-4 and never
// sets a limit.
double outermost(const Eigen::VectorXcd& eigenvalues) {
  double rho = 0.0;
  for (const auto& lambda : eigenvalues)
    if (std::abs(lambda - 1.0) >= 1e-4) rho = std::max(rho, std::abs(lambda));
  return rho;
}

double measured_amplification(Method method, const Model& model, const State& state, double h,
                              const StepSettings& settings) {
  StepJacobian J(method, model, state, h, settings);
  const int n = J.dofs();
  if (n == 0) return 0.0;
  Eigen::VectorXd column;
  if (n <= kDenseDofs) {
    Eigen::MatrixXd A(n, n);
    for (int k = 0; k < n; ++k) {
      J.apply(Eigen::VectorXd::Unit(n, k), column);
      A.col(k) = column;
    }
    if (!A.allFinite()) return std::numeric_limits<double>::infinity();
    return outermost(Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues());
  }
  return std::numeric_limits<double>::quiet_NaN();  // too large for the whole Jacobian
}

// A large scene: run the method from rest with a tiny random push (linear regime), and call it
// unstable when the energy grows a thousandfold within kGrowthSteps steps. Neutral directions
// (slack springs, rigid motions) keep their energy; an unstable stiff mode multiplies it by at
// least 1.3 a step one per cent past the limits of symplectic Euler, Verlet and RK4.
bool grows(Method method, const Model& model, const State& rest, double h, const StepSettings& settings) {
  // An implicit step costs a solve, and ill-conditioned ones at large h: a hundred show the
  // same growth there would be.
  const int kGrowthSteps = method_info(method).implicit ? 100 : 1000;
  constexpr double kGrowth = 1e3;
  State a = rest, b = rest;
  std::uint64_t seed = 0x2545F4914F6CDD1Dull;
  for (int i = 0; i < model.particle_count(); ++i)
    for (int c = 0; c < 3; ++c) {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      a.v(i, c) = model.pinned(i) ? 0.0 : static_cast<double>(seed >> 11) / 9007199254740992.0 - 0.5;
    }
  const double scale = energy_scale(model, rest);
  a.v *= std::sqrt(1e-12 * scale / std::max(1e-300, kinetic_energy(model, a)));
  const double start = energy(model, a).total();
  Workspace ws;
  for (int k = 0; k < kGrowthSteps; ++k) {
    step(method, model, a, b, h, settings, ws);
    std::swap(a, b);
    const double e = energy(model, a).total();
    if (!std::isfinite(e) || e > kGrowth * start) return true;
  }
  return false;
}

EquilibriumScene at_rest(const Model& model, const State& state) {
  EquilibriumScene rest{model, state};
  rest.model.planes.clear();
  rest.model.spheres.clear();
  rest.model.gravity.setZero();
  rest.state.v.setZero();
  // Already at rest (generated scenes start so): nothing to relax.
  double strain = 0.0;
  for (int k = 0; k < model.spring_count(); ++k) {
    const double l = (state.x.row(model.spring_b[k]) - state.x.row(model.spring_a[k])).norm();
    strain = std::max(strain, std::abs(l - model.rest_length[k]) / std::max(model.rest_length[k], 1e-300));
  }
  if (strain < 1e-12) return rest;
  const StabilityEstimate e = estimate_stability(rest.model, rest.state);
  if (!(e.w_max > 0.0)) return rest;
  // Implicit Euler with h w_max = 1e4 is, to M / h^2, Newton's method on the springs' static
  // balance: it takes every spring back to its rest length in a few dozen steps.
  State a = rest.state, b = rest.state;
  Workspace ws;
  StepSettings s;
  s.solver_tolerance = 1e-12;
  for (int k = 0; k < 60; ++k) {
    a.v.setZero();
    step(Method::ImplicitEuler, rest.model, a, b, 1e4 / e.w_max, s, ws);
    std::swap(a, b);
  }
  rest.state.x = a.x;
  rest.state.v.setZero();
  return rest;
}

double measured_stable_step(Method method, const Model& model, const State& state, double w_max,
                            double guess, const StepSettings& settings) {
  return measured_stable_step(method, at_rest(model, state), w_max, guess, settings);
}

double measured_stable_step(Method method, const EquilibriumScene& rest, double w_max, double guess,
                            const StepSettings& settings) {
  if (method_info(method).adaptive) return std::numeric_limits<double>::quiet_NaN();
  if (!(w_max > 0.0)) return std::numeric_limits<double>::infinity();
  int free = 0;
  for (int i = 0; i < rest.model.particle_count(); ++i) free += !rest.model.pinned(i);
  const bool dense = 6 * free <= kDenseDofs;
  const auto stable = [&](double h) {
    if (!dense) return !grows(method, rest.model, rest.state, h, settings);
    const double rho = measured_amplification(method, rest.model, rest.state, h, settings);
    return std::isfinite(rho) && rho <= 1.0 + 1e-9;
  };
  // A thousandfold growth in 1000 steps needs about 0.35% a step: the run test cannot see the
  // slowest instabilities (midpoint's (h w)^4 / 8) below h w = 0.3, where it decides "never",
  // unless the theory expects a limit below that (damping: explicit Euler's c / w^2), which it
  // then checks from a quarter of it up.
  double floor = kNeverStableFrom / w_max;
  if (!dense) {
    floor = kNeverStableFromByRuns / w_max;
    if (std::isfinite(guess) && guess > 0.0) floor = std::min(floor, 0.25 * guess);
  }
  // Runs cost steps, and an always-stable method would be tried at every size on the way to
  // the ceiling: they go up tenfold at a time, and stop at 100 / w_max (where implicit Euler's
  // solves already face a condition number of 1e4).
  const double ceiling = (dense ? 1e6 : 1e2) / w_max, growth = dense ? 1.5 : 10.0;
  double h = std::isfinite(guess) && guess > floor ? guess : 1.0 / w_max;
  if (!stable(floor)) return 0.0;
  double lo, hi;
  if (stable(h)) {
    lo = h;
    for (hi = growth * h; stable(hi); hi *= growth) {
      lo = hi;
      if (hi > ceiling) return std::numeric_limits<double>::infinity();
    }
  } else {
    hi = h;
    for (lo = h / 1.5; !stable(lo); lo /= 1.5) hi = lo;
  }
  while (hi - lo > (dense ? 1e-4 : 3e-3) * lo) {
    const double mid = 0.5 * (lo + hi);
    (stable(mid) ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace springlab
