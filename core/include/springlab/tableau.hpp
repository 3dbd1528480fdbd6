// A Runge-Kutta method as its Butcher tableau, and what follows from it alone: its stability
// function R(z), the factor one step multiplies y' = lambda y by, z = h lambda.
//   stage i:  Y_i = y + h sum_j a_ij F(Y_j),   y1 = y + h sum_i b_i F(Y_i)
//   R(z) = 1 + z b^T (I - z A)^{-1} 1
// For an explicit tableau (A strictly lower triangular) R is the polynomial
//   R(z) = sum_{j=0}^{s} gamma_j z^j,   gamma_0 = 1,  gamma_j = b^T A^{j-1} 1,
// whose first p + 1 coefficients are 1 / j! for a method of order p (docs/numerics.md,
// "Stability functions").
#pragma once

#include <complex>
#include <vector>

namespace springlab {

struct Tableau {
  int stages = 0;
  std::vector<double> a;  // stages x stages, row by row
  std::vector<double> b;  // stages
  // R(z) = P(z) / Q(z), coefficients from z^0 up: for an explicit tableau P is the polynomial
  // below and Q = 1; for an implicit one both from det(I - zA + z 1 b^T) and det(I - zA), found
  // at construction in doubles (exactly, for a tableau read as data: springlab/butcher.hpp).
  std::vector<double> numerator, denominator;
  // An embedded pair (adaptive): the weights' difference b - b_hat that estimates the local error,
  // and the controller's exponent 1 / (q + 1), q the lower of the two orders; empty otherwise.
  std::vector<double> error_weights;
  double error_exponent = 0.0;
  // Whether the last stage is the derivative at the new state (its row of A is b, its node 1):
  // then it is the next step's first ("first same as last").
  bool first_same_as_last() const;

  Tableau() = default;
  Tableau(std::vector<std::vector<double>> rows, std::vector<double> weights);

  double A(int i, int j) const { return a[static_cast<std::size_t>(i * stages + j)]; }
  // Every stage from the ones before it only.
  bool is_explicit() const;
  // R(z), by solving (I - z A) k = 1 (an explicit tableau: stage after stage, as a step does).
  std::complex<double> stability_function(std::complex<double> z) const;
  // gamma_0 .. gamma_s (explicit tableaux only).
  std::vector<double> stability_polynomial() const;
  // The tableau's stated stability function wins: the same R(z) from exact arithmetic.
  void set_stability_function(std::vector<double> p, std::vector<double> q);
};

}  // namespace springlab
