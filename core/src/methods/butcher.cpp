// A tableau's order conditions and stability function, exactly (springlab/butcher.hpp).
#include "springlab/butcher.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <cstdio>

#include "methods/rational.hpp"

namespace springlab {

// ---- Rationals --------------------------------------------------------------------------------

namespace {

// [sign] digits [. digits] [e [sign] digits], at least one digit; the exponent within +-400.
std::optional<Rational> parse_decimal(const std::string& s) {
  std::size_t k = 0;
  bool negative = false;
  if (k < s.size() && (s[k] == '+' || s[k] == '-')) negative = s[k++] == '-';
  std::string digits;
  int scale = 0;  // value = digits * 10^-scale
  bool any = false;
  while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) digits += s[k++], any = true;
  if (k < s.size() && s[k] == '.') {
    ++k;
    while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) digits += s[k++], ++scale, any = true;
  }
  if (!any) return std::nullopt;
  int exponent = 0;
  if (k < s.size() && (s[k] == 'e' || s[k] == 'E')) {
    ++k;
    bool minus = false;
    if (k < s.size() && (s[k] == '+' || s[k] == '-')) minus = s[k++] == '-';
    std::string e;
    while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) e += s[k++];
    if (e.empty() || e.size() > 3) return std::nullopt;
    exponent = (minus ? -1 : 1) * std::stoi(e);
    if (std::abs(exponent) > 400) return std::nullopt;
  }
  if (k != s.size()) return std::nullopt;
  using boost::multiprecision::cpp_int;
  // (Leading zeros off: cpp_int reads "0..." as octal.)
  digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size()));
  const cpp_int mantissa(digits.empty() ? std::string("0") : digits);
  const int power = exponent - scale;
  const cpp_int ten_power = boost::multiprecision::pow(cpp_int(10), static_cast<unsigned>(std::abs(power)));
  Rational r = power >= 0 ? Rational(mantissa * ten_power) : Rational(mantissa, ten_power);
  return negative ? Rational(-r) : r;
}

std::string trimmed(const std::string& s) {
  std::string out;
  for (char ch : s)
    if (!std::isspace(static_cast<unsigned char>(ch))) out += ch;
  return out;
}

}  // namespace

std::optional<Rational> parse_rational(const std::string& text) {
  const std::string s = trimmed(text);
  const std::size_t slash = s.find('/');
  if (slash == std::string::npos) return parse_decimal(s);
  const auto p = parse_decimal(s.substr(0, slash)), q = parse_decimal(s.substr(slash + 1));
  if (!p || !q || *q == 0) return std::nullopt;
  return Rational(*p / *q);
}

std::string rational_text(const Rational& r) { return r.str(); }

namespace {

// For reading: the exact fraction while it is short, else "~" and 17 digits (a decimal entry of
// 30 digits makes fractions of 60).
std::string readable(const Rational& r) {
  std::string exact = rational_text(r);
  if (exact.size() <= 24) return exact;
  char s[40];
  const double x = static_cast<double>(r);
  std::snprintf(s, sizeof s, "%s~%.17g", x < 0 ? "-" : "", std::abs(x));
  return s;
}

}  // namespace

// ---- Rooted trees -------------------------------------------------------------------------------

namespace {

struct Tree {
  int order = 1;
  std::vector<int> children;  // ids of subtrees, non-decreasing: one tree, one list
  Rational density = 1;       // gamma(t) = |t| prod gamma(children)
};

// Every rooted tree up to `max_order`, by order; within one order, in the order generated.
std::vector<Tree> all_trees(int max_order) {
  std::vector<Tree> trees{Tree{}};  // the single node
  for (int n = 2; n <= max_order; ++n) {
    const std::size_t known = trees.size();  // trees of order < n
    std::vector<int> pick;
    const auto extend = [&](auto& self, int remaining, std::size_t from) -> void {
      if (remaining == 0) {
        Tree t;
        t.order = n;
        t.children = pick;
        t.density = n;
        for (int c : pick) t.density *= trees[static_cast<std::size_t>(c)].density;
        trees.push_back(std::move(t));
        return;
      }
      for (std::size_t id = from; id < known; ++id) {
        if (trees[id].order > remaining) continue;
        pick.push_back(static_cast<int>(id));
        self(self, remaining - trees[id].order, id);
        pick.pop_back();
      }
    };
    extend(extend, n - 1, 0);
  }
  return trees;
}

// Butcher's brackets: "t", "[t]", "[t^2]", "[t,[t]]".
std::string bracket(const std::vector<Tree>& trees, int id) {
  const Tree& t = trees[static_cast<std::size_t>(id)];
  if (t.children.empty()) return "t";
  std::string s = "[";
  for (std::size_t k = 0; k < t.children.size();) {
    std::size_t same = k;
    while (same < t.children.size() && t.children[same] == t.children[k]) ++same;
    if (k) s += ",";
    s += bracket(trees, t.children[k]);
    if (same - k > 1) s += "^" + std::to_string(same - k);
    k = same;
  }
  return s + "]";
}

// The sum a condition stands for, with an index a node: "b_i c_i^2 a_ij c_j".
void factors(const std::vector<Tree>& trees, int id, char index, char& next, std::string& out) {
  const Tree& t = trees[static_cast<std::size_t>(id)];
  int leaves = 0;
  for (int c : t.children) leaves += trees[static_cast<std::size_t>(c)].children.empty();
  if (leaves) out += std::string(" c_") + index + (leaves > 1 ? "^" + std::to_string(leaves) : "");
  for (int c : t.children) {
    if (trees[static_cast<std::size_t>(c)].children.empty()) continue;
    const char child = next++;
    out += std::string(" a_") + index + child;
    factors(trees, c, child, next, out);
  }
}

std::string formula(const std::vector<Tree>& trees, int id) {
  std::string out = "sum b_i";
  char next = 'j';
  factors(trees, id, 'i', next, out);
  return out;
}

using Vector = std::vector<Rational>;
using Matrix = std::vector<Vector>;

Vector times(const Matrix& A, const Vector& x) {
  Vector y(x.size(), Rational(0));
  for (std::size_t i = 0; i < A.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j)
      if (A[i][j] != 0) y[i] += A[i][j] * x[j];
  return y;
}

// Phi(t), the elementary weights of every tree over the stages: the single node's are 1, and a
// tree's are the product over its children of A Phi(child).
std::vector<Vector> elementary_weights(const std::vector<Tree>& trees, const Matrix& A) {
  const std::size_t s = A.size();
  std::vector<Vector> phi;
  std::vector<Vector> a_phi;  // A Phi(t)
  for (const Tree& t : trees) {
    Vector w(s, Rational(1));
    for (int c : t.children)
      for (std::size_t i = 0; i < s; ++i) w[i] *= a_phi[static_cast<std::size_t>(c)][i];
    a_phi.push_back(times(A, w));
    phi.push_back(std::move(w));
  }
  return phi;
}

Rational dot(const Vector& a, const Vector& b) {
  Rational r = 0;
  for (std::size_t i = 0; i < a.size(); ++i) r += a[i] * b[i];
  return r;
}

struct OrderResult {
  int order = TableauAnalysis::kMaxOrder, order_to_rounding = TableauAnalysis::kMaxOrder, conditions = 0;
  std::optional<OrderCondition> failure;
};

OrderResult check_order(const std::vector<Tree>& trees, const std::vector<Vector>& phi, const Vector& b) {
  OrderResult out;
  bool exact = true, rounded = true;
  for (std::size_t t = 0; t < trees.size(); ++t) {
    const int order = trees[t].order;
    const Rational lhs = dot(b, phi[t]);
    const Rational rhs = Rational(1) / trees[t].density;
    ++out.conditions;
    if (exact && lhs != rhs) {
      exact = false;
      out.order = order - 1;
      out.failure = OrderCondition{bracket(trees, static_cast<int>(t)), formula(trees, static_cast<int>(t)), order,
                                   readable(lhs), readable(rhs),
                                   static_cast<double>(Rational(lhs - rhs))};
    }
    if (rounded && abs(static_cast<double>(Rational(lhs - rhs))) > 1e-10 * static_cast<double>(rhs)) {
      rounded = false;
      out.order_to_rounding = order - 1;
    }
  }
  return out;
}

// ---- Polynomials with rational coefficients, lowest power first ----------------------------------

using Poly = std::vector<Rational>;

void trim(Poly& p) {
  while (p.size() > 1 && p.back() == 0) p.pop_back();
  if (p.empty()) p.push_back(Rational(0));
}
bool is_zero(const Poly& p) { return p.size() == 1 && p[0] == 0; }

Poly multiply(const Poly& a, const Poly& b) {
  Poly c(a.size() + b.size() - 1, Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
  trim(c);
  return c;
}
Poly add(const Poly& a, const Poly& b, int sign = 1) {
  Poly c(std::max(a.size(), b.size()), Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i) c[i] += a[i];
  for (std::size_t i = 0; i < b.size(); ++i) c[i] += sign * b[i];
  trim(c);
  return c;
}

// a = q b + r.
void divide(Poly a, const Poly& b, Poly& q, Poly& r) {
  trim(a);
  q.assign(a.size() >= b.size() ? a.size() - b.size() + 1 : 1, Rational(0));
  while (!is_zero(a) && a.size() >= b.size()) {
    const std::size_t shift = a.size() - b.size();
    const Rational f = a.back() / b.back();
    q[shift] = f;
    for (std::size_t i = 0; i < b.size(); ++i) a[i + shift] -= f * b[i];
    a.pop_back();
    trim(a);
  }
  r = a;
  trim(q);
}

Poly gcd(Poly a, Poly b) {
  trim(a);
  trim(b);
  while (!is_zero(b)) {
    Poly q, r;
    divide(a, b, q, r);
    a = std::move(b);
    b = std::move(r);
  }
  const Rational lead = a.back();
  for (Rational& x : a) x /= lead;
  return a;
}

Rational determinant(Matrix m) {
  const std::size_t n = m.size();
  Rational det = 1;
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k;
    while (p < n && m[p][k] == 0) ++p;
    if (p == n) return Rational(0);
    if (p != k) {
      std::swap(m[p], m[k]);
      det = -det;
    }
    det *= m[k][k];
    for (std::size_t i = k + 1; i < n; ++i) {
      if (m[i][k] == 0) continue;
      const Rational f = m[i][k] / m[k][k];
      for (std::size_t j = k; j < n; ++j) m[i][j] -= f * m[k][j];
    }
  }
  return det;
}

// The polynomial of degree <= n through (0, v_0) .. (n, v_n): Newton's divided differences.
Poly interpolate(const Vector& values) {
  const std::size_t n = values.size();
  Vector d = values;
  for (std::size_t level = 1; level < n; ++level)
    for (std::size_t i = n - 1; i >= level; --i) d[i] = (d[i] - d[i - 1]) / Rational(static_cast<long>(level));
  Poly p{d[n - 1]};
  for (std::size_t k = n - 1; k-- > 0;) {
    p = multiply(p, Poly{Rational(-static_cast<long>(k)), Rational(1)});
    p[0] += d[k];
  }
  trim(p);
  return p;
}

Rational evaluate(const Poly& p, const Rational& x) {
  Rational y = 0;
  for (std::size_t k = p.size(); k-- > 0;) y = y * x + p[k];
  return y;
}

// |p(i y)|^2 as a polynomial in y.
Poly modulus_squared_on_imaginary_axis(const Poly& p) {
  Poly re(p.size(), Rational(0)), im(p.size(), Rational(0));
  for (std::size_t k = 0; k < p.size(); ++k) {
    const int sign = (k / 2) % 2 ? -1 : 1;  // i^k = (+-1) or (+-i)
    (k % 2 ? im : re)[k] = sign * p[k];
  }
  trim(re);
  trim(im);
  return add(multiply(re, re), multiply(im, im));
}

// The end of the interval [0, L) of t > 0 where s(t) <= 0: the first root past which s turns
// positive. +inf when s never does (s identically 0: |R| = 1 all along); 0 when s > 0 just past 0.
// Coefficients below 1e-12 of the largest count as zero: they are the rounding of entries written
// as decimals of irrational values (an A-stable SDIRK's gamma to 30 digits leaves 1e-30 where its
// order makes the coefficient of y^2 vanish).
double first_crossing(Poly s) {
  double largest = 0.0;
  for (const Rational& x : s) largest = std::max(largest, std::abs(static_cast<double>(x)));
  for (Rational& x : s)
    if (std::abs(static_cast<double>(x)) <= 1e-12 * largest) x = 0;
  trim(s);
  if (is_zero(s)) return std::numeric_limits<double>::infinity();
  std::size_t m = 0;
  while (s[m] == 0) ++m;
  s.erase(s.begin(), s.begin() + static_cast<long>(m));  // divided by t^m
  if (s[0] > 0) return 0.0;
  const int degree = static_cast<int>(s.size()) - 1;
  std::vector<double> roots;
  if (degree > 0) {
    // The companion matrix's eigenvalues, then Newton in doubles for the last digits.
    Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(degree, degree);
    const double lead = static_cast<double>(s.back());
    for (int i = 0; i < degree; ++i) companion(0, i) = -static_cast<double>(s[static_cast<std::size_t>(degree - 1 - i)]) / lead;
    for (int i = 1; i < degree; ++i) companion(i, i - 1) = 1.0;
    const Eigen::VectorXcd eigen = Eigen::EigenSolver<Eigen::MatrixXd>(companion, false).eigenvalues();
    std::vector<double> coefficient(s.size());
    for (std::size_t k = 0; k < s.size(); ++k) coefficient[k] = static_cast<double>(s[k]);
    for (const auto& z : eigen) {
      if (!(z.real() > 0.0) || std::abs(z.imag()) > 1e-6 * std::max(1.0, std::abs(z.real()))) continue;
      double t = z.real();
      for (int it = 0; it < 8; ++it) {
        double f = 0.0, df = 0.0;
        for (std::size_t k = coefficient.size(); k-- > 0;) df = df * t + f, f = f * t + coefficient[k];
        if (df == 0.0) break;
        const double next = t - f / df;
        if (!(next > 0.0) || std::abs(next - t) > 1e-3 * t) break;  // a double root: keep the estimate
        t = next;
      }
      roots.push_back(t);
    }
  }
  std::sort(roots.begin(), roots.end());
  for (double r : roots)
    if (evaluate(s, Rational(r * (1.0 + 1e-6))) > 0) return r;  // the sign just past it, exactly
  return s.back() < 0 ? std::numeric_limits<double>::infinity() : 0.0;
}

std::vector<std::string> texts(const Poly& p) {
  std::vector<std::string> out;
  for (const Rational& x : p) out.push_back(readable(x));
  return out;
}
std::vector<double> values(const Poly& p) {
  std::vector<double> out;
  for (const Rational& x : p) out.push_back(static_cast<double>(x));
  return out;
}

Vector exact(const std::vector<TableauEntry>& entries) {
  Vector v;
  for (const TableauEntry& e : entries) v.push_back(*parse_rational(e.text));
  return v;
}

}  // namespace

std::vector<std::vector<std::string>> rooted_trees(int order) {
  const std::vector<Tree> trees = all_trees(order);
  std::vector<std::vector<std::string>> out(static_cast<std::size_t>(order));
  for (std::size_t t = 0; t < trees.size(); ++t)
    out[static_cast<std::size_t>(trees[t].order - 1)].push_back(bracket(trees, static_cast<int>(t)));
  return out;
}

bool ButcherTableau::is_explicit() const {
  for (int i = 0; i < stages; ++i)
    for (int j = i; j < stages; ++j)
      if (a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)].value != 0.0) return false;
  return true;
}

Tableau ButcherTableau::numeric() const {
  std::vector<std::vector<double>> rows;
  for (const auto& row : a) {
    rows.emplace_back();
    for (const TableauEntry& e : row) rows.back().push_back(e.value);
  }
  std::vector<double> weights;
  for (const TableauEntry& e : b) weights.push_back(e.value);
  return Tableau(std::move(rows), std::move(weights));
}

TableauAnalysis analyse_tableau(const ButcherTableau& tableau) {
  TableauAnalysis out;
  const std::size_t s = static_cast<std::size_t>(tableau.stages);
  Matrix A;
  for (const auto& row : tableau.a) A.push_back(exact(row));
  const Vector b = exact(tableau.b);

  // Order conditions.
  const std::vector<Tree> trees = all_trees(TableauAnalysis::kMaxOrder);
  const std::vector<Vector> phi = elementary_weights(trees, A);
  const OrderResult order = check_order(trees, phi, b);
  out.order = order.order;
  out.order_to_rounding = order.order_to_rounding;
  out.first_failure = order.failure;
  out.conditions = order.conditions;
  if (tableau.b_hat) out.embedded_order = check_order(trees, phi, exact(*tableau.b_hat)).order;

  // c against the row sums (the scenes do not depend on time, so the steps use A alone).
  if (tableau.c_given) {
    const Vector c = exact(tableau.c);
    for (std::size_t i = 0; i < s; ++i) {
      Rational sum = 0;
      for (const Rational& x : A[i]) sum += x;
      if (c[i] != sum)
        out.warnings.push_back("c_" + std::to_string(i + 1) + " = " + tableau.c[i].text + " is not the sum of row " +
                               std::to_string(i + 1) + " of A (" + rational_text(sum) +
                               "): the order conditions use the row sums");
    }
  }
  if (tableau.stated_order && *tableau.stated_order != out.order && *tableau.stated_order != out.order_to_rounding &&
      !(*tableau.stated_order > TableauAnalysis::kMaxOrder && out.order == TableauAnalysis::kMaxOrder))
    out.warnings.push_back("the file states order " + std::to_string(*tableau.stated_order) + ", the conditions give " +
                           std::to_string(out.order));
  if (tableau.stated_embedded_order && out.embedded_order && *tableau.stated_embedded_order != *out.embedded_order)
    out.warnings.push_back("the file states embedded order " + std::to_string(*tableau.stated_embedded_order) +
                           ", the conditions give " + std::to_string(*out.embedded_order));

  // R(z) = P / Q, each determinant interpolated from its values at z = 0 .. s.
  Vector p_values, q_values;
  for (std::size_t k = 0; k <= s; ++k) {
    const Rational z(static_cast<long>(k));
    Matrix q(s, Vector(s, Rational(0))), p;
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) q[i][j] = (i == j ? Rational(1) : Rational(0)) - z * A[i][j];
    p = q;
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) p[i][j] += z * b[j];
    p_values.push_back(determinant(p));
    q_values.push_back(determinant(q));
  }
  Poly P = interpolate(p_values), Q = interpolate(q_values);
  const Poly common = gcd(P, Q);
  if (common.size() > 1) {
    Poly r;
    divide(Poly(P), common, P, r);
    divide(Poly(Q), common, Q, r);
  }
  const Rational q0 = Q[0];  // Q(0) = det I = 1 up to the common factor's constant
  for (Rational& x : P) x /= q0;
  for (Rational& x : Q) x /= q0;
  out.numerator = texts(P);
  out.denominator = texts(Q);
  out.numerator_value = values(P);
  out.denominator_value = values(Q);
  if (P.size() > Q.size()) out.r_at_infinity = std::numeric_limits<double>::infinity();
  else if (P.size() == Q.size()) out.r_at_infinity = std::abs(static_cast<double>(Rational(P.back() / Q.back())));
  else out.r_at_infinity = 0.0;

  // The axes: on x = -t < 0, P^2 - Q^2; on z = i y, |P|^2 - |Q|^2.
  Poly real = add(multiply(P, P), multiply(Q, Q), -1);
  for (std::size_t k = 1; k < real.size(); k += 2) real[k] = -real[k];
  out.real_limit = first_crossing(real);
  out.imaginary_limit = first_crossing(add(modulus_squared_on_imaginary_axis(P), modulus_squared_on_imaginary_axis(Q), -1));
  return out;
}

namespace {

std::string polynomial_text(const std::vector<std::string>& coefficients) {
  std::string out;
  for (std::size_t k = 0; k < coefficients.size(); ++k) {
    std::string c = coefficients[k];
    if (c == "0") continue;
    const bool negative = c[0] == '-';
    if (negative) c.erase(0, 1);
    out += out.empty() ? (negative ? "-" : "") : (negative ? " - " : " + ");
    const std::string power = k == 0 ? "" : k == 1 ? "z" : "z^" + std::to_string(k);
    if (k == 0) out += c;
    else out += (c == "1" ? "" : c + " ") + power;
  }
  return out.empty() ? "0" : out;
}

}  // namespace

std::string axis_limit_text(double limit, int digits) {
  if (std::isinf(limit)) return "whole axis";
  if (limit == 0.0) return "none";
  char s[32];
  std::snprintf(s, sizeof s, "%.*g", digits, limit);
  return s;
}

std::string stability_function_text(const TableauAnalysis& analysis) {
  const std::string p = polynomial_text(analysis.numerator), q = polynomial_text(analysis.denominator);
  if (q == "1") return p;
  return "(" + p + ") / (" + q + ")";
}

}  // namespace springlab
