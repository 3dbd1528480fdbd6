// The Model: the constants of a scene, which change only through the functions at the end
// (parameters, and pinning: a drag pins what it holds, an emitter's births and deaths unpin and
// pin its pool's particles).
//
//   Particle data      one array a quantity (mass, inverse mass); inverse mass 0 means pinned.
//   Springs            index pairs, rest lengths and a material (stiffness k_s, damping k_d),
//                      stored structure-of-arrays and grouped into contiguous "spans" (below).
//   Forces             gravity, global viscous drag (in still air or a wind), attractors.
//   Emitters           particle sources, each with a fixed pool of particles (emitter.hpp).
//   Colliders          planes and spheres with Coulomb friction and restitution.
//
// Positions and velocities live in the State (state.hpp), never here.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "springlab/emitter.hpp"
#include "springlab/fields.hpp"

namespace springlab {

/// k_s and k_d shared by a group of springs (a cloth's stretch, shear and bend springs are three
/// materials). Setting "every spring's stiffness" sets every material's.
struct SpringMaterial {
  double ks = 0.0;  ///< stiffness, N/m
  double kd = 0.0;  ///< damping along the spring, N s/m
};

/// A run of springs whose ends are consecutive particles: spring first + k joins particles
/// a0 + k and b0 + k, all with one material and one rest length. Generators produce long runs (a
/// rope is one span, a cloth's vertical springs are one span), which lets the force loop read
/// positions contiguously and vectorise. A lone spring is a span of length one.
struct SpringSpan {
  std::int32_t first = 0;
  std::int32_t count = 0;
  std::int32_t a0 = 0;
  std::int32_t b0 = 0;
  std::int32_t material = 0;
  double rest = 0.0;
};

struct PlaneCollider {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitY();  ///< unit length
  double friction = 0.0;        ///< Coulomb coefficient mu
  double restitution = 0.0;     ///< fraction of the normal speed kept after impact
};

struct SphereCollider {
  Vec3 center = Vec3::Zero();
  double radius = 1.0;
  double friction = 0.0;
  double restitution = 0.0;
};

/// The Model: the constants of a scene, which change only through the functions below
/// (parameters, and pinning). One array a quantity for the particles (inverse mass 0: pinned);
/// springs as index pairs, rest lengths and materials, grouped into spans; forces, emitters and
/// colliders. Positions and velocities live in the State (state.hpp), never here.
struct Model {
  // Particles.
  std::vector<double> mass;      ///< kg; kept for pinned particles too (drawing, un-pinning)
  std::vector<double> inv_mass;  ///< 1/kg; 0 = pinned (moves only with its prescribed velocity)

  // Springs, sorted by finalize() so that spans are long; a < b for every spring.
  std::vector<std::int32_t> spring_a;
  std::vector<std::int32_t> spring_b;
  std::vector<double> rest_length;
  std::vector<std::uint16_t> spring_material;
  std::vector<SpringMaterial> materials;
  std::vector<SpringSpan> spans;  ///< built by finalize()

  // Forces.
  Vec3 gravity = Vec3::Zero();  ///< m/s^2
  double drag = 0.0;            ///< global viscous drag k_drag: f = -k_drag (v - wind), N s/m
  Vec3 wind = Vec3::Zero();     ///< m/s, the air's velocity
  std::vector<Attractor> attractors;

  std::vector<Emitter> emitters;

  // Colliders.
  std::vector<PlaneCollider> planes;
  std::vector<SphereCollider> spheres;
  double particle_radius = 0.0;  ///< m: particles touch colliders at this distance

  /// The "damping" factor of position Verlet (the rope exercise): x1 = x + (1 - d)(x - x_prev) +
  /// ...
  double verlet_damping = 0.0;

  int particle_count() const { return static_cast<int>(mass.size()); }
  int spring_count() const { return static_cast<int>(spring_a.size()); }
  bool pinned(int i) const { return inv_mass[i] == 0.0; }
  double ks(int s) const { return materials[spring_material[s]].ks; }
  double kd(int s) const { return materials[spring_material[s]].kd; }
  bool has_colliders() const { return !planes.empty() || !spheres.empty(); }
};

/// Building a model. Particles and springs may be added in any order; finalize() must be called
/// once after the last spring, before the model is simulated.
int add_particle(Model& model, double mass, bool pinned);
int add_material(Model& model, SpringMaterial material);
void add_spring(Model& model, int a, int b, double rest_length, int material);

/// Sorts the springs (by material, then by b - a, then by rest length, then by a), orients them
/// a < b and groups them into spans. The order of springs after this is what every loop uses.
void finalize(Model& model);

/// Parameter changes the app and the command line make (the only ways the model changes).
void set_stiffness(Model& model, double ks);  ///< every material
void set_damping(Model& model, double kd);    ///< every material
void set_pinned(Model& model, int particle, bool pinned);

}  // namespace springlab
