#include "springlab/tableau.hpp"

#include <Eigen/Dense>
#include <stdexcept>

namespace springlab {

Tableau::Tableau(std::vector<std::vector<double>> rows, std::vector<double> weights)
    : stages(static_cast<int>(weights.size())), b(std::move(weights)) {
  if (rows.size() != b.size())
    throw std::invalid_argument("a tableau needs as many rows of A as weights b");
  a.assign(static_cast<std::size_t>(stages * stages), 0.0);
  for (int i = 0; i < stages; ++i) {
    if (rows[i].size() > b.size()) throw std::invalid_argument("a row of A is longer than b");
    for (std::size_t j = 0; j < rows[i].size(); ++j)
      a[static_cast<std::size_t>(i * stages) + j] = rows[i][j];
  }
  if (is_explicit()) {
    numerator = stability_polynomial();
    denominator = {1.0};
    return;
  }
  // P and Q through their values at z = 0 .. s (Newton's divided differences), in doubles: the
  // built-in implicit rows have one or two stages.
  const auto determinant = [&](double z, bool with_b) {
    Eigen::MatrixXd m = Eigen::MatrixXd::Identity(stages, stages);
    for (int i = 0; i < stages; ++i)
      for (int j = 0; j < stages; ++j)
        m(i, j) += -z * A(i, j) + (with_b ? z * b[static_cast<std::size_t>(j)] : 0.0);
    return m.determinant();
  };
  const auto interpolate = [&](bool with_b) {
    std::vector<double> d;
    for (int k = 0; k <= stages; ++k) d.push_back(determinant(k, with_b));
    for (int level = 1; level <= stages; ++level)
      for (int i = stages; i >= level; --i)
        d[static_cast<std::size_t>(i)] =
            (d[static_cast<std::size_t>(i)] - d[static_cast<std::size_t>(i - 1)]) / level;
    std::vector<double> p{d.back()};
    for (int k = stages - 1; k >= 0; --k) {
      std::vector<double> next(p.size() + 1, 0.0);  // p (z - k) + d_k
      for (std::size_t j = 0; j < p.size(); ++j) next[j + 1] += p[j], next[j] -= k * p[j];
      next[0] += d[static_cast<std::size_t>(k)];
      p = std::move(next);
    }
    while (p.size() > 1 && std::abs(p.back()) < 1e-14) p.pop_back();
    return p;
  };
  numerator = interpolate(true);
  denominator = interpolate(false);
}

bool Tableau::first_same_as_last() const {
  if (stages < 2) return false;
  for (int j = 0; j < stages; ++j)
    if (A(stages - 1, j) != b[static_cast<std::size_t>(j)]) return false;
  return true;
}

void Tableau::set_stability_function(std::vector<double> p, std::vector<double> q) {
  numerator = std::move(p);
  denominator = std::move(q);
}

bool Tableau::is_explicit() const {
  for (int i = 0; i < stages; ++i)
    for (int j = i; j < stages; ++j)
      if (A(i, j) != 0.0) return false;
  return true;
}

std::complex<double> Tableau::stability_function(std::complex<double> z) const {
  if (is_explicit() && stages <= 64) {
    // k_i = 1 + z sum_{j < i} a_ij k_j, the stages one after another, as a step computes them.
    std::complex<double> k[64], bk = 0.0;
    for (int i = 0; i < stages; ++i) {
      std::complex<double> sum = 0.0;
      for (int j = 0; j < i; ++j) sum += A(i, j) * k[j];
      k[i] = 1.0 + z * sum;
      bk += b[static_cast<std::size_t>(i)] * k[i];
    }
    return 1.0 + z * bk;
  }
  using Matrix = Eigen::MatrixXcd;
  Matrix m = Matrix::Identity(stages, stages);
  for (int i = 0; i < stages; ++i)
    for (int j = 0; j < stages; ++j) m(i, j) -= z * A(i, j);
  const Eigen::VectorXcd k = m.partialPivLu().solve(Eigen::VectorXcd::Ones(stages));
  std::complex<double> bk = 0.0;
  for (int i = 0; i < stages; ++i) bk += b[static_cast<std::size_t>(i)] * k[i];
  return 1.0 + z * bk;
}

std::vector<double> Tableau::stability_polynomial() const {
  std::vector<double> gamma{1.0};
  std::vector<double> power(static_cast<std::size_t>(stages), 1.0);  // A^{j-1} 1
  for (int j = 1; j <= stages; ++j) {
    double g = 0.0;
    for (int i = 0; i < stages; ++i)
      g += b[static_cast<std::size_t>(i)] * power[static_cast<std::size_t>(i)];
    gamma.push_back(g);
    std::vector<double> next(static_cast<std::size_t>(stages), 0.0);
    for (int i = 0; i < stages; ++i)
      for (int k = 0; k < stages; ++k)
        next[static_cast<std::size_t>(i)] += A(i, k) * power[static_cast<std::size_t>(k)];
    power = std::move(next);
  }
  while (gamma.size() > 1 && gamma.back() == 0.0) gamma.pop_back();
  return gamma;
}

}  // namespace springlab
