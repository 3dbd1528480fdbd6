// The parts of a model: its particles joined by springs with stiffness (union-find), and which
// parts hold a pin. A part with no pin is free: gravity would carry it away, and only a part held
// by a pin has a static balance under a load (equilibrium.cpp, iterative_cost.cpp).
#pragma once

#include <numeric>
#include <vector>

#include "springlab/model.hpp"

namespace springlab {

struct Parts {
  std::vector<int> parent;
  std::vector<char> held;  // by root: the part holds a pinned particle
  explicit Parts(const Model& m) : parent(m.particle_count()), held(m.particle_count(), 0) {
    std::iota(parent.begin(), parent.end(), 0);
    for (int s = 0; s < m.spring_count(); ++s)
      if (m.ks(s) > 0.0) parent[find(m.spring_a[s])] = find(m.spring_b[s]);
    for (int i = 0; i < m.particle_count(); ++i)
      if (m.pinned(i)) held[find(i)] = 1;
  }
  int find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  bool held_part(int i) { return held[find(i)] != 0; }
};

}  // namespace springlab
