#include "stability/linearised.hpp"

#include <cmath>

#include "springlab/spring_kernel.hpp"

namespace springlab {

Linearised::Linearised(const Model& model, const State& at) {
  const int n = model.particle_count();
  root_inv_mass_.resize(n);
  for (int i = 0; i < n; ++i) {
    root_inv_mass_[i] = std::sqrt(model.inv_mass[i]);
    if (!model.pinned(i)) free_.push_back(i);
  }
  drag_ = model.drag;
  // Springs with a pinned end keep their free end's diagonal block; springs between two pinned
  // particles add nothing.
  std::vector<double> k_row(n, 0.0), c_row(n, 0.0);
  for (int s = 0; s < model.spring_count(); ++s) {
    const int a = model.spring_a[s], b = model.spring_b[s];
    if (model.pinned(a) && model.pinned(b)) continue;
    const Vec3 d = (at.x.row(b) - at.x.row(a)).transpose();
    const DefiniteSpringJacobian J =
        definite_spring_jacobian(d.squaredNorm(), model.ks(s), model.kd(s), model.rest_length[s]);
    const double across_c = model.rest_length[s] == 0.0 && coincident(d.norm(), 0.0) ? model.kd(s) : 0.0;
    if (J.stiff_along == 0.0 && J.stiff_across == 0.0 && J.damp_along == 0.0 && across_c == 0.0) continue;
    a_.push_back(a);
    b_.push_back(b);
    dx_.push_back(d.x());
    dy_.push_back(d.y());
    dz_.push_back(d.z());
    along_k_.push_back(J.stiff_along);
    across_k_.push_back(J.stiff_across);
    along_c_.push_back(J.damp_along);
    across_c_.push_back(across_c);
    // Gershgorin on the scaled matrices: row i sums |K^_ij| = r_i sum_j |K_ij| r_j (r = M^-1/2).
    // A 3x3 block's row sums are at most sqrt(3) times its largest eigenvalue, along |d|^2 +
    // across for K_s, along |d|^2 for C_s; the block sits at (a, a), (a, b), (b, a), (b, b).
    const double l2 = d.squaredNorm();
    const double k = std::sqrt(3.0) * (J.stiff_along * l2 + J.stiff_across);
    const double c = std::sqrt(3.0) * J.damp_along * l2 + across_c;
    const double ra = root_inv_mass_[a], rb = root_inv_mass_[b];
    k_row[a] += k * (ra + rb);
    k_row[b] += k * (ra + rb);
    c_row[a] += c * (ra + rb);
    c_row[b] += c * (ra + rb);
  }
  for (int i : free_) {
    const double r = root_inv_mass_[i];
    stiffness_bound_ = std::max(stiffness_bound_, r * k_row[i]);
    damping_bound_ = std::max(damping_bound_, r * c_row[i] + drag_ * r * r);
  }
}

void Linearised::apply(double a, double b, const Points& x, Points& y) const {
  const int n = particles();
  y.setZero(n, 3);
  Points u(n, 3);
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < n; ++i) u(i, c) = root_inv_mass_[i] * x(i, c);
  const double* U[3] = {u.col(0).data(), u.col(1).data(), u.col(2).data()};
  double* Y[3] = {y.col(0).data(), y.col(1).data(), y.col(2).data()};
  const std::size_t springs = a_.size();
  for (std::size_t s = 0; s < springs; ++s) {
    const int i = a_[s], j = b_[s];
    // K_s du = along_k (d . du) d + across_k du; C_s du = along_c (d . du) d + across_c du;
    // du = u_a - u_b.
    const double ux = U[0][i] - U[0][j], uy = U[1][i] - U[1][j], uz = U[2][i] - U[2][j];
    const double dot = dx_[s] * ux + dy_[s] * uy + dz_[s] * uz;
    const double along = (a * along_k_[s] + b * along_c_[s]) * dot;
    const double across = a * across_k_[s] + b * across_c_[s];
    const double fx = along * dx_[s] + across * ux, fy = along * dy_[s] + across * uy,
                 fz = along * dz_[s] + across * uz;
    Y[0][i] += fx;
    Y[1][i] += fy;
    Y[2][i] += fz;
    Y[0][j] -= fx;
    Y[1][j] -= fy;
    Y[2][j] -= fz;
  }
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < n; ++i) Y[c][i] = root_inv_mass_[i] * (Y[c][i] + b * drag_ * U[c][i]);
}

double Linearised::stiffness(const Points& x) const {
  Points y;
  apply(1.0, 0.0, x, y);
  return x.cwiseProduct(y).sum();
}

double Linearised::damping(const Points& x) const {
  Points y;
  apply(0.0, 1.0, x, y);
  return x.cwiseProduct(y).sum();
}

namespace {
Eigen::MatrixXd dense(const Linearised& lin, double a, double b) {
  const int m = lin.dofs();
  Eigen::MatrixXd out(m, m);
  Points y;
  for (int k = 0; k < m; ++k) {
    lin.apply(a, b, lin.points(Eigen::VectorXd::Unit(m, k)), y);
    out.col(k) = lin.coordinates(y);
  }
  return 0.5 * (out + out.transpose());  // symmetric to the last bit
}
}  // namespace

Eigen::MatrixXd Linearised::dense_stiffness() const { return dense(*this, 1.0, 0.0); }
Eigen::MatrixXd Linearised::dense_damping() const { return dense(*this, 0.0, 1.0); }

Points Linearised::points(const Eigen::VectorXd& v) const {
  Points x = Points::Zero(particles(), 3);
  for (std::size_t k = 0; k < free_.size(); ++k)
    for (int c = 0; c < 3; ++c) x(free_[k], c) = v[3 * k + c];
  return x;
}

Eigen::VectorXd Linearised::coordinates(const Points& x) const {
  Eigen::VectorXd v(dofs());
  for (std::size_t k = 0; k < free_.size(); ++k)
    for (int c = 0; c < 3; ++c) v[3 * k + c] = x(free_[k], c);
  return v;
}

Points Linearised::displacement(const Points& x) const {
  Points u(particles(), 3);
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < particles(); ++i) u(i, c) = root_inv_mass_[i] * x(i, c);
  return u;
}

Points Linearised::random_vector(std::uint64_t seed) const {
  Points q = Points::Zero(particles(), 3);
  for (int i : free_)
    for (int c = 0; c < 3; ++c) {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      q(i, c) = static_cast<double>(seed >> 11) / 9007199254740992.0 - 0.5;
    }
  const double norm = q.norm();
  if (norm > 0.0) q /= norm;
  return q;
}

}  // namespace springlab
