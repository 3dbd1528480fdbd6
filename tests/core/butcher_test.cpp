// Tableaux as data (springlab/butcher.hpp), checked against mathematics: the number of rooted
// trees, the orders of the classical tableaux, closed forms of their stability limits, R(z)
// against the stability function computed numerically from the tableau, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <string>

#include "methods/rational.hpp"
#include "springlab/butcher.hpp"
#include "springlab/error.hpp"
#include "springlab/methods.hpp"

namespace springlab {
namespace {

namespace fs = std::filesystem;

fs::path tableau_dir() { return fs::path(SPRINGLAB_SOURCE_DIR) / "assets" / "tableaux"; }
ButcherTableau shipped(const std::string& name) { return load_tableau_file((tableau_dir() / (name + ".json")).string()); }

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
  for (const char* bad : {"", "abc", "1/0", "1/", "/2", "1e", "--1", "1.2.3", "0x10", "1e999", "sqrt(2)"})
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
  const TableauAnalysis heun = analyse_tableau(parse_tableau(R"({"A": [[0], ["1/2"]], "b": ["1/2", "1/2"]})", "test"));
  EXPECT_EQ(heun.order, 1);
  ASSERT_TRUE(heun.first_failure);
  EXPECT_EQ(heun.first_failure->tree, "[t]");
  EXPECT_EQ(heun.first_failure->formula, "sum b_i c_i");
  EXPECT_EQ(heun.first_failure->lhs, "1/4");
  EXPECT_EQ(heun.first_failure->rhs, "1/2");
  // RK4 with b_4 = 1/5: even the weights' sum (the single node, order 1) fails.
  const TableauAnalysis rk4 = analyse_tableau(parse_tableau(
      R"({"A": [[0], ["1/2"], [0, "1/2"], [0, 0, 1]], "b": ["1/6", "1/3", "1/3", "1/5"]})", "test"));
  EXPECT_EQ(rk4.order, 0);
  EXPECT_EQ(rk4.first_failure->tree, "t");
  EXPECT_EQ(rk4.first_failure->lhs, "31/30");
  // The classic RK4's first failure is at order 5: sum b_i a_ij a_jk a_kl c_l = 1/120 is one of them.
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
  const double rk4_real = -root([](double x) { return 1.0 + x / 2 + x * x / 6 + x * x * x / 24; }, -3.0, -2.5);
  const double ssprk3_real = -root([](double x) { return 2.0 + x + x * x / 2 + x * x * x / 6; }, -3.0, -2.0);
  struct Case {
    const char* name;
    double real, imaginary;
  };
  const double inf = std::numeric_limits<double>::infinity();
  for (const Case& c : {Case{"rk4", rk4_real, 2.0 * std::sqrt(2.0)}, Case{"three-eighths", rk4_real, 2.0 * std::sqrt(2.0)},
                        Case{"ssprk3", ssprk3_real, std::sqrt(3.0)}, Case{"kutta3", ssprk3_real, std::sqrt(3.0)},
                        Case{"heun", 2.0, 0.0}, Case{"midpoint", 2.0, 0.0}, Case{"euler", 2.0, 0.0},
                        Case{"implicit-euler", inf, inf}, Case{"implicit-midpoint", inf, inf},
                        Case{"trapezoidal", inf, inf}, Case{"sdirk2", inf, inf}, Case{"sdirk3", inf, inf}}) {
    SCOPED_TRACE(c.name);
    const TableauAnalysis a = analyse_tableau(shipped(c.name));
    if (std::isinf(c.real)) EXPECT_TRUE(std::isinf(a.real_limit));
    else EXPECT_NEAR(a.real_limit, c.real, 1e-9 * c.real);
    if (std::isinf(c.imaginary)) EXPECT_TRUE(std::isinf(a.imaginary_limit));
    else EXPECT_NEAR(a.imaginary_limit, c.imaginary, 1e-9 * std::max(c.imaginary, 1.0));
  }
  EXPECT_NEAR(rk4_real, 2.785293563, 1e-8);
  EXPECT_NEAR(ssprk3_real, 2.512745327, 1e-8);
}

// R(z) = P / Q from the exact determinants equals 1 + z b^T (I - z A)^-1 1 solved in complex
// doubles (tableau.hpp), and R(z) - e^z = O(z^(p+1)) for a method of order p.
TEST(Butcher, StabilityFunctionIsTheTableaus) {
  for (const char* name : {"rk4", "dormand-prince", "fehlberg45", "implicit-midpoint", "trapezoidal", "sdirk2",
                           "sdirk3", "bogacki-shampine"}) {
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
    for (const std::complex<double> z : {std::complex<double>(-1.3, 0.4), {0.2, -2.1}, {-3.0, 0.0}, {0.0, 1.7}})
      EXPECT_LT(std::abs(R(z) - numeric.stability_function(z)), 1e-12 * std::max(1.0, std::abs(R(z))));
    // The local error: |R(z) - e^z| / |z|^(p+1) stays bounded as z -> 0 (ratio of two sizes ~ 1).
    const int p = a.order_to_rounding;
    const double e1 = std::abs(R(0.05) - std::exp(0.05)), e2 = std::abs(R(0.025) - std::exp(0.025));
    EXPECT_NEAR(std::log2(e1 / e2), p + 1, 0.15);
  }
  EXPECT_EQ(stability_function_text(analyse_tableau(shipped("implicit-midpoint"))), "(1 + 1/2 z) / (1 - 1/2 z)");
  EXPECT_EQ(stability_function_text(analyse_tableau(shipped("rk4"))), "1 + z + 1/2 z^2 + 1/6 z^3 + 1/24 z^4");
  // The trapezoidal rule's 2 x 2 determinants share nothing to divide out, and give implicit midpoint's R.
  EXPECT_EQ(stability_function_text(analyse_tableau(shipped("trapezoidal"))), "(1 + 1/2 z) / (1 - 1/2 z)");
}

// The built-in methods' tableaux are the shipped data.
TEST(Butcher, BuiltInTableauxAreTheShippedOnes) {
  const std::pair<Method, const char*> pairs[] = {{Method::Euler, "euler"}, {Method::Midpoint, "midpoint"},
                                                  {Method::RK4, "rk4"}, {Method::ImplicitEuler, "implicit-euler"}};
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
           Case{R"({"A": [[0], [1, 0, 0]], "b": [0.5, 0.5]})", "/A/1: row 2 of A has 3 entries: A must be square, 2 x 2"},
           Case{R"({"A": [[0], [1]], "b": [1]})", "/b: b has 1 entries but A has 2 rows"},
           Case{R"({"A": [[0], ["1/0"]], "b": [0.5, 0.5]})", "/A/1/0: A row 2, column 1 \"1/0\" is not a number"},
           Case{R"({"A": [[0], ["x"]], "b": [0.5, 0.5]})", "write a fraction"},
           Case{R"({"A": [["1/2", "1/2"], [0, "1/2"]], "b": [0.5, 0.5]})",
                "/A/0/1: A row 1, column 2 is 1/2, above the diagonal: a fully implicit tableau is not supported"},
           Case{R"({"A": [[0], [1]], "b": [0.5, null]})", "/b/1: b entry 2 must be a number, got null"},
           Case{R"({"A": [[0], [1]]})", "/b: a tableau needs b"},
           Case{R"({"A": [], "b": []})", "/A: A must be a non-empty array"},
           Case{R"({"A": [[0], [1]], "b": [0.5, 0.5], "bhat": [1, 0]})", "did you mean \"b_hat\""},
           Case{R"({"A": [[0], [1]], "b": [0.5, 0.5], "c": [0]})", "/c: c has 1 entries"},
           Case{R"({"A": [[0], [1]], "b": ["1e999", 0.5]})", "is not a number"},
           Case{R"({"A": [[0], [1]], "b": [0.5, 0.5], "embedded_order": 1})", "embedded_order needs b_hat"},
           Case{R"([1, 2])", "a tableau must be a JSON object"},
       }) {
    const std::string m = message(c.json);
    EXPECT_NE(m.find(c.says), std::string::npos) << c.json << "\n  said: " << m;
    EXPECT_EQ(m.find("tableau 'mine.json'"), 0u) << m;
  }
  // c that disagrees with the row sums is a warning, not an error: the steps use A alone.
  const TableauAnalysis shifted = analyse_tableau(parse_tableau(R"({"A": [[0], [1]], "b": [0.5, 0.5], "c": [0, "1/2"]})", "t"));
  ASSERT_EQ(shifted.warnings.size(), 1u);
  EXPECT_NE(shifted.warnings[0].find("c_2 = 1/2 is not the sum of row 2 of A (1)"), std::string::npos);
}

}  // namespace
}  // namespace springlab
