#include "stability/linearised.hpp"

#include <algorithm>
#include <cmath>

#include "springlab/simd.hpp"
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
  spans_ = model.spans;
  const int springs = model.spring_count();
  for (auto* v : {&dx_, &dy_, &dz_, &along_k_, &across_k_, &along_c_, &across_c_})
    v->assign(springs, 0.0);
  std::vector<double> k_row(n, 0.0), c_row(n, 0.0);
  for (int s = 0; s < springs; ++s) {
    const int a = model.spring_a[s], b = model.spring_b[s];
    if (model.pinned(a) && model.pinned(b)) continue;
    const Vec3 d = (at.x.row(b) - at.x.row(a)).transpose();
    const DefiniteSpringJacobian J =
        definite_spring_jacobian(d.squaredNorm(), model.ks(s), model.kd(s), model.rest_length[s]);
    const double across_c =
        model.rest_length[s] == 0.0 && coincident(d.norm(), 0.0) ? model.kd(s) : 0.0;
    dx_[s] = d.x();
    dy_[s] = d.y();
    dz_[s] = d.z();
    along_k_[s] = J.stiff_along;
    across_k_[s] = J.stiff_across;
    along_c_[s] = J.damp_along;
    across_c_[s] = across_c;
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

namespace {

// A span's springs, a chunk at a time: their forces first, then added to their a-ends and taken
// from their b-ends in two separate passes. (Adding each spring's force to both ends at once
// reads a y just written when the ends are closer than four particles, as along a rope or a
// cloth's row: the store cannot be forwarded to the overlapping load, and every four springs
// wait for it.)
constexpr int kChunk = 128;

// The weights of apply(a, b): a K^ + b C^ from the springs' four.
struct Mixed {
  const double *along_k, *across_k, *along_c, *across_c;
  double a, b;
  template <typename T>
  T along(int s) const {
    return a * simd::at<T>(along_k + s) + b * simd::at<T>(along_c + s);
  }
  template <typename T>
  T across(int s) const {
    return a * simd::at<T>(across_k + s) + b * simd::at<T>(across_c + s);
  }
};

// The weights of a Combined operator, made once.
struct Fixed {
  const double *along_w, *across_w;
  template <typename T>
  T along(int s) const {
    return simd::at<T>(along_w + s);
  }
  template <typename T>
  T across(int s) const {
    return simd::at<T>(across_w + s);
  }
};

// y[k] += sign f[k], k < count.
void accumulate(double* y, const double* f, int count, double sign) {
  int k = 0;
  for (; k + simd::kLanes <= count; k += simd::kLanes)
    simd::store(y + k, simd::load(y + k) + sign * simd::load(f + k));
  for (; k < count; ++k) y[k] += sign * f[k];
}

}  // namespace

template <typename Weights>
void Linearised::product(const Weights& weights, double drag, const Points& x, Points& y) const {
  const int n = particles();
  y.setZero(n, 3);
  Points u(n, 3);
  const Eigen::Map<const Eigen::ArrayXd> r(root_inv_mass_.data(), n);
  for (int c = 0; c < 3; ++c) u.col(c).array() = r * x.col(c).array();
  alignas(32) double buffer[3][kChunk];
  double* f[3] = {buffer[0], buffer[1], buffer[2]};
  // Springs s .. s + lanes - 1 of the chunk (T = f64x4: four of them, double: one), into f[.][k]:
  //   du = u_a - u_b,  f = along (d . du) d + across du.
  const auto forces_at = [&]<typename T>(int s, const double* const ua[3],
                                         const double* const ub[3], int k) {
    using simd::at;
    const T ux = at<T>(ua[0] + k) - at<T>(ub[0] + k), uy = at<T>(ua[1] + k) - at<T>(ub[1] + k),
            uz = at<T>(ua[2] + k) - at<T>(ub[2] + k);
    const T dx = at<T>(dx_.data() + s), dy = at<T>(dy_.data() + s), dz = at<T>(dz_.data() + s);
    const T along = weights.template along<T>(s) * (dx * ux + dy * uy + dz * uz);
    const T across = weights.template across<T>(s);
    simd::store(f[0] + k, along * dx + across * ux);
    simd::store(f[1] + k, along * dy + across * uy);
    simd::store(f[2] + k, along * dz + across * uz);
  };
  for (const SpringSpan& span : spans_) {
    for (int first = 0; first < span.count; first += kChunk) {
      const int s = span.first + first, count = std::min(kChunk, span.count - first);
      const int a0 = span.a0 + first, b0 = span.b0 + first;
      const double* ua[3];
      const double* ub[3];
      for (int c = 0; c < 3; ++c) {
        ua[c] = u.col(c).data() + a0;
        ub[c] = u.col(c).data() + b0;
      }
      int k = 0;
      for (; k + simd::kLanes <= count; k += simd::kLanes)
        forces_at.template operator()<simd::f64x4>(s + k, ua, ub, k);
      for (; k < count; ++k) forces_at.template operator()<double>(s + k, ua, ub, k);
      for (int c = 0; c < 3; ++c) {
        accumulate(y.col(c).data() + a0, f[c], count, 1.0);
        accumulate(y.col(c).data() + b0, f[c], count, -1.0);
      }
    }
  }
  for (int c = 0; c < 3; ++c) y.col(c).array() = r * (y.col(c).array() + drag * u.col(c).array());
}

void Linearised::apply(double a, double b, const Points& x, Points& y) const {
  product(Mixed{along_k_.data(), across_k_.data(), along_c_.data(), across_c_.data(), a, b},
          b * drag_, x, y);
}

Linearised::Combined Linearised::combined(double a, double b) const& {
  Combined out(*this);
  const std::size_t springs = along_k_.size();
  out.along_.resize(springs);
  out.across_.resize(springs);
  for (std::size_t s = 0; s < springs; ++s) {
    out.along_[s] = a * along_k_[s] + b * along_c_[s];
    out.across_[s] = a * across_k_[s] + b * across_c_[s];
  }
  out.drag_ = b * drag_;
  return out;
}

void Linearised::Combined::apply(const Points& x, Points& y) const {
  lin_->product(Fixed{along_.data(), across_.data()}, drag_, x, y);
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

Eigen::MatrixXd Linearised::dense_stiffness() const {
  return dense(*this, 1.0, 0.0);
}
Eigen::MatrixXd Linearised::dense_damping() const {
  return dense(*this, 0.0, 1.0);
}

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
