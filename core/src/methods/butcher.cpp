// A tableau's order conditions and stability function, exactly (springlab/butcher.hpp).
#include "springlab/butcher.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "methods/polynomial.hpp"
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
  while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k])))
    digits += s[k++], any = true;
  if (k < s.size() && s[k] == '.') {
    ++k;
    while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k])))
      digits += s[k++], ++scale, any = true;
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
  const cpp_int ten_power =
      boost::multiprecision::pow(cpp_int(10), static_cast<unsigned>(std::abs(power)));
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

std::string rational_text(const Rational& r) {
  return r.str();
}

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
  int order = TableauAnalysis::kMaxOrder, order_to_rounding = TableauAnalysis::kMaxOrder,
      conditions = 0;
  std::optional<OrderCondition> failure;
};

OrderResult check_order(const std::vector<Tree>& trees, const std::vector<Vector>& phi,
                        const Vector& b) {
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
      out.failure = OrderCondition{bracket(trees, static_cast<int>(t)),
                                   formula(trees, static_cast<int>(t)),
                                   order,
                                   readable(lhs),
                                   readable(rhs),
                                   static_cast<double>(Rational(lhs - rhs))};
    }
    if (rounded &&
        abs(static_cast<double>(Rational(lhs - rhs))) > 1e-10 * static_cast<double>(rhs)) {
      rounded = false;
      out.order_to_rounding = order - 1;
    }
  }
  return out;
}

// ---- The stability function ---------------------------------------------------------------------

using poly::add;
using poly::divide;
using poly::gcd;
using poly::multiply;
using poly::Poly;
using poly::reflected;
using poly::trim;

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
    for (std::size_t i = n - 1; i >= level; --i)
      d[i] = (d[i] - d[i - 1]) / Rational(static_cast<long>(level));
  Poly p{d[n - 1]};
  for (std::size_t k = n - 1; k-- > 0;) {
    p = multiply(p, Poly{Rational(-static_cast<long>(k)), Rational(1)});
    p[0] += d[k];
  }
  trim(p);
  return p;
}

// The sign of |R|^2 - 1 on an axis, as a product of coprime polynomials (the root search takes
// each alone: their degrees, not their sum), each with `terms`, the sizes of what each of its
// coefficients sums (the same products of coefficients' moduli): where a coefficient is a
// cancellation to rounding of its terms, `terms` shows it.
struct AxisFactor {
  Poly s, terms;
};
using AxisPolynomial = std::vector<AxisFactor>;

Poly absolute(Poly p) {
  for (Rational& x : p) x = abs(x);
  return p;
}

// On the negative real axis, z = -t: P(-t)^2 - Q(-t)^2 = (P - Q)(P + Q), coprime since P and Q
// are (a common root would be one of P and of Q). Q has no root there: parse_tableau refuses a
// negative diagonal entry, the only way a lower triangular A puts one there.
AxisPolynomial real_axis(const Poly& P, const Poly& Q) {
  const Poly size =
      reflected(add(absolute(P), absolute(Q)));  // (|P_k| + |Q_k|, signs as reflected)
  return {AxisFactor{reflected(add(P, Q, -1)), absolute(size)},
          AxisFactor{reflected(add(P, Q)), absolute(size)}};
}

// On the imaginary axis, z = i y: |P(iy)|^2 - |Q(iy)|^2, even in y, as a polynomial in u = y^2.
AxisPolynomial imaginary_axis(const Poly& P, const Poly& Q) {
  // p(iy) = re(y) + i im(y), i^k = 1, i, -1, -i.
  const auto parts = [](const Poly& p, Poly& re, Poly& im) {
    re.assign(p.size(), Rational(0));
    im.assign(p.size(), Rational(0));
    for (std::size_t k = 0; k < p.size(); ++k)
      (k % 2 ? im : re)[k] = (k / 2) % 2 ? Rational(-p[k]) : p[k];
    trim(re);
    trim(im);
  };
  Poly pr, pi, qr, qi;
  parts(P, pr, pi);
  parts(Q, qr, qi);
  const auto square = [](const Poly& p) { return multiply(p, p); };
  const auto square_size = [](const Poly& p) { return multiply(absolute(p), absolute(p)); };
  const Poly s = add(add(square(pr), square(pi)), add(square(qr), square(qi)), -1);
  const Poly terms =
      add(add(square_size(pr), square_size(pi)), add(square_size(qr), square_size(qi)));
  AxisFactor a;
  for (std::size_t k = 0; k < s.size(); k += 2) a.s.push_back(s[k]);
  for (std::size_t k = 0; k < terms.size(); k += 2) a.terms.push_back(terms[k]);
  trim(a.s);
  trim(a.terms);
  return {a};
}

// Entries written as decimals of irrational values (SDIRK's gamma to 30 digits) break exact
// identities by their rounding: where |R| = 1 identically, or where order p makes the
// coefficients of |R(iy)|^2 - 1 vanish up to y^p (|e^(iy)| = 1), they are left as 1e-30 of the
// terms that cancel in them, and decide the sign near 0 or far out. For such a tableau (its order
// to rounding above its exact order) those coefficients are set to 0: on the imaginary axis the
// ones up to degree p in y (`vanishing`, in u = y^2 up to p / 2), and on either axis any that is
// below 1e-12 of its terms (the order conditions' test is 1e-10). The limits are then the
// tableau's the entries round, to the digits shown.
void drop_rounding(AxisPolynomial& a, int vanishing) {
  for (AxisFactor& f : a) {
    Poly kept;
    for (std::size_t k = 0; k < f.s.size(); ++k) {
      const double size = k < f.terms.size() ? static_cast<double>(f.terms[k]) : 0.0;
      const bool rounding =
          static_cast<int>(k) <= vanishing || std::abs(static_cast<double>(f.s[k])) <= 1e-12 * size;
      kept.push_back(rounding ? Rational() : f.s[k]);
    }
    trim(kept);
    f.s = std::move(kept);
  }
}

// Where |R| first exceeds 1 along the axis, exactly (polynomial.hpp).
double first_crossing(const AxisPolynomial& a) {
  std::vector<Poly> factors;
  for (const AxisFactor& f : a) factors.push_back(f.s);
  return poly::first_positive_crossing(factors).at;
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
    out[static_cast<std::size_t>(trees[t].order - 1)].push_back(
        bracket(trees, static_cast<int>(t)));
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

namespace {

// The order conditions, one for each rooted tree up to TableauAnalysis::kMaxOrder: the order (exact
// and to rounding), the first condition that fails and how many were checked; and the embedded
// weights' order where the tableau has them.
void record_order_conditions(TableauAnalysis& out, const ButcherTableau& tableau, const Matrix& A,
                             const Vector& b) {
  const std::vector<Tree> trees = all_trees(TableauAnalysis::kMaxOrder);
  const std::vector<Vector> phi = elementary_weights(trees, A);
  const OrderResult order = check_order(trees, phi, b);
  out.order = order.order;
  out.order_to_rounding = order.order_to_rounding;
  out.first_failure = order.failure;
  out.conditions = order.conditions;
  if (tableau.b_hat) out.embedded_order = check_order(trees, phi, exact(*tableau.b_hat)).order;
}

// Cooper's condition, b_i a_ij + b_j a_ji - b_i b_j = 0: exact, or to rounding where the
// entries round irrational values (as the order to rounding is found). Needs the order found.
void check_cooper_condition(TableauAnalysis& out, const Matrix& A, const Vector& b, std::size_t s) {
  out.symplectic = true;
  for (std::size_t i = 0; i < s && out.symplectic; ++i)
    for (std::size_t j = 0; j <= i && out.symplectic; ++j) {
      const Rational m = b[i] * A[i][j] + b[j] * A[j][i] - b[i] * b[j];
      out.symplectic = m == 0 || (out.order_to_rounding > out.order &&
                                  std::abs(m.convert_to<double>()) <= 1e-12);
    }
}

// Warnings where the file says what the tableau does not do: c against the row sums (the scenes
// do not depend on time, so the steps use A alone), and the orders it states against those found.
void warn_on_stated_values(TableauAnalysis& out, const ButcherTableau& tableau, const Matrix& A,
                           std::size_t s) {
  if (tableau.c_given) {
    const Vector c = exact(tableau.c);
    for (std::size_t i = 0; i < s; ++i) {
      Rational sum = 0;
      for (const Rational& x : A[i]) sum += x;
      if (c[i] != sum)
        out.warnings.push_back("c_" + std::to_string(i + 1) + " = " + tableau.c[i].text +
                               " is not the sum of row " + std::to_string(i + 1) + " of A (" +
                               rational_text(sum) + "): the order conditions use the row sums");
    }
  }
  if (tableau.stated_order && *tableau.stated_order != out.order &&
      *tableau.stated_order != out.order_to_rounding &&
      !(*tableau.stated_order > TableauAnalysis::kMaxOrder &&
        out.order == TableauAnalysis::kMaxOrder))
    out.warnings.push_back("the file states order " + std::to_string(*tableau.stated_order) +
                           ", the conditions give " + std::to_string(out.order));
  if (tableau.stated_embedded_order && out.embedded_order &&
      *tableau.stated_embedded_order != *out.embedded_order)
    out.warnings.push_back("the file states embedded order " +
                           std::to_string(*tableau.stated_embedded_order) +
                           ", the conditions give " + std::to_string(*out.embedded_order));
}

// R(z) = P / Q, each determinant interpolated from its values at z = 0 .. s; their common factor
// divided out and both scaled so that Q(0) = 1.
void stability_polynomials(const Matrix& A, const Vector& b, std::size_t s, Poly& P, Poly& Q) {
  Vector p_values, q_values;
  for (std::size_t k = 0; k <= s; ++k) {
    const Rational z(static_cast<long>(k));
    Matrix q(s, Vector(s, Rational(0))), p;
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j)
        q[i][j] = (i == j ? Rational(1) : Rational(0)) - z * A[i][j];
    p = q;
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) p[i][j] += z * b[j];
    p_values.push_back(determinant(p));
    q_values.push_back(determinant(q));
  }
  P = interpolate(p_values);
  Q = interpolate(q_values);
  const Poly common = gcd(P, Q);
  if (common.size() > 1) {
    Poly r;
    divide(Poly(P), common, P, r);
    divide(Poly(Q), common, Q, r);
  }
  const Rational q0 = Q[0];  // Q(0) = det I = 1 up to the common factor's constant
  for (Rational& x : P) x /= q0;
  for (Rational& x : Q) x /= q0;
}

// R(z)'s coefficients, as text and as doubles, and |R| at infinity.
void record_stability_function(TableauAnalysis& out, const Poly& P, const Poly& Q) {
  out.numerator = texts(P);
  out.denominator = texts(Q);
  out.numerator_value = values(P);
  out.denominator_value = values(Q);
  if (P.size() > Q.size())
    out.r_at_infinity = std::numeric_limits<double>::infinity();
  else if (P.size() == Q.size())
    out.r_at_infinity = std::abs(static_cast<double>(Rational(P.back() / Q.back())));
  else
    out.r_at_infinity = 0.0;
}

// The axes, exactly: where |R|^2 - 1 first turns positive (polynomial.hpp's Sturm sequences).
void record_axis_limits(TableauAnalysis& out, const Poly& P, const Poly& Q) {
  AxisPolynomial real = real_axis(P, Q), imaginary = imaginary_axis(P, Q);
  out.rounded_limits = out.order_to_rounding > out.order;
  if (out.rounded_limits) {
    drop_rounding(real, -1);
    drop_rounding(imaginary, out.order_to_rounding / 2);
  }
  out.real_limit = first_crossing(real);
  out.imaginary_limit = std::sqrt(first_crossing(imaginary));  // u = y^2
}

}  // namespace

TableauAnalysis analyse_tableau(const ButcherTableau& tableau) {
  TableauAnalysis out;
  const std::size_t s = static_cast<std::size_t>(tableau.stages);
  Matrix A;
  for (const auto& row : tableau.a) A.push_back(exact(row));
  const Vector b = exact(tableau.b);

  record_order_conditions(out, tableau, A, b);
  check_cooper_condition(out, A, b, s);
  warn_on_stated_values(out, tableau, A, s);
  Poly P, Q;
  stability_polynomials(A, b, s, P, Q);
  record_stability_function(out, P, Q);
  record_axis_limits(out, P, Q);
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
    if (k == 0)
      out += c;
    else
      out += (c == "1" ? "" : c + " ") + power;
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
  std::string p = polynomial_text(analysis.numerator), q = polynomial_text(analysis.denominator);
  if (q == "1") return p;
  return "(" + p + ") / (" + q + ")";
}

}  // namespace springlab
