#include "springlab/model.hpp"

#include <algorithm>
#include <cassert>
#include <numeric>
#include <utility>

namespace springlab {

int add_particle(Model& model, double mass, bool pinned) {
  model.mass.push_back(mass);
  model.inv_mass.push_back(pinned ? 0.0 : 1.0 / mass);
  return model.particle_count() - 1;
}

int add_material(Model& model, SpringMaterial material) {
  for (std::size_t i = 0; i < model.materials.size(); ++i)
    if (model.materials[i].ks == material.ks && model.materials[i].kd == material.kd)
      return static_cast<int>(i);
  model.materials.push_back(material);
  return static_cast<int>(model.materials.size()) - 1;
}

void add_spring(Model& model, int a, int b, double rest_length, int material) {
  assert(a != b && material >= 0 && material < static_cast<int>(model.materials.size()));
  model.spring_a.push_back(a);
  model.spring_b.push_back(b);
  model.rest_length.push_back(rest_length);
  model.spring_material.push_back(static_cast<std::uint16_t>(material));
}

void finalize(Model& model) {
  const int n = model.spring_count();
  for (int s = 0; s < n; ++s)
    if (model.spring_a[s] > model.spring_b[s]) std::swap(model.spring_a[s], model.spring_b[s]);

  // Springs with the same material and the same offset b - a, in increasing a, form runs of
  // consecutive particles whenever the scene is regular (a rope, a grid, a box).
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int i, int j) {
    const auto key = [&](int s) {
      return std::tuple(model.spring_material[s], model.spring_b[s] - model.spring_a[s],
                        model.rest_length[s], model.spring_a[s]);
    };
    return key(i) < key(j);
  });
  const auto permute = [&](auto& values) {
    auto sorted = values;
    for (int k = 0; k < n; ++k) sorted[k] = values[order[k]];
    values = std::move(sorted);
  };
  permute(model.spring_a);
  permute(model.spring_b);
  permute(model.rest_length);
  permute(model.spring_material);

  model.spans.clear();
  for (int s = 0; s < n; ++s) {
    if (!model.spans.empty()) {
      SpringSpan& last = model.spans.back();
      const int k = s - last.first;
      if (model.spring_a[s] == last.a0 + k && model.spring_b[s] == last.b0 + k &&
          model.spring_material[s] == last.material && model.rest_length[s] == last.rest) {
        ++last.count;
        continue;
      }
    }
    model.spans.push_back({s, 1, model.spring_a[s], model.spring_b[s], model.spring_material[s],
                           model.rest_length[s]});
  }
}

void set_stiffness(Model& model, double ks) {
  for (auto& m : model.materials) m.ks = ks;
}

void set_damping(Model& model, double kd) {
  for (auto& m : model.materials) m.kd = kd;
}

void set_pinned(Model& model, int particle, bool pinned) {
  model.inv_mass[particle] = pinned ? 0.0 : 1.0 / model.mass[particle];
}

}  // namespace springlab
