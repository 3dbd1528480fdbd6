// A scene's forces linearised about a state, in mass-scaled coordinates (y = M^1/2 x):
//
//   K^ = M^-1/2 K M^-1/2,   K = -df/dx from the definite spring Jacobians (spring_kernel.hpp)
//   C^ = M^-1/2 C M^-1/2,   C = -df/dv: spring damping along each spring, plus the drag k_drag I
//
// with the pinned particles' rows and columns dropped (their coordinates are zero in every
// vector). Both are symmetric positive semidefinite, so the first-order system
// y' = [[0, I], [-K^, -C^]] y has its eigenvalues in the closed left half-plane, and any vector x
// has a damping rate gamma = x^T C^ x and a stiffness kappa = x^T K^ x (|x| = 1): the joint
// numerical range of (C^, K^) that stability.cpp searches.
//
// Vectors are N x 3 Points over all particles. The spring terms are computed once, at
// construction, so that the thousands of products an eigen-solver asks for cost a pass over
// arrays each: span by span (model.hpp), where spring first + k joins a0 + k to b0 + k, so that
// the positions and results are read and written four springs at a time.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "springlab/model.hpp"
#include "springlab/state.hpp"

namespace springlab {

class Linearised {
 public:
  Linearised(const Model& model, const State& at);

  int particles() const { return static_cast<int>(root_inv_mass_.size()); }
  int dofs() const { return 3 * static_cast<int>(free_.size()); }
  const std::vector<int>& free_particles() const { return free_; }

  // y = a K^ x + b C^ x.
  void apply(double a, double b, const Points& x, Points& y) const;

  // a K^ + b C^ with each spring's two weights combined once, for an eigen-solver's hundreds of
  // products with the same a and b: five numbers a spring to read instead of seven (a 64 x 64
  // cloth's operator then nearly fits a core's 1 MB L2 cache; 0.7 of apply's time a product).
  // It refers to this Linearised, which must outlive it (none from a temporary).
  class Combined {
   public:
    void apply(const Points& x, Points& y) const;

   private:
    friend class Linearised;
    explicit Combined(const Linearised& lin) : lin_(&lin) {}
    const Linearised* lin_;
    std::vector<double> along_, across_;
    double drag_ = 0.0;  // b k_drag
  };
  Combined combined(double a, double b) const&;
  Combined combined(double a, double b) const&& = delete;
  // x^T K^ x and x^T C^ x, from one product each.
  double stiffness(const Points& x) const;
  double damping(const Points& x) const;

  // Gershgorin's bounds on the largest eigenvalues of K^ and C^ (rows of M^-1/2 |K| M^-1/2).
  double stiffness_bound() const { return stiffness_bound_; }
  double damping_bound() const { return damping_bound_; }

  // K^ and C^ as dense matrices over the free coordinates (particle by particle, x y z).
  Eigen::MatrixXd dense_stiffness() const;
  Eigen::MatrixXd dense_damping() const;
  // A dense vector over the free coordinates to Points, and back.
  Points points(const Eigen::VectorXd& free_coordinates) const;
  Eigen::VectorXd coordinates(const Points& x) const;

  // The physical displacement M^-1/2 x of a mass-scaled vector.
  Points displacement(const Points& x) const;
  // A fixed pseudo-random unit vector on the free coordinates (the same every time).
  Points random_vector(std::uint64_t seed) const;

 private:
  // y = M^-1/2 (sum over springs of (along_s d d^T + across_s I) + drag I) M^-1/2 x, the weights
  // of spring s read by `weights` (linearised.cpp).
  template <typename Weights>
  void product(const Weights& weights, double drag, const Points& x, Points& y) const;

  // One spring's blocks: K_s = along_k d d^T + across_k I, C_s = along_c d d^T + across_c I,
  // d = x_b - x_a. (across_c is k_d for a zero-length spring whose ends meet: it damps along
  // whatever direction they part in, as its stiffness k_s I pulls back along any.) Every spring
  // of the model in its order (a spring between two pinned particles acts on nothing: its ends'
  // coordinates are zero in every vector).
  std::vector<SpringSpan> spans_;
  std::vector<double> dx_, dy_, dz_, along_k_, across_k_, along_c_, across_c_;
  std::vector<double> root_inv_mass_;  // 0 for pinned particles
  std::vector<int> free_;
  double drag_ = 0.0;
  double stiffness_bound_ = 0.0, damping_bound_ = 0.0;
};

}  // namespace springlab
