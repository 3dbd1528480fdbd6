// The State: what an integrator advances. Positions and velocities are N x 3 column-major
// matrices, so each coordinate (all x, all y, all z) is one contiguous array: structure of
// arrays, which is what lets the spring loop vectorise. Row i is particle i.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>

namespace springlab {

namespace detail {
using PointsMap =
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3>, Eigen::Aligned64, Eigen::OuterStride<>>;
}

/// N x 3 doubles (positions, velocities, forces), column-major: x | y | z. Its columns are not N
/// doubles apart but a whole number of 64-byte lines, 168 more than a multiple of 512 (about a
/// third of a 4 KiB page): columns exactly a multiple of 4 KiB apart, as N x 3 gives whenever N is
/// a multiple of 512 (a 64 x 64 cloth), map x[i], y[i] and z[i] to one set of every cache, and the
/// force loop, which reads them together with another particle's and with the velocities, evicts
/// its own data (a 512 x 512 cloth stepped half as fast per spring as a 500 x 500 one).
///
/// An Eigen::Map over storage it owns: in expressions it is the Map (no copy); copying,
/// assigning and resize() work as for an Eigen::Matrix<double, Dynamic, 3>. The columns are
/// contiguous one by one, not together: use col(c).data(), never data() over all 3 N.
class Points : public detail::PointsMap {
 public:
  using Base = detail::PointsMap;

  Points() : Base(nullptr, 0, 3, Eigen::OuterStride<>(0)) {}
  Points(Eigen::Index rows, Eigen::Index cols) : Points() { resize(rows, cols); }
  Points(const Points& other) : Points() { *this = other; }
  Points(Points&& other) noexcept : Points() { swap(other); }
  template <typename Derived>
  Points(const Eigen::DenseBase<Derived>& values) : Points() {  // NOLINT: implicit, as Matrix's
    *this = values;
  }

  Points& operator=(const Points& other) {
    if (this != &other) assign(other);
    return *this;
  }
  Points& operator=(Points&& other) noexcept {
    swap(other);
    return *this;
  }
  template <typename Derived>
  Points& operator=(const Eigen::DenseBase<Derived>& values) {
    assign(values);
    return *this;
  }

  /// Contents are kept only when the size does not change, as Eigen's resize().
  void resize(Eigen::Index rows, Eigen::Index cols = 3);
  using Base::setZero;
  Points& setZero(Eigen::Index rows, Eigen::Index cols) {
    resize(rows, cols);
    Base::setZero();
    return *this;
  }
  void swap(Points& other) noexcept;

  /// The distance between the columns, in doubles, for N rows.
  static Eigen::Index column_stride(Eigen::Index rows);

 private:
  template <typename Derived>
  void assign(const Eigen::DenseBase<Derived>& values) {
    if (values.rows() == rows()) {
      Base::operator=(values.derived());
    } else {  // into new storage first: `values` may read this one
      Points fresh(values.rows(), values.cols());
      static_cast<Base&>(fresh) = values.derived();
      swap(fresh);
    }
  }

  struct Free {
    void operator()(double* p) const;
  };
  std::unique_ptr<double[], Free> storage_;
};

/// The State: what an integrator advances: positions and velocities (Points, N x 3, row i is
/// particle i) and the time.
struct State {
  Points x;        ///< positions, m
  Points v;        ///< velocities, m/s
  double t = 0.0;  ///< time, s

  int particle_count() const { return static_cast<int>(x.rows()); }
  void resize(int n) {
    x.resize(n, 3);
    v.resize(n, 3);
  }
};

/// A hash of the exact bits of a state (positions, velocities and time): equal hashes mean
/// bit-identical states. FNV-1a over the raw doubles.
std::uint64_t state_hash(const State& state);

bool all_finite(const State& state);

}  // namespace springlab
