// The stability of each method on one damped mode, x'' = -kappa x - gamma x' (kappa = w^2,
// gamma = c): the largest h such that every step size up to it keeps the spectral radius of the
// method's step at most 1. Closed forms from each method's characteristic polynomial, checked
// by Jury's conditions (a monic quadratic mu^2 + a1 mu + a0 has both roots in the unit disc
// exactly when |a0| <= 1 and |a1| <= 1 + a0); the Runge-Kutta methods by the first positive root of
// |R(h lambda)|^2 - 1, R = P / Q their tableau's stability function (tableau.hpp).
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include "springlab/stability.hpp"
#include "stability/mode_limits.hpp"
#include "stability/sqrt_of_real.hpp"

namespace springlab {

namespace {

constexpr double kNoLimit = std::numeric_limits<double>::infinity();  // every step is stable
using Complex = std::complex<double>;

// |R(h lambda)|^2 - 1 has the sign of |P|^2 - |Q|^2 = sum_{m >= 1} c_m h^m for R = P / Q (Q = 1
// for an explicit tableau), P = sum_j p_j z^j, Q = sum_j q_j z^j, with
//   c_m = sum_{j + k = m} (p_j p_k - q_j q_k) Re(lambda^j conj(lambda)^k).
// Divided by h it starts at c_1 = 2 (p_1 - q_1) Re(lambda), so its sign near h = 0 is not lost
// to rounding.
struct GrowthPolynomial {
  std::vector<double> c;  // c[1] .. c[degree]
  int degree = 0;
  GrowthPolynomial(const std::vector<double>& p, const std::vector<double>& q, Complex lambda) {
    const int n = static_cast<int>(std::max(p.size(), q.size())) - 1;
    degree = 2 * n;
    c.assign(static_cast<std::size_t>(degree + 1), 0.0);
    std::vector<Complex> powers{1.0};
    for (int j = 1; j <= n; ++j) powers.push_back(powers.back() * lambda);
    const auto at = [](const std::vector<double>& v, int j) {
      return j < static_cast<int>(v.size()) ? v[static_cast<std::size_t>(j)] : 0.0;
    };
    // A coefficient that is a sum of terms cancelling to rounding (on the imaginary axis RK4's
    // first five do: R is an approximation of e^z, |e^(iy)| = 1) is exactly zero.
    std::vector<double> gross(c.size(), 0.0);
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k)
        if (j + k > 0) {
          const double re = (powers[j] * std::conj(powers[k])).real();
          const double plus = at(p, j) * at(p, k) * re, minus = at(q, j) * at(q, k) * re;
          c[j + k] += plus - minus;
          gross[j + k] += std::abs(plus) + std::abs(minus);
        }
    for (int m = 1; m <= degree; ++m)
      if (std::abs(c[m]) <= 1e-13 * gross[m]) c[m] = 0.0;
  }
  // (|R|^2 - 1) / h, and the sum of its terms' magnitudes (the rounding yardstick).
  double over_h(double h, double* magnitude) const {
    double value = 0.0, size = 0.0, power = 1.0;
    for (int m = 1; m <= degree; ++m) {
      value += c[m] * power;
      size += std::abs(c[m] * power);
      power *= h;
    }
    *magnitude = size;
    return value;
  }
  // Above every positive root of (|R|^2 - 1) / h (Cauchy's bound), with some room for rounding.
  double root_bound() const {
    int top = degree;
    while (top > 1 && c[top] == 0.0) --top;
    if (top <= 1) return 0.0;  // c_1 h^0 alone: the sign near 0 holds everywhere
    double largest = 0.0;
    for (int m = 1; m < top; ++m) largest = std::max(largest, std::abs(c[m] / c[top]));
    return 1.05 * (1.0 + largest);
  }
  // True: the sum decides the sign; false: it is within its own rounding of 0.
  bool decides(double h, bool* grows) const {
    double size = 0.0;
    const double value = over_h(h, &size);
    *grows = value > 0.0;
    return std::abs(value) > 1e-13 * size;
  }
};

// Whether |R(h lambda)| > 1. The growth polynomial's sum decides near 0, where |R|^2 - 1 is
// small and only its series keeps the sign; far out it cancels to rounding (its terms' sum is
// about |R(|z|)|^2: e^28 for Ketcheson's SSPRK(10,4) at z = -13.9, where it put the limit 2e-6
// past |R| = 1), and R is computed as the method computes it, stage after stage (tableau.hpp).
bool grows(const GrowthPolynomial& poly, const Tableau& tableau, Complex lambda, double h) {
  bool grows = false;
  if (poly.decides(h, &grows)) return grows;
  return std::abs(tableau.stability_function(h * lambda)) > 1.0 + 1e-13;
}

// The first h > 0 at which |R(h lambda)| exceeds 1 (infinity if none). The search ends at
// Cauchy's bound on the growth polynomial's roots, 1 + max |c_m / c_top|, past which its sign
// is its top coefficient's: a long-interval method (a Chebyshev method's -2 s^2) is searched to
// its end, not to a fixed multiple of 1 / |lambda|.
double runge_kutta_exit(const Tableau& tableau, Complex lambda) {
  const std::vector<double>& gamma = tableau.numerator;
  const double size = std::abs(lambda);
  if (!(size > 0.0)) return kNoLimit;
  if (lambda.real() > 0.0) return 0.0;
  if (gamma.size() == 2 && tableau.denominator.size() == 1) {
    // R(z) = 1 + gamma_1 z: |1 + h gamma_1 lambda| <= 1 up to h = -2 Re(lambda) / (gamma_1
    // |lambda|^2).
    return lambda.real() >= 0.0 ? 0.0 : -2.0 * lambda.real() / (gamma[1] * std::norm(lambda));
  }
  const GrowthPolynomial poly(gamma, tableau.denominator, lambda);
  const auto grows_at = [&](double h) { return grows(poly, tableau, lambda, h); };
  double lo = 1e-12 / size;
  if (grows_at(lo)) return 0.0;
  double hi = 0.0;
  const double bound = poly.root_bound();
  for (double h = lo * 1.02; h <= bound; h *= 1.02) {
    if (grows_at(h)) {
      hi = h;
      break;
    }
    lo = h;
  }
  if (hi == 0.0) return kNoLimit;
  for (int k = 0; k < 80 && hi - lo > 1e-15 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (grows_at(mid) ? hi : lo) = mid;
  }
  return lo;
}

// The two roots of lambda^2 + gamma lambda + kappa = 0.
void mode_eigenvalues(double gamma, double kappa, Complex& first, Complex& second) {
  const Complex root = sqrt_of_real(0.25 * gamma * gamma - kappa);
  first = -0.5 * gamma + root;
  second = -0.5 * gamma - root;
}

}  // namespace

namespace modes {

double euler(double gamma, double kappa, const MethodParameters&) {
  // mu = 1 + h lambda: mu^2 - (2 - h gamma) mu + 1 - h gamma + h^2 kappa. Jury: a0 <= 1 is
  // h <= gamma / kappa; 1 - a1 + a0 >= 0 is h^2 kappa - 2 h gamma + 4 >= 0, which binds only
  // for an overdamped mode (real lambda): h <= 2 / |lambda|, the larger |lambda|.
  if (kappa == 0.0) return 2.0 / gamma;
  const double disc = gamma * gamma - 4.0 * kappa;
  if (disc < 0.0) return gamma / kappa;
  return 4.0 / (gamma + std::sqrt(disc));
}

double modified_euler(double gamma, double kappa, const MethodParameters&) {
  // With s = 1 - mu: s^2 - s (h gamma + h^2 kappa / 2) + h^2 kappa = 0 (v1 = v + h a,
  // x1 = x + h (v + v1) / 2). Jury: a0 <= 1 is h kappa / 2 <= gamma; 1 - a1 + a0 >= 0 is
  // h gamma <= 2.
  if (kappa == 0.0) return 2.0 / gamma;
  if (gamma == 0.0) return 0.0;
  return std::min(2.0 * gamma / kappa, 2.0 / gamma);
}

double symplectic_euler(double gamma, double kappa, const MethodParameters&) {
  // mu^2 - (2 - h gamma - h^2 kappa) mu + 1 - h gamma: a complex pair has |mu|^2 = 1 - h gamma
  // <= 1, so the roots leave the disc through -1, where 4 - 2 h gamma - h^2 kappa = 0.
  return 4.0 / (gamma + std::sqrt(gamma * gamma + 4.0 * kappa));
}

double verlet(double gamma, double kappa, const MethodParameters& parameters) {
  // Position Verlet as verlet.cpp runs it (velocities predicted for the damping), a cubic in
  // mu whose roots leave the disc through -1 (checked against the step in the tests), where
  //   h^2 kappa + (4 - d) h gamma - (4 - 2 d) = 0.
  const double d = parameters.verlet_damping;
  const double b = (4.0 - d) * gamma, c = 4.0 - 2.0 * d;
  return 2.0 * c / (b + std::sqrt(b * b + 4.0 * kappa * c));
}

}  // namespace modes

double mode_limit(Method method, double gamma, double kappa, const MethodParameters& parameters) {
  const MethodInfo& info = method_info(method);
  if (info.adaptive()) return std::numeric_limits<double>::quiet_NaN();
  gamma = std::max(gamma, 0.0);
  kappa = std::max(kappa, 0.0);
  if (gamma == 0.0 && kappa == 0.0) return kNoLimit;  // a free motion: nothing to oscillate
  if (info.mode_limit) return info.mode_limit(gamma, kappa, parameters);
  if (info.any_step()) return kNoLimit;
  Complex first, second;
  mode_eigenvalues(gamma, kappa, first, second);
  return std::min(runge_kutta_limit(method, first), runge_kutta_limit(method, second));
}

double runge_kutta_limit(Method method, std::complex<double> lambda) {
  const MethodInfo& info = method_info(method);
  if (info.any_step()) return kNoLimit;
  if (info.family != MethodFamily::RungeKutta) return std::numeric_limits<double>::quiet_NaN();
  return runge_kutta_exit(*info.tableau, lambda);
}

double stable_step(Method method, double w, double c, const MethodParameters& parameters) {
  return mode_limit(method, c, w * w, parameters);
}

}  // namespace springlab
