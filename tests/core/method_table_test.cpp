// The method table's contract, row by row: what each row says of itself holds, so that a new row
// (a method, a student's tableau) is checked where it is written. Each row is found by its name and
// its id; a Runge-Kutta row's tableau is explicit and its stability polynomial matches e^z to its
// order (gamma_j = 1 / j!, docs/numerics.md, "Stability functions and the method table"); an
// implicit row's R(z) is that close to e^z and A-stable; the undamped limit it states is where R
// first leaves the unit disc on the imaginary axis, and a closed form it gives agrees with R(z) on
// damped modes. (Order measured in runs: accuracy_test.cpp over the same rows; each limit against
// the method's own step: stability_test.cpp; bits for any thread count: determinism_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <set>
#include <string>

#include "springlab/stability.hpp"
#include "support.hpp"

namespace springlab {
namespace {

using Complex = std::complex<double>;

TEST(MethodTable, EveryRowIsFoundByItsNameAndItsId) {
  std::set<std::string> names;
  for (const MethodInfo& m : methods()) {
    SCOPED_TRACE(m.name);
    EXPECT_EQ(&method_info(m.id), &m);
    ASSERT_TRUE(find_method(m.name));
    EXPECT_EQ(*find_method(m.name), m.id);
    EXPECT_TRUE(names.insert(m.name).second) << "a second row named " << m.name;
    EXPECT_GE(m.order, 1);
    // A step of its own, or (a row made from a tableau) a step given its tableau.
    ASSERT_TRUE(m.step || (m.tableau_step && m.tableau));
    // What each family must carry.
    switch (m.family) {
      case MethodFamily::RungeKutta:
        ASSERT_NE(m.tableau, nullptr);
        // Built-in: explicit; made from a tableau: explicit or diagonally implicit.
        EXPECT_TRUE(m.tableau->is_explicit() || m.tableau_step);
        break;
      case MethodFamily::Implicit:
        ASSERT_NE(m.tableau, nullptr);
        EXPECT_FALSE(m.tableau->is_explicit());
        EXPECT_TRUE(std::isinf(m.undamped_limit));
        break;
      case MethodFamily::Partitioned:
        EXPECT_EQ(m.tableau, nullptr);
        EXPECT_NE(m.mode_limit, nullptr);
        break;
      case MethodFamily::Adaptive:
        EXPECT_TRUE(std::isnan(m.undamped_limit));
        EXPECT_FALSE(m.audited);
        break;
      case MethodFamily::Iterative:
        EXPECT_EQ(m.tableau, nullptr);
        EXPECT_TRUE(std::isinf(m.undamped_limit));
        EXPECT_FALSE(m.audited);
        break;
    }
  }
  EXPECT_FALSE(find_method("no-such-method"));
}

TEST(MethodTable, ARungeKuttaRowsStabilityFunctionIsEToItsOrder) {
  for (const MethodInfo& m : methods()) {
    if (m.family != MethodFamily::RungeKutta) continue;
    SCOPED_TRACE(m.name);
    // R = P / Q (Q = 1 for an explicit row, whose P is the polynomial b^T A^(j-1) 1); its Taylor
    // series r = P / Q by series division: r_j = p_j - sum_{k=1..j} q_k r_(j-k) (q_0 = 1).
    const std::vector<double>& P = m.tableau->numerator;
    const std::vector<double>& Q = m.tableau->denominator;
    ASSERT_EQ(Q.front(), 1.0);
    if (m.tableau->is_explicit()) {
      EXPECT_EQ(Q.size(), 1u);
      const std::vector<double> gamma = m.tableau->stability_polynomial();
      ASSERT_EQ(P.size(), gamma.size());
      for (std::size_t j = 0; j < P.size(); ++j) EXPECT_NEAR(P[j], gamma[j], 1e-15) << j;
    }
    const auto at = [](const std::vector<double>& v, int j) {
      return j < static_cast<int>(v.size()) ? v[j] : 0.0;
    };
    std::vector<double> r;
    double factorial = 1.0;
    for (int j = 0; j <= m.order; ++j) {
      double rj = at(P, j);
      for (int k = 1; k <= j; ++k) rj -= at(Q, k) * r[j - k];
      r.push_back(rj);
      if (j > 0) factorial *= j;
      EXPECT_NEAR(rj, 1.0 / factorial, 1e-13) << "coefficient of z^" << j;
    }
    // P / Q is R(z) as the tableau defines it.
    for (Complex z : {Complex(-0.7, 0.3), Complex(0.2, -1.1), Complex(-2.0, 0.0)}) {
      Complex p = 0.0, q = 0.0, power = 1.0;
      for (std::size_t j = 0; j < std::max(P.size(), Q.size()); ++j, power *= z) {
        p += at(P, static_cast<int>(j)) * power;
        q += at(Q, static_cast<int>(j)) * power;
      }
      EXPECT_NEAR(std::abs(p / q - m.tableau->stability_function(z)), 0.0, 1e-13);
    }
  }
}

TEST(MethodTable, AnImplicitRowIsEToItsOrderAndAStable) {
  for (const MethodInfo& m : methods()) {
    if (!m.implicit()) continue;
    SCOPED_TRACE(m.name);
    // |R(z) - e^z| = O(z^(p+1)): halving z divides it by 2^(p+1).
    const Complex z(0.01, 0.02);
    const double e1 = std::abs(m.tableau->stability_function(z) - std::exp(z));
    const double e2 = std::abs(m.tableau->stability_function(z / 2.0) - std::exp(z / 2.0));
    EXPECT_NEAR(std::log2(e1 / e2), m.order + 1, 0.1);
    for (double x : {-1e3, -10.0, -1.0, -1e-3, 0.0})
      for (double y : {-1e3, -3.0, -0.5, 0.0, 0.5, 3.0, 1e3})
        EXPECT_LE(std::abs(m.tableau->stability_function(Complex(x, y))), 1.0 + 1e-12)
            << x << " " << y;
  }
}

TEST(MethodTable, TheStatedLimitsAreTheRowsOwn) {
  for (const MethodInfo& m : methods()) {
    if (m.adaptive()) continue;
    SCOPED_TRACE(m.name);
    // Undamped: the stated h w is where the row's own rule (R(z) or its closed form) says.
    if (std::isfinite(m.undamped_limit)) {
      EXPECT_NEAR(stable_step(m.id, 1.0, 0.0), m.undamped_limit, 1e-9);
    } else {
      EXPECT_TRUE(std::isinf(stable_step(m.id, 1.0, 0.0)));
    }
    if (m.family != MethodFamily::RungeKutta) continue;
    // A Runge-Kutta row: |R(i y)| <= 1 up to the stated y and not beyond (a diagonally implicit
    // tableau's may be the whole axis).
    const double y = m.undamped_limit;
    if (std::isinf(y)) {
      for (double at : {0.1, 1.0, 10.0, 1e3})
        EXPECT_LE(std::abs(m.tableau->stability_function(Complex(0.0, at))), 1.0 + 1e-12) << at;
      continue;
    }
    if (y > 0.0) {
      EXPECT_LE(std::abs(m.tableau->stability_function(Complex(0.0, y * (1 - 1e-9)))), 1.0 + 1e-12);
    }
    // Past it (where it is 0, never stable: just off 0, |R(i y)|^2 - 1 ~ y^2 or y^4 / 4).
    EXPECT_GT(
        std::abs(m.tableau->stability_function(Complex(0.0, y > 0.0 ? y * (1 + 1e-6) : 1e-3))),
        1.0);
    // A closed form the row gives agrees with R(z) on damped modes (under- and overdamped).
    if (!m.mode_limit) continue;
    for (double zeta : {0.01, 0.3, 0.99, 1.5, 6.0}) {
      const double w = 10.0, c = 2.0 * zeta * w;
      const Complex root = std::sqrt(Complex(0.25 * c * c - w * w, 0.0));
      const double from_r = std::min(runge_kutta_limit(m.id, -0.5 * c + root),
                                     runge_kutta_limit(m.id, -0.5 * c - root));
      EXPECT_NEAR(m.mode_limit(c, w * w, {}), from_r, 1e-9 * from_r) << "zeta " << zeta;
    }
  }
}

}  // namespace
}  // namespace springlab
