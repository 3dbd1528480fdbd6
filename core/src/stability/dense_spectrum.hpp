// The spectrum of a small dense real matrix (Eigen's EigenSolver: Hessenberg, real Schur), in one
// file: instantiated where it is used, it took 3 to 4 s of compilation a use (a matrix type a
// use), and the analysis used it three ways.
#pragma once

#include <Eigen/Core>

namespace springlab {

/// The eigenvalues of a square real matrix.
Eigen::VectorXcd eigenvalues(const Eigen::MatrixXd& a);

/// The eigenvalues of a square real matrix and its eigenvectors (unit columns, in their order).
void eigen_decomposition(const Eigen::MatrixXd& a, Eigen::VectorXcd& values,
                         Eigen::MatrixXcd& vectors);

}  // namespace springlab
