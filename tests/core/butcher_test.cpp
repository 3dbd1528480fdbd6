// Tableaux as data (springlab/butcher.hpp), checked against mathematics: the number of rooted
// trees, the orders of the classical tableaux, closed forms of their stability limits, R(z)
// against the stability function computed numerically from the tableau, and bad input.
#include "springlab/butcher.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "methods/polynomial.hpp"
#include "methods/rational.hpp"
#include "springlab/error.hpp"
#include "springlab/methods.hpp"

namespace springlab {
namespace {

namespace fs = std::filesystem;

fs::path tableau_dir() {
  return fs::path(SPRINGLAB_SOURCE_DIR) / "assets" / "tableaux";
}
ButcherTableau shipped(const std::string& name) {
  return load_tableau_file((tableau_dir() / (name + ".json")).string());
}

// Rooted trees with n nodes: 1, 1, 2, 4, 9, 20 (OEIS A000081), 37 up to order 6.
TEST(Butcher, RootedTreesAreCountedAsCayleyCountedThem) {
  const auto trees = rooted_trees(6);
  const std::size_t expected[] = {1, 1, 2, 4, 9, 20};
  std::size_t total = 0;
  for (int n = 0; n < 6; ++n) {
    EXPECT_EQ(trees[static_cast<std::size_t>(n)].size(), expected[n]) << "order " << n + 1;
    total += trees[static_cast<std::size_t>(n)].size();
    // No tree twice.
    auto names = trees[static_cast<std::size_t>(n)];
    std::sort(names.begin(), names.end());
    EXPECT_EQ(std::unique(names.begin(), names.end()), names.end());
  }
  EXPECT_EQ(total, 37u);
  EXPECT_EQ(trees[1][0], "[t]");
}

TEST(Butcher, EntriesAreReadExactly) {
  EXPECT_EQ(parse_rational("0.1"), Rational(1, 10));
  EXPECT_EQ(parse_rational("1.5e-3"), Rational(3, 2000));
  EXPECT_EQ(parse_rational(" 3 / 8 "), Rational(3, 8));
  EXPECT_EQ(parse_rational("-2"), Rational(-2));
  EXPECT_EQ(parse_rational("007"), Rational(7));  // not octal
  EXPECT_EQ(parse_rational("0.5/3"), Rational(1, 6));
  for (const char* bad :
       {"", "abc", "1/0", "1/", "/2", "1e", "--1", "1.2.3", "0x10", "1e999", "sqrt(2)"})
    EXPECT_FALSE(parse_rational(bad)) << bad;
  // A JSON number is read by its shortest decimal: 0.1 is 1/10, so Heun written with 0.5 is exact.
  const ButcherTableau t = parse_tableau(R"({"A": [[0], [1]], "b": [0.5, 0.5]})", "test");
  EXPECT_EQ(t.b[0].text, "0.5");
  EXPECT_EQ(analyse_tableau(t).order, 2);
}

// Every shipped tableau: the order its conditions give is the one the literature states
// (for entries that are decimals of irrational values, to rounding; exactly one order less).
TEST(Butcher, ShippedTableauxHaveTheirStatedOrders) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(tableau_dir())) {
    if (entry.path().extension() != ".json") continue;
    ++count;
    const ButcherTableau t = load_tableau_file(entry.path().string());
    SCOPED_TRACE(entry.path().filename().string());
    ASSERT_TRUE(t.stated_order);
    const TableauAnalysis a = analyse_tableau(t);
    EXPECT_EQ(a.order_to_rounding, *t.stated_order);
    EXPECT_TRUE(a.order == *t.stated_order || a.order == *t.stated_order - 1);
    EXPECT_TRUE(a.warnings.empty()) << a.warnings.front();
    if (t.stated_embedded_order) {
      EXPECT_EQ(a.embedded_order, t.stated_embedded_order);
    }
    EXPECT_EQ(a.conditions, 37);
  }
  EXPECT_GE(count, 17);
  EXPECT_EQ(analyse_tableau(shipped("sdirk2")).order, 1);  // gamma = 1 - sqrt(2)/2 to 30 digits
  EXPECT_EQ(analyse_tableau(shipped("rk4")).order, 4);
  EXPECT_EQ(analyse_tableau(shipped("dormand-prince")).order, 5);
}

// One wrong entry drops the order, and the first failing condition is named with its two sides.
TEST(Butcher, AWrongEntryNamesTheFirstConditionThatFails) {
  // Heun with a21 = 1/2 instead of 1: sum b_i c_i = 1/4, not 1/2.
  const TableauAnalysis heun =
      analyse_tableau(parse_tableau(R"({"A": [[0], ["1/2"]], "b": ["1/2", "1/2"]})", "test"));
  EXPECT_EQ(heun.order, 1);
  ASSERT_TRUE(heun.first_failure);
  EXPECT_EQ(heun.first_failure->tree, "[t]");
  EXPECT_EQ(heun.first_failure->formula, "sum b_i c_i");
  EXPECT_EQ(heun.first_failure->lhs, "1/4");
  EXPECT_EQ(heun.first_failure->rhs, "1/2");
  // RK4 with b_4 = 1/5: even the weights' sum (the single node, order 1) fails.
  const TableauAnalysis rk4 = analyse_tableau(parse_tableau(
      R"({"A": [[0], ["1/2"], [0, "1/2"], [0, 0, 1]], "b": ["1/6", "1/3", "1/3", "1/5"]})",
      "test"));
  EXPECT_EQ(rk4.order, 0);
  EXPECT_EQ(rk4.first_failure->tree, "t");
  EXPECT_EQ(rk4.first_failure->lhs, "31/30");
  // The classic RK4's first failure is at order 5: sum b_i a_ij a_jk a_kl c_l = 1/120 is one of
  // them.
  const TableauAnalysis classic = analyse_tableau(shipped("rk4"));
  EXPECT_EQ(classic.first_failure->order, 5);
  EXPECT_EQ(classic.first_failure->rhs, "1/5");
}

// Stability limits against their closed forms: RK4 on the real axis the root of
// 1 + x/2 + x^2/6 + x^3/24 = 0 (R(x) = 1), on the imaginary axis 2 sqrt(2); SSPRK3's real limit the
// root of R(x) = -1 and sqrt(3) on the imaginary axis; Heun's 2 and none.
TEST(Butcher, AxisLimitsMatchTheirClosedForms) {
  const auto root = [](auto f, double lo, double hi) {
    for (int k = 0; k < 200; ++k) {
      const double mid = 0.5 * (lo + hi);
      (f(lo) * f(mid) <= 0.0 ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
  };
  const double rk4_real =
      -root([](double x) { return 1.0 + x / 2 + x * x / 6 + x * x * x / 24; }, -3.0, -2.5);
  const double ssprk3_real =
      -root([](double x) { return 2.0 + x + x * x / 2 + x * x * x / 6; }, -3.0, -2.0);
  struct Case {
    const char* name;
    double real, imaginary;
  };
  const double inf = std::numeric_limits<double>::infinity();
  for (const Case& c :
       {Case{"rk4", rk4_real, 2.0 * std::sqrt(2.0)},
        Case{"three-eighths", rk4_real, 2.0 * std::sqrt(2.0)},
        Case{"ssprk3", ssprk3_real, std::sqrt(3.0)}, Case{"kutta3", ssprk3_real, std::sqrt(3.0)},
        Case{"heun", 2.0, 0.0}, Case{"midpoint", 2.0, 0.0}, Case{"euler", 2.0, 0.0},
        Case{"implicit-euler", inf, inf}, Case{"implicit-midpoint", inf, inf},
        Case{"trapezoidal", inf, inf}, Case{"sdirk2", inf, inf}, Case{"sdirk3", inf, inf}}) {
    SCOPED_TRACE(c.name);
    const TableauAnalysis a = analyse_tableau(shipped(c.name));
    // Exact roots narrowed to 2^-64: the closed forms to their last bits.
    if (std::isinf(c.real))
      EXPECT_TRUE(std::isinf(a.real_limit));
    else
      EXPECT_NEAR(a.real_limit, c.real, 4e-16 * c.real);
    if (std::isinf(c.imaginary))
      EXPECT_TRUE(std::isinf(a.imaginary_limit));
    else
      EXPECT_NEAR(a.imaginary_limit, c.imaginary, 4e-16 * std::max(c.imaginary, 1.0));
  }
  EXPECT_NEAR(rk4_real, 2.785293563, 1e-8);
  EXPECT_NEAR(ssprk3_real, 2.512745327, 1e-8);
}

// R(z) = P / Q from the exact determinants equals 1 + z b^T (I - z A)^-1 1 solved in complex
// doubles (tableau.hpp), and R(z) - e^z = O(z^(p+1)) for a method of order p.
TEST(Butcher, StabilityFunctionIsTheTableaus) {
  for (const char* name : {"rk4", "dormand-prince", "fehlberg45", "implicit-midpoint",
                           "trapezoidal", "sdirk2", "sdirk3", "bogacki-shampine"}) {
    SCOPED_TRACE(name);
    const ButcherTableau t = shipped(name);
    const TableauAnalysis a = analyse_tableau(t);
    const Tableau numeric = t.numeric();
    const auto R = [&](std::complex<double> z) {
      std::complex<double> p = 0.0, q = 0.0;
      for (std::size_t k = a.numerator_value.size(); k-- > 0;) p = p * z + a.numerator_value[k];
      for (std::size_t k = a.denominator_value.size(); k-- > 0;) q = q * z + a.denominator_value[k];
      return p / q;
    };
    for (const std::complex<double> z :
         {std::complex<double>(-1.3, 0.4), {0.2, -2.1}, {-3.0, 0.0}, {0.0, 1.7}})
      EXPECT_LT(std::abs(R(z) - numeric.stability_function(z)),
                1e-12 * std::max(1.0, std::abs(R(z))));
    // The local error: |R(z) - e^z| / |z|^(p+1) stays bounded as z -> 0 (ratio of two sizes ~ 1).
    const int p = a.order_to_rounding;
    const double e1 = std::abs(R(0.05) - std::exp(0.05)), e2 = std::abs(R(0.025) - std::exp(0.025));
    EXPECT_NEAR(std::log2(e1 / e2), p + 1, 0.15);
  }
  EXPECT_EQ(stability_function_text(analyse_tableau(shipped("implicit-midpoint"))),
            "(1 + 1/2 z) / (1 - 1/2 z)");
  EXPECT_EQ(stability_function_text(analyse_tableau(shipped("rk4"))),
            "1 + z + 1/2 z^2 + 1/6 z^3 + 1/24 z^4");
  // The trapezoidal rule's 2 x 2 determinants share nothing to divide out, and give implicit
  // midpoint's R.
  EXPECT_EQ(stability_function_text(analyse_tableau(shipped("trapezoidal"))),
            "(1 + 1/2 z) / (1 - 1/2 z)");
}

// The built-in methods' tableaux are the shipped data.
TEST(Butcher, BuiltInTableauxAreTheShippedOnes) {
  const std::pair<Method, const char*> pairs[] = {{Method::Euler, "euler"},
                                                  {Method::Midpoint, "midpoint"},
                                                  {Method::RK4, "rk4"},
                                                  {Method::ImplicitEuler, "implicit-euler"}};
  for (const auto& [method, name] : pairs) {
    SCOPED_TRACE(name);
    const Tableau* built_in = method_info(method).tableau;
    ASSERT_NE(built_in, nullptr);
    const Tableau data = shipped(name).numeric();
    ASSERT_EQ(built_in->stages, data.stages);
    EXPECT_EQ(built_in->a, data.a);
    EXPECT_EQ(built_in->b, data.b);
  }
}

// Bad input: one message naming the field, the row and the column, and what to do.
TEST(Butcher, BadInputIsNamed) {
  const auto message = [](const std::string& json) {
    try {
      parse_tableau(json, "tableau 'mine.json'");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  struct Case {
    const char* json;
    const char* says;
  };
  for (const Case& c : {
           Case{R"({"A": [[0], [1, 0, 0]], "b": [0.5, 0.5]})",
                "/A/1: row 2 of A has 3 entries: A must be square, 2 x 2"},
           Case{R"({"A": [[0], [1]], "b": [1]})", "/b: b has 1 entries but A has 2 rows"},
           Case{R"({"A": [[0], ["1/0"]], "b": [0.5, 0.5]})",
                "/A/1/0: A row 2, column 1 \"1/0\" is not a number"},
           Case{R"({"A": [[0], ["x"]], "b": [0.5, 0.5]})", "write a fraction"},
           Case{R"({"A": [["1/2", "1/2"], [0, "1/2"]], "b": [0.5, 0.5]})",
                "/A/0/1: A row 1, column 2 is 1/2, above the diagonal: a fully implicit tableau is "
                "not supported"},
           Case{R"({"A": [[0], [1]], "b": [0.5, null]})",
                "/b/1: b entry 2 must be a number, got null"},
           Case{R"({"A": [[0], [1]]})", "/b: a tableau needs b"},
           Case{R"({"A": [], "b": []})", "/A: A must be a non-empty array"},
           Case{R"({"A": [[0], [1]], "b": [0.5, 0.5], "bhat": [1, 0]})", "did you mean \"b_hat\""},
           Case{R"({"A": [[0], [1]], "b": [0.5, 0.5], "c": [0]})", "/c: c has 1 entries"},
           Case{R"({"A": [[0], [1]], "b": ["1e999", 0.5]})", "is not a number"},
           Case{R"({"A": [[0], [1]], "b": [0.5, 0.5], "embedded_order": 1})",
                "embedded_order needs b_hat"},
           Case{R"([1, 2])", "a tableau must be a JSON object"},
           Case{R"({"A": [["1/2"], [0, "-1/2"]], "b": [0.5, 0.5]})",
                "/A/1/1: A row 2, column 2 is -1/2: a negative diagonal entry puts a pole of R(z) "
                "at z = -2 on the "
                "negative real axis (stage 2's solve"},
       }) {
    const std::string m = message(c.json);
    EXPECT_NE(m.find(c.says), std::string::npos) << c.json << "\n  said: " << m;
    EXPECT_EQ(m.find("tableau 'mine.json'"), 0u) << m;
  }
  // c that disagrees with the row sums is a warning, not an error: the steps use A alone.
  const TableauAnalysis shifted =
      analyse_tableau(parse_tableau(R"({"A": [[0], [1]], "b": [0.5, 0.5], "c": [0, "1/2"]})", "t"));
  ASSERT_EQ(shifted.warnings.size(), 1u);
  EXPECT_NE(shifted.warnings[0].find("c_2 = 1/2 is not the sum of row 2 of A (1)"),
            std::string::npos);
}

// ---- Limits proven: exact roots, checked against closed forms and the numeric R
// ------------------

using Numeric = std::function<std::complex<double>(std::complex<double>)>;

// The first sign change to positive, exactly: a root where s touches 0 and turns back is passed
// over, a triple root counts, a rational root is found exactly, an irrational one to 2^-64.
TEST(Polynomial, FirstPositiveCrossingIsExact) {
  using poly::Poly;
  const auto from_roots = [](std::initializer_list<Rational> roots, Rational scale) {
    Poly p{scale};
    for (const Rational& r : roots) p = poly::multiply(p, Poly{Rational(-r), Rational(1)});
    return p;
  };
  // (t - 1)^2 (t - 3): negative at 0, touches 0 at 1, crosses at 3.
  poly::SignChange c = poly::first_positive_crossing(from_roots({1, 1, 3}, 1));
  EXPECT_LE(c.lo, Rational(3));
  EXPECT_GE(c.hi, Rational(3));
  EXPECT_EQ(c.at, 3.0);
  // (t - 1)^2 (t - 4): a dyadic root, met exactly by the bisection.
  c = poly::first_positive_crossing(from_roots({1, 1, 4}, 1));
  EXPECT_EQ(c.lo, Rational(4));
  EXPECT_EQ(c.hi, Rational(4));
  // (t - 1/3)^3: crosses at 1/3 (not dyadic: isolated, then narrowed).
  c = poly::first_positive_crossing(
      from_roots({Rational(1, 3), Rational(1, 3), Rational(1, 3)}, 1));
  EXPECT_LT(c.lo, Rational(1, 3));
  EXPECT_GE(c.hi, Rational(1, 3));
  EXPECT_EQ(c.at, 1.0 / 3.0);
  // t^2 - 2: sqrt(2) to the last bit.
  EXPECT_EQ(poly::first_positive_crossing(Poly{-2, 0, 1}).at, std::sqrt(2.0));
  // Never positive: -(1 + t^2), and 0 itself.
  EXPECT_TRUE(std::isinf(poly::first_positive_crossing(Poly{-1, 0, -1}).at));
  EXPECT_TRUE(std::isinf(poly::first_positive_crossing(Poly{0}).at));
  // Positive at once: t (after t^m is divided out, the lowest coefficient decides).
  EXPECT_EQ(poly::first_positive_crossing(Poly{0, 0, 1, -5}).at, 0.0);
  // Two roots 1e-12 apart and a third: (t - r1)(t - r2)(t - 7) is negative at 0 and turns
  // positive first at r1 (each root isolated alone before the sign is read); its negative is
  // positive at once.
  const Rational r1(1, 1000), r2 = Rational(1, 1000) + Rational(1, 1000000000000);
  EXPECT_EQ(poly::first_positive_crossing(from_roots({r1, r2, 7}, -1)).at, 0.0);
  c = poly::first_positive_crossing(from_roots({r1, r2, 7}, 1));
  EXPECT_LT(c.lo, r1);
  EXPECT_GE(c.hi, r1);
  EXPECT_LT(c.hi, r2);
  EXPECT_EQ(poly::positive_roots(from_roots({r1, r2, 7, 7}, 1)), 3);
}

// R(z) of an explicit tableau with one entry below the diagonal a row (Y_i = y + h alpha_i
// F(Y_{i-1}), y1 = y + h beta F(Y_s)) is 1 + gamma_1 z + ... + gamma_s z^s with gamma_1 = beta and
// gamma_j = gamma_(j-1) alpha_(s-j+2): any polynomial with nonzero coefficients is one. The JSON of
// the tableau whose R is the given polynomial (coefficients from z^0 up, the first 1).
std::string tableau_with_polynomial(const std::vector<Rational>& gamma) {
  const std::size_t s = gamma.size() - 1;
  std::vector<Rational> alpha(s + 1, Rational(0));  // alpha[i] for stage i (1-based), i >= 2
  for (std::size_t j = 2; j <= s; ++j) alpha[s - j + 2] = gamma[j] / gamma[j - 1];
  std::string json = R"({"A": [["0"])";
  for (std::size_t i = 2; i <= s; ++i) {
    json += ", [";
    for (std::size_t k = 1; k + 1 < i; ++k) json += "\"0\", ";
    json += "\"" + rational_text(alpha[i]) + "\"]";
  }
  json += R"(], "b": [)";
  for (std::size_t i = 1; i <= s; ++i)
    json += (i > 1 ? ", \"" : "\"") + (i == s ? rational_text(gamma[1]) : "0") + "\"";
  return json + "]}";
}

// T_s(w0 + w1 z) / T_s(w0) by the three-term recurrence, in complex doubles: stable where the
// monomial form (the tableau's R, 1e15 times its size at z = -2 s^2 in cancelling terms) is not.
Numeric chebyshev_numeric(int s, double w0, double w1) {
  return [=](std::complex<double> z) {
    const auto T = [s](std::complex<double> x) {
      std::complex<double> previous = 1.0, current = x;
      for (int n = 1; n < s; ++n) previous = std::exchange(current, 2.0 * x * current - previous);
      return current;
    };
    return T(w0 + w1 * z) / T(w0);
  };
}

// The coefficients of T_s(w0 + w1 z) / T_s(w0), the Runge-Kutta-Chebyshev stability polynomial
// (van der Houwen and Sommeijer 1980), exactly.
std::vector<Rational> chebyshev_polynomial(int s, const Rational& w0, const Rational& w1) {
  using poly::Poly;
  Poly previous{Rational(1)}, current{w0, w1};  // T_0, T_1 of x = w0 + w1 z
  for (int n = 1; n < s; ++n) {
    Poly next = poly::add(poly::multiply(Poly{2 * w0, 2 * w1}, current), previous, -1);
    previous = std::move(current);
    current = std::move(next);
  }
  const Rational at_zero = current[0];
  for (Rational& c : current) c /= at_zero;
  return current;
}

// |R| <= 1 just inside each limit and > 1 just past it, from the tableau's own numeric R(z) (a
// complex linear solve, tableau.hpp: no part of the exact analysis), and nowhere above 1 on a dense
// grid of the interval: an independent check that the limit is the first crossing.
// `R` is R(z) in complex doubles (by default the tableau's, by a complex linear solve).
void expect_limits_hold_numerically(const ButcherTableau& t, const TableauAnalysis& a,
                                    Numeric R = nullptr) {
  const Tableau numeric = t.numeric();
  if (!R) R = [&](std::complex<double> z) { return numeric.stability_function(z); };
  const auto modulus = [&](std::complex<double> z) { return std::abs(R(z)); };
  const double slack = 1e-9;  // the numeric R's rounding
  for (const auto& [limit, direction] :
       {std::pair{a.real_limit, std::complex<double>(-1.0, 0.0)},
        std::pair{a.imaginary_limit, std::complex<double>(0.0, 1.0)}}) {
    SCOPED_TRACE(direction.real() ? "real axis" : "imaginary axis");
    if (std::isinf(limit)) {
      for (double r : {1.0, 10.0, 1e3, 1e6}) EXPECT_LE(modulus(r * direction), 1.0 + slack) << r;
      continue;
    }
    if (limit == 0.0) {  // (|R|^2 - 1 ~ c y^(p+1) near 0: far enough out to be seen in doubles)
      EXPECT_GT(modulus(0.1 * direction), 1.0);
      continue;
    }
    for (int k = 1; k < 4000; ++k)
      EXPECT_LE(modulus(limit * k / 4000.0 * direction), 1.0 + slack) << k;
    EXPECT_GT(modulus(limit * (1.0 + 1e-6) * direction), 1.0);
  }
  if (t.is_explicit()) {  // a polynomial: |R| grows without bound on both axes
    EXPECT_FALSE(std::isinf(a.real_limit));
    EXPECT_FALSE(std::isinf(a.imaginary_limit));
  }
}

// Runge-Kutta-Chebyshev polynomials of 10 to 20 stages: undamped, T_s(1 + z / s^2) is stable
// exactly on [-2 s^2, 0], touching |R| = 1 at s - 1 points inside (each a double root the first
// crossing must pass over); damped (w0 = 1 + eps / s^2, w1 = T_s(w0) / T_s'(w0)), exactly on
// [-2 w0 / w1, 0] (|T_s(x)| <= T_s(w0) for |x| <= w0), w0 / w1 in closed form by cosh and sinh.
// Both are first order, so |R(iy)| > 1 for small y: no imaginary interval.
TEST(Butcher, ChebyshevMethodsHaveTheirDerivedRealIntervals) {
  for (int s : {10, 13, 16, 20}) {
    SCOPED_TRACE(s);
    const ButcherTableau undamped = parse_tableau(
        tableau_with_polynomial(chebyshev_polynomial(s, Rational(1), Rational(1, s * s))),
        "chebyshev");
    const TableauAnalysis a = analyse_tableau(undamped);
    EXPECT_EQ(a.order, 1);
    EXPECT_EQ(a.real_limit, 2.0 * s * s);
    EXPECT_EQ(a.imaginary_limit, 0.0);
    expect_limits_hold_numerically(undamped, a, chebyshev_numeric(s, 1.0, 1.0 / (s * s)));

    if (s > 16) continue;  // (damped at 20 stages: entries of 250 digits, 5 s of exact arithmetic)
    const Rational eps(2, 13);  // RKC's damping (Sommeijer, Shampine and Verwer 1998)
    const Rational w0 = 1 + eps / (s * s);
    // w1 = T_s(w0) / T_s'(w0), exactly from the recurrence's coefficients of T_s(w0 + z).
    const std::vector<Rational> shifted =
        chebyshev_polynomial(s, w0, Rational(1));  // T_s(w0 + z) / T_s(w0)
    const Rational w1 = 1 / shifted[1];
    const ButcherTableau damped =
        parse_tableau(tableau_with_polynomial(chebyshev_polynomial(s, w0, w1)), "rkc");
    const TableauAnalysis d = analyse_tableau(damped);
    const double x0 = static_cast<double>(w0), theta = std::acosh(x0);
    const double closed =
        2.0 * x0 * s * std::sinh(s * theta) / (std::sqrt(x0 * x0 - 1.0) * std::cosh(s * theta));
    EXPECT_NEAR(d.real_limit, closed, 1e-12 * closed);
    EXPECT_NEAR(d.real_limit, (2.0 - 4.0 / 3.0 * 2.0 / 13.0) * s * s,
                0.05 * s * s);  // RKC's known (2 - 4 eps / 3) s^2
    EXPECT_EQ(d.imaginary_limit, 0.0);
    expect_limits_hold_numerically(damped, d, chebyshev_numeric(s, x0, static_cast<double>(w1)));
  }
}

// A published ten-stage tableau (Ketcheson's SSPRK(10,4), in Butcher form, tests/data): fourth
// order, limits finite on both axes (a polynomial R), and each the first crossing as the numeric
// R shows; so for every shipped tableau.
TEST(Butcher, LimitsAreTheFirstCrossingOfEveryTableau) {
  const ButcherTableau ssp =
      load_tableau_file(std::string(SPRINGLAB_SOURCE_DIR) + "/tests/data/ssprk10-4.json");
  const TableauAnalysis a = analyse_tableau(ssp);
  EXPECT_EQ(a.order, 4);
  EXPECT_TRUE(std::isinf(a.r_at_infinity));
  EXPECT_NEAR(a.real_limit, 13.9, 0.1);
  expect_limits_hold_numerically(ssp, a);
  for (const auto& entry : fs::directory_iterator(tableau_dir())) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().filename().string());
    const ButcherTableau t = load_tableau_file(entry.path().string());
    expect_limits_hold_numerically(t, analyse_tableau(t));
  }
}

}  // namespace
}  // namespace springlab
