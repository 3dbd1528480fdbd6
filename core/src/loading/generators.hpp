// Generators: the repetitive parts of a scene (a rope of N nodes, a W x H cloth, a soft box)
// expanded into particles and springs. Internal to scene.cpp.
//
// Their constants are material constants, so that a finer generator builds the same object:
//   rope   k_s of a segment = stiffness / segment length     (stiffness in N, like E A)
//   cloth  k_s of a spring  = stretch, shear or bend          (a 2D lattice's modulus does not
//                                                              depend on its spacing)
//   box    k_s of a spring  = stiffness x its rest length     (stiffness in N/m^2, like E)
// and the same for k_d; the total mass is shared equally by the nodes.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "loading/json_reader.hpp"
#include "springlab/scene.hpp"

namespace springlab::generators {

struct Builder {
  Model& model;
  std::vector<Vec3>& x;
  std::vector<Vec3>& v;
  std::vector<Surface>& surfaces;
  std::vector<Cell>& cells;
  // Particles of each generator, by name: first index and count.
  std::map<std::string, std::pair<int, int>>& named;
  long springs_planned = 0;

  int particle(const Vec3& position, const Vec3& velocity, double mass, bool pinned) {
    x.push_back(position);
    v.push_back(velocity);
    return add_particle(model, mass, pinned);
  }
  // Refuses (before allocating) a generator that would pass the scene limits.
  void reserve(json_reader::ObjectReader& r, long particles, long springs);
};

void rope(json_reader::ObjectReader& r, const std::string& name, Builder& b);
void cloth(json_reader::ObjectReader& r, const std::string& name, Builder& b);
void box(json_reader::ObjectReader& r, const std::string& name, Builder& b);

}  // namespace springlab::generators
