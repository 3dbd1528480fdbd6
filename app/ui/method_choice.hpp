// Methods ticked in a panel: a set of the table's rows that grows with the table (no count of
// methods written down here).
#pragma once

#include <vector>

#include "springlab/methods.hpp"

namespace springlab::ui {

class MethodChoice {
 public:
  bool has(Method m) const {
    const auto row = static_cast<std::size_t>(m);
    return row < on_.size() && on_[row];
  }
  void set(Method m, bool on) {
    const auto row = static_cast<std::size_t>(m);
    if (row >= on_.size()) on_.resize(row + 1, false);
    on_[row] = on;
  }
  bool operator==(const MethodChoice&) const = default;

 private:
  std::vector<bool> on_;
};

}  // namespace springlab::ui
