// Rational polynomials and the exact isolation of their positive roots (polynomial.hpp).
#include "methods/polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>

namespace springlab::poly {

using boost::multiprecision::cpp_int;

// ---- Arithmetic ---------------------------------------------------------------------------------

void trim(Poly& p) {
  while (p.size() > 1 && p.back() == 0) p.pop_back();
  if (p.empty()) p.push_back(Rational(0));
}

bool is_zero(const Poly& p) {
  return p.size() == 1 && p[0] == 0;
}

int degree(const Poly& p) {
  return static_cast<int>(p.size()) - 1;
}

Poly multiply(const Poly& a, const Poly& b) {
  Poly c(a.size() + b.size() - 1, Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != 0)
      for (std::size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
  trim(c);
  return c;
}

Poly add(const Poly& a, const Poly& b, int sign) {
  Poly c(std::max(a.size(), b.size()), Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i) c[i] += a[i];
  for (std::size_t i = 0; i < b.size(); ++i) c[i] += sign * b[i];
  trim(c);
  return c;
}

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

// ---- Remainder sequences over the integers ------------------------------------------------------
//
// Euclid's algorithm in the rationals lets coefficients grow without bound (a random 20-stage
// tableau's Sturm sequence took 80 s); the subresultant remainder sequence (Collins 1967; Brown
// and Traub 1971; Cohen, "A course in computational algebraic number theory", 3.3.1) keeps them
// integers whose size grows linearly, each member a constant times Euclid's.

namespace {

// A polynomial times a positive constant, with integer coefficients: the same sign everywhere.
using IntPoly = std::vector<cpp_int>;

int int_degree(const IntPoly& p) {
  return static_cast<int>(p.size()) - 1;
}
bool int_zero(const IntPoly& p) {
  return p.size() == 1 && p[0] == 0;
}
void int_trim(IntPoly& p) {
  while (p.size() > 1 && p.back() == 0) p.pop_back();
  if (p.empty()) p.push_back(0);
}

IntPoly integral(const Poly& p) {
  cpp_int denominators = 1;
  for (const Rational& c : p) {
    const cpp_int d = boost::multiprecision::denominator(c);
    denominators = denominators / boost::multiprecision::gcd(denominators, d) * d;
  }
  IntPoly out;
  cpp_int content = 0;
  for (const Rational& c : p) {
    out.push_back(boost::multiprecision::numerator(c) *
                  (denominators / boost::multiprecision::denominator(c)));
    content = boost::multiprecision::gcd(content, cpp_int(abs(out.back())));
  }
  if (content > 1)
    for (cpp_int& c : out) c /= content;
  int_trim(out);
  return out;
}

// prem(a, b) = lc(b)^(deg a - deg b + 1) a mod b, in the integers (deg a >= deg b).
IntPoly pseudo_remainder(IntPoly a, const IntPoly& b) {
  const int db = int_degree(b);
  const cpp_int& lead = b.back();
  int times = int_degree(a) - db + 1;
  while (!int_zero(a) && int_degree(a) >= db) {
    const cpp_int f = a.back();
    const int shift = int_degree(a) - db;
    for (cpp_int& c : a) c *= lead;
    for (int i = 0; i <= db; ++i)
      a[static_cast<std::size_t>(i + shift)] -= f * b[static_cast<std::size_t>(i)];
    a.pop_back();
    int_trim(a);
    --times;
  }
  if (times > 0) {
    const cpp_int rest = boost::multiprecision::pow(lead, static_cast<unsigned>(times));
    for (cpp_int& c : a) c *= rest;
  }
  return a;
}

// The subresultant remainder sequence of a, b (deg a >= deg b, b != 0), each member after the two
// given scaled to be -rem(the two before) times a positive constant (Sturm's signs), until the
// remainder vanishes: the last member is gcd(a, b) up to a constant.
std::vector<IntPoly> remainder_sequence(IntPoly a, IntPoly b) {
  std::vector<IntPoly> out{a, b};
  cpp_int g = 1, h = 1;
  for (;;) {
    const int delta = int_degree(a) - int_degree(b);
    IntPoly r = pseudo_remainder(a, b);
    if (int_zero(r)) break;
    // prem is lc(b)^(delta + 1) rem; the division by g h^delta is exact.
    const cpp_int divisor = g * boost::multiprecision::pow(h, static_cast<unsigned>(delta));
    const bool negative = ((b.back() < 0) && (delta + 1) % 2 == 1) != (divisor < 0);
    for (cpp_int& c : r) c = (negative ? c : cpp_int(-c)) / divisor;
    out.push_back(r);
    if (int_degree(r) == 0) break;
    a = std::move(b);
    b = std::move(r);
    g = a.back();
    // h <- g^delta / h^(delta - 1), exactly.
    if (delta == 0) continue;
    h = boost::multiprecision::pow(g, static_cast<unsigned>(delta)) /
        boost::multiprecision::pow(h, static_cast<unsigned>(delta - 1));
  }
  return out;
}

Poly rational(const IntPoly& p) {
  Poly out;
  for (const cpp_int& c : p) out.push_back(Rational(c));
  return out;
}

}  // namespace

Poly gcd(Poly a, Poly b) {
  trim(a);
  trim(b);
  if (is_zero(a) && is_zero(b)) return Poly{Rational(1)};
  if (is_zero(b)) std::swap(a, b);
  if (is_zero(a) || degree(b) == 0) {  // gcd(0, b) = b; a constant divides everything
    Poly monic = is_zero(a) ? b : Poly{Rational(1)};
    const Rational lead = monic.back();
    for (Rational& x : monic) x /= lead;
    return monic;
  }
  if (degree(a) < degree(b)) std::swap(a, b);
  Poly g = rational(remainder_sequence(integral(a), integral(b)).back());
  const Rational lead = g.back();
  for (Rational& x : g) x /= lead;
  return g;
}
Poly derivative(const Poly& p) {
  Poly d(p.size() > 1 ? p.size() - 1 : 1, Rational(0));
  for (std::size_t k = 1; k < p.size(); ++k) d[k - 1] = p[k] * static_cast<long>(k);
  trim(d);
  return d;
}

Rational evaluate(const Poly& p, const Rational& x) {
  Rational y = 0;
  for (std::size_t k = p.size(); k-- > 0;) y = y * x + p[k];
  return y;
}

Poly reflected(Poly p) {
  for (std::size_t k = 1; k < p.size(); k += 2) p[k] = -p[k];
  return p;
}

// ---- Exact signs at dyadic points ---------------------------------------------------------------

namespace {

// n / 2^k, n >= 0.
struct Dyadic {
  cpp_int n = 0;
  unsigned k = 0;
};

// a and b over one power of two.
void common(Dyadic& a, Dyadic& b) {
  if (a.k < b.k) a.n <<= (b.k - a.k), a.k = b.k;
  if (b.k < a.k) b.n <<= (a.k - b.k), b.k = a.k;
}

Dyadic midpoint(Dyadic a, Dyadic b) {
  common(a, b);
  return Dyadic{a.n + b.n, a.k + 1};
}

Rational value(const Dyadic& x) {
  return Rational(x.n, cpp_int(1) << x.k);
}

// The sign of p(n / 2^k): of sum c_i n^i 2^(k (d - i)), by Horner's rule.
int sign_at(const IntPoly& p, const Dyadic& x) {
  const std::size_t d = p.size() - 1;
  cpp_int acc = p[d];
  for (std::size_t i = d; i-- > 0;) acc = acc * x.n + (p[i] << (x.k * (d - i)));
  return acc > 0 ? 1 : acc < 0 ? -1 : 0;
}

// Sturm's sequence of a square-free polynomial, each member scaled to integers.
class Sturm {
 public:
  // q_0 = q, q_1 = q', q_{k+1} = -rem(q_{k-1}, q_k), each times a positive constant.
  explicit Sturm(const Poly& q) {
    const IntPoly p = integral(q), d = integral(derivative(q));
    sequence_ = degree(q) > 0 ? remainder_sequence(p, d) : std::vector<IntPoly>{p};
  }
  // Sign changes along the sequence at x, zeros skipped.
  int variations(const Dyadic& x) const {
    int changes = 0, last = 0;
    for (const IntPoly& p : sequence_) {
      const int s = sign_at(p, x);
      if (s != 0 && last != 0 && s != last) ++changes;
      if (s != 0) last = s;
    }
    return changes;
  }
  // Distinct roots in (a, b], a not a root.
  int count(const Dyadic& a, const Dyadic& b) const { return variations(a) - variations(b); }
  const IntPoly& polynomial() const { return sequence_.front(); }
  // gcd(q, q') up to a constant: the last member (a constant when q is square-free).
  const IntPoly& last() const { return sequence_.back(); }

 private:
  std::vector<IntPoly> sequence_;
};

// A power of two above every root's modulus (Cauchy: 1 + max |c_i / c_d|).
Dyadic root_bound(const IntPoly& p) {
  const cpp_int lead = abs(p.back());
  cpp_int largest = 0;
  for (const cpp_int& c : p) largest = std::max(largest, cpp_int(abs(c)));
  const cpp_int bound = largest / lead + 2;
  Dyadic b{1, 0};
  while (b.n <= bound) b.n <<= 1;
  return b;
}

// The square-free part: p / gcd(p, p'), the same roots each once.
Poly square_free(const Poly& p) {
  const Poly g = gcd(p, derivative(p));
  if (degree(g) == 0) return p;
  Poly q, r;
  divide(p, g, q, r);
  return q;
}

// The product of the factors of odd multiplicity (Yun's square-free decomposition f = prod
// a_i^i): the same sign changes as f, each at a simple root. Where |R| touches 1 (a Chebyshev
// method's s - 1 extrema) the factors are squares and drop out, so they are never isolated.
// `first` is gcd(f, f').
Poly odd_part(const Poly& f, const Poly& first) {
  Poly b, c, quotient, remainder;
  divide(f, first, b, remainder);
  divide(derivative(f), first, c, remainder);
  Poly d = add(c, derivative(b), -1);
  Poly odd{Rational(1)};
  for (int i = 1; degree(b) > 0; ++i) {
    const Poly a = gcd(b, d);  // a_i
    if (i % 2 == 1) odd = multiply(odd, a);
    divide(b, a, quotient, remainder);
    b = quotient;
    divide(d, a, c, remainder);
    d = add(c, derivative(b), -1);
  }
  return odd;
}

}  // namespace

int positive_roots(const Poly& p0) {
  Poly p = p0;
  trim(p);
  if (is_zero(p)) return 0;
  while (p.size() > 1 && p[0] == 0) p.erase(p.begin());  // the root 0 is not positive
  if (degree(p) == 0) return 0;
  const Sturm sturm(square_free(p));
  return sturm.count(Dyadic{0, 0}, root_bound(sturm.polynomial()));
}

namespace {

// The smallest positive root of a square-free q with q(0) != 0, isolated and narrowed from its
// Sturm sequence; nullopt when it has none.
std::optional<SignChange> smallest_positive_root(const Sturm& sturm) {
  const IntPoly& q = sturm.polynomial();
  if (int_degree(q) == 0) return std::nullopt;
  Dyadic a{0, 0}, b = root_bound(q);
  if (sturm.count(a, b) == 0) return std::nullopt;
  // Alone in (a, b].
  while (sturm.count(a, b) > 1) {
    const Dyadic m = midpoint(a, b);
    (sturm.count(a, m) >= 1 ? b : a) = m;
  }
  // Bisection by sign: q has a simple root in (a, b], of opposite signs at a and past it.
  const int sign_a = sign_at(q, a);
  for (;;) {
    if (sign_at(q, b) == 0) {
      a = b;
      break;
    }
    common(a, b);
    if (((b.n - a.n) << 64) <= b.n) break;
    const Dyadic m = midpoint(a, b);
    (sign_at(q, m) == sign_a ? a : b) = m;
  }
  SignChange out;
  out.lo = value(a);
  out.hi = value(b);
  out.at = static_cast<double>(Rational((out.lo + out.hi) / 2));
  return out;
}

}  // namespace

SignChange first_positive_crossing(const std::vector<Poly>& factors) {
  SignChange out;
  int sign_near_zero = 1;
  std::vector<Poly> reduced;
  for (Poly f : factors) {
    trim(f);
    if (is_zero(f)) return out;            // the product is 0 everywhere
    while (f[0] == 0) f.erase(f.begin());  // divided by t^m: the same sign for t > 0
    if (f[0] < 0) sign_near_zero = -sign_near_zero;
    if (degree(f) > 0) reduced.push_back(std::move(f));
  }
  if (sign_near_zero > 0) {
    out.at = 0.0;
    return out;
  }
  // Sign changes happen only at the odd parts' roots, all simple: the first of them past 0 is
  // the crossing (the product < 0 before it, > 0 after).
  std::optional<SignChange> first;
  for (const Poly& f : reduced) {
    // Sturm's sequence of f ends in gcd(f, f'): a constant when f is square-free (the usual case,
    // and then the sequence is the one to search); else f's odd part has a sequence of its own.
    const Sturm whole(f);
    const std::optional<SignChange> root =
        int_degree(whole.last()) == 0
            ? smallest_positive_root(whole)
            : smallest_positive_root(Sturm(odd_part(f, rational(whole.last()))));
    if (root && (!first || root->lo < first->lo)) first = root;
  }
  return first ? *first : out;
}

SignChange first_positive_crossing(const Poly& s) {
  return first_positive_crossing(std::vector<Poly>{s});
}

}  // namespace springlab::poly
