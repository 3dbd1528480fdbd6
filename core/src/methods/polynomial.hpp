// Polynomials with exact rational coefficients, lowest power first, and where they change sign:
// the arithmetic a tableau's stability function is built with (butcher.cpp), and the exact
// isolation of its real roots that proves where |R| <= 1 ends on an axis.
//
// Where s changes sign: only at the roots of odd multiplicity, which are the roots of its odd
// part (Yun's square-free decomposition s = prod a_i^i, the a_i of odd i multiplied), each simple
// there; roots where s touches 0 and turns back drop out. The odd part's smallest positive root
// is isolated by Sturm's theorem: for a square-free q with q_0 = q, q_1 = q', q_{k+1} =
// -rem(q_{k-1}, q_k), the number of distinct roots in (a, b] is V(a) - V(b), V(x) the sign
// changes along q_0(x), q_1(x), ... (zeros skipped); bisection by counts leaves it alone in an
// interval, bisection by sign narrows that to 2^-64 of its size. Every decision is an exact
// sign: the sequence is kept as integer polynomials (each q_k scaled by a positive constant,
// which changes no sign) and evaluated at dyadic points N / 2^k by integer arithmetic.
#pragma once

#include <limits>
#include <vector>

#include "methods/rational.hpp"

namespace springlab::poly {

using Poly = std::vector<Rational>;  // p[k] the coefficient of t^k

void trim(Poly& p);  // no zero leading coefficient (the zero polynomial is {0})
bool is_zero(const Poly& p);
int degree(const Poly& p);  // 0 for constants and the zero polynomial
Poly multiply(const Poly& a, const Poly& b);
Poly add(const Poly& a, const Poly& b, int sign = 1);  // a + sign b
void divide(Poly a, const Poly& b, Poly& q, Poly& r);  // a = q b + r, deg r < deg b
Poly gcd(Poly a, Poly b);                              // monic; gcd(0, 0) = {1}
Poly derivative(const Poly& p);
Rational evaluate(const Poly& p, const Rational& x);
Poly reflected(Poly p);  // p(-t)

// Where a polynomial first turns positive on t > 0, exactly.
struct SignChange {
  // 0: positive just past 0; +inf: never positive on t > 0 (identically zero included).
  double at = std::numeric_limits<double>::infinity();
  // The root isolated: lo < root <= hi (lo == hi: the root is that rational exactly), with
  // hi - lo at most 2^-64 of hi; `at` is the double nearest their midpoint.
  Rational lo = 0, hi = 0;
};

// The first t > 0 past which s > 0, for s with s <= 0 just past 0 (otherwise at = 0): the
// smallest positive root of odd multiplicity. Roots where s touches 0 and turns back are
// passed over.
SignChange first_positive_crossing(const Poly& s);
// The same for the product of `factors`, pairwise coprime (cheaper: each factor's degree, not
// their sum; P^2 - Q^2 = (P - Q)(P + Q)).
SignChange first_positive_crossing(const std::vector<Poly>& factors);

// The number of distinct roots of p in (0, +inf).
int positive_roots(const Poly& p);

}  // namespace springlab::poly
