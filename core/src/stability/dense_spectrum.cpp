#include "stability/dense_spectrum.hpp"

#include <Eigen/Eigenvalues>

namespace springlab {

Eigen::VectorXcd eigenvalues(const Eigen::MatrixXd& a) {
  return Eigen::EigenSolver<Eigen::MatrixXd>(a, false).eigenvalues();
}

void eigen_decomposition(const Eigen::MatrixXd& a, Eigen::VectorXcd& values,
                         Eigen::MatrixXcd& vectors) {
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(a, true);
  values = solver.eigenvalues();
  vectors = solver.eigenvectors();
}

}  // namespace springlab
