// A student's own Runge-Kutta method: a Butcher tableau typed as data, and what follows from it
// exactly (docs/numerics.md, "A tableau of your own").
//
//   stage i:  Y_i = y + h sum_j a_ij F(Y_j),   y1 = y + h sum_i b_i F(Y_i)
//
// Entries are read exactly: "1/6", "-2", "0.25" and JSON numbers (by their shortest decimal text,
// so 0.1 is 1/10) are rationals. From them, in exact rational arithmetic:
//   - the order conditions, one for each rooted tree t up to order 6 (1, 1, 2, 4, 9, 20 trees,
//     37 in all): b^T Phi(t) = 1 / gamma(t), Phi the elementary weights, gamma the density
//     (Butcher, "Numerical methods for ODEs", ch. 3; Hairer, Norsett and Wanner I, II.2). The
//     order is the highest p whose conditions all hold; the first that fails is named.
//   - the stability function R(z) = P(z) / Q(z),
//       P(z) = det(I - z A + z 1 b^T),   Q(z) = det(I - z A),
//     its coefficients found by interpolating the two determinants at z = 0 .. s, and common
//     factors divided out;
//   - its limits on the negative real axis and on the imaginary axis, from the polynomials
//     P(-t)^2 - Q(-t)^2 and |P(iy)|^2 - |Q(iy)|^2, whose first sign change to positive ends the
//     interval where |R| <= 1: proven, not scanned. Their roots are isolated exactly by Sturm
//     sequences in the rationals and narrowed to 2^-64 of their size (methods/polynomial.hpp),
//     for any number of stages; a root where |R| touches 1 and turns back is passed over.
// Supported: explicit tableaux (A strictly lower triangular) and diagonally implicit ones (A lower
// triangular); a fully implicit A is refused.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "springlab/tableau.hpp"

namespace springlab {

// One entry as written, and its value rounded to double.
struct TableauEntry {
  std::string text;
  double value = 0.0;
};

struct ButcherTableau {
  std::string name;         // shown in lists and messages
  std::string description;  // one or two sentences, optional
  int stages = 0;
  std::vector<std::vector<TableauEntry>> a;  // stages x stages, zeros filled in
  std::vector<TableauEntry> b;
  std::vector<TableauEntry> c;  // as given, or the row sums of A
  bool c_given = false;
  std::optional<std::vector<TableauEntry>> b_hat;  // an embedded pair's other weights
  std::optional<int> stated_order;                 // "order" in the file, if any
  std::optional<int> stated_embedded_order;

  bool is_explicit() const;  // A strictly lower triangular
  // The tableau in doubles, for the steps and the region chart (tableau.hpp).
  Tableau numeric() const;
};

// Reads a tableau from JSON text (format: assets/tableaux/README.md). `where` names the file or
// link in messages. Bad input throws InputError naming the field, row and column:
//   "tableau 'my.json': /A/1/2: "1/0" is not a number: write a fraction (1/6), an integer or a
//   decimal".
ButcherTableau parse_tableau(const std::string& json_text, const std::string& where);
ButcherTableau load_tableau_file(const std::string& path);
// The tableau as compact JSON that parse_tableau reads back to the same entries (for a link).
std::string tableau_json(const ButcherTableau& tableau);

// One order condition: its tree in Butcher's bracket notation ("[t,[t]]", t the single node),
// the sum it stands for ("sum b_i c_i a_ij c_j") and its two sides, exactly.
struct OrderCondition {
  std::string tree;
  std::string formula;
  int order = 0;
  std::string lhs, rhs;   // "1/8"
  double residual = 0.0;  // lhs - rhs, in doubles
};

struct TableauAnalysis {
  static constexpr int kMaxOrder = 6;
  int order = 0;  // exact: every condition of order <= order holds (kMaxOrder: at least that)
  std::optional<OrderCondition> first_failure;  // the first that fails, in order of trees
  // The order when each condition need only hold to 1e-10 of its right side: higher than `order`
  // when entries are decimals rounded from irrational values (1 - sqrt(2) / 2 to 17 digits).
  int order_to_rounding = 0;
  int conditions = 0;                 // checked: every tree up to kMaxOrder (37)
  std::optional<int> embedded_order;  // of b_hat, the same way
  std::vector<std::string> warnings;  // c against the row sums, the stated orders
  // R(z) = P(z) / Q(z): coefficients from z^0 up, exact ("1/24") and in doubles.
  std::vector<std::string> numerator, denominator;
  std::vector<double> numerator_value, denominator_value;
  // Where |R| <= 1 from the origin: [-real_limit, 0] on the real axis, [-imaginary_limit,
  // imaginary_limit] on the imaginary one (+inf: the whole half axis; 0: nowhere past 0).
  double real_limit = 0.0, imaginary_limit = 0.0;
  // True when the limits are those of the tableau the entries round (entries written as
  // decimals of irrational values: coefficients that cancel to rounding taken as 0, butcher.cpp).
  bool rounded_limits = false;
  double r_at_infinity = 0.0;  // |R(z)| as |z| -> infinity (+inf for a polynomial; 0: L-stable's)
  // b_i a_ij + b_j a_ji = b_i b_j for every i, j (exactly; to 1e-12 where the entries are
  // rounded): the method keeps every quadratic invariant, such as angular momentum, and is
  // symplectic (Cooper 1987; Hairer, Lubich and Wanner, Geometric Numerical Integration, IV.2.1).
  bool symplectic = false;
};

TableauAnalysis analyse_tableau(const ButcherTableau& tableau);

// A limit on an axis for reading: "whole axis" (infinite), "none" (0), else `digits` digits.
std::string axis_limit_text(double limit, int digits = 6);

// R(z) written out: "1 + z + 1/2 z^2 + 1/6 z^3 + 1/24 z^4", "(1 + 1/2 z) / (1 - 1/2 z)".
std::string stability_function_text(const TableauAnalysis& analysis);

// The rooted trees up to `order` in Butcher's bracket notation, grouped by order (for tests and
// the docs): 1, 1, 2, 4, 9, 20 of orders 1 to 6.
std::vector<std::vector<std::string>> rooted_trees(int order);

}  // namespace springlab
