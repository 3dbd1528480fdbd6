#include "springlab/state.hpp"

#include <cassert>
#include <cstdlib>
#include <new>
#include <utility>

namespace springlab {

Eigen::Index Points::column_stride(Eigen::Index rows) {
  const Eigen::Index lines = (rows + 7) / 8 * 8;  // whole 64-byte lines
  return lines + (168 - lines % 512 + 512) % 512;
}

void Points::Free::operator()(double* p) const {
  std::free(p);
}

void Points::resize(Eigen::Index rows, Eigen::Index cols) {
  assert(cols == 3);
  (void)cols;
  if (rows == this->rows()) return;
  const Eigen::Index stride = column_stride(rows);
  double* data = nullptr;
  if (rows > 0) {
    data = static_cast<double*>(std::aligned_alloc(64, sizeof(double) * 3 * stride));
    if (data == nullptr) throw std::bad_alloc();
  }
  storage_.reset(data);
  new (static_cast<Base*>(this)) Base(data, rows, 3, Eigen::OuterStride<>(rows > 0 ? stride : 0));
}

void Points::swap(Points& other) noexcept {
  const Eigen::Index mine = rows(), theirs = other.rows();
  const Eigen::Index my_stride = outerStride(), their_stride = other.outerStride();
  storage_.swap(other.storage_);
  new (static_cast<Base*>(this))
      Base(storage_.get(), theirs, 3, Eigen::OuterStride<>(their_stride));
  new (static_cast<Base*>(&other))
      Base(other.storage_.get(), mine, 3, Eigen::OuterStride<>(my_stride));
}

namespace {
std::uint64_t fnv1a(std::uint64_t hash, const void* data, std::size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) {
    hash ^= p[i];
    hash *= 1099511628211ull;
  }
  return hash;
}

std::uint64_t fnv1a(std::uint64_t hash, const Points& p) {
  for (int c = 0; c < 3; ++c) hash = fnv1a(hash, p.col(c).data(), sizeof(double) * p.rows());
  return hash;
}
}  // namespace

std::uint64_t state_hash(const State& state) {
  std::uint64_t h = 14695981039346656037ull;
  h = fnv1a(h, state.x);
  h = fnv1a(h, state.v);
  return fnv1a(h, &state.t, sizeof state.t);
}

bool all_finite(const State& state) {
  return state.x.allFinite() && state.v.allFinite();
}

}  // namespace springlab
