#include "springlab/state.hpp"

#include <cstring>

namespace springlab {

namespace {
std::uint64_t fnv1a(std::uint64_t hash, const void* data, std::size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) {
    hash ^= p[i];
    hash *= 1099511628211ull;
  }
  return hash;
}
}  // namespace

std::uint64_t state_hash(const State& state) {
  std::uint64_t h = 14695981039346656037ull;
  h = fnv1a(h, state.x.data(), sizeof(double) * state.x.size());
  h = fnv1a(h, state.v.data(), sizeof(double) * state.v.size());
  return fnv1a(h, &state.t, sizeof state.t);
}

bool all_finite(const State& state) { return state.x.allFinite() && state.v.allFinite(); }

}  // namespace springlab
