// Helpers shared by the tests: loading shipped scenes, running a simulation, small models.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "springlab/exact.hpp"
#include "springlab/forces.hpp"
#include "springlab/scene.hpp"
#include "springlab/simulation.hpp"

namespace springlab::test {

// The table's rows that pass a test of their row (MethodInfo): the tests read the table, so a
// new row is tested where its kind is, with no list to edit.
template <typename Keep>
std::vector<Method> methods_where(Keep keep) {
  std::vector<Method> out;
  for (const MethodInfo& m : methods())
    if (keep(m)) out.push_back(m.id);
  return out;
}
// Explicit with a fixed step: the rows with a finite stability limit.
inline std::vector<Method> explicit_fixed_step() {
  return methods_where([](const MethodInfo& m) { return !m.adaptive() && !m.any_step(); });
}
// Every fixed-step row, implicit included.
inline std::vector<Method> fixed_step() {
  return methods_where([](const MethodInfo& m) { return !m.adaptive(); });
}

// A mass-spring scene's rows for these methods, for Session::choose and set_compare_rows: its
// kind's row k is Method k (app/session/mass_spring_kind.cpp).
inline int method_row(Method method) {
  return static_cast<int>(method);
}
inline std::vector<int> method_rows(const std::vector<Method>& methods) {
  std::vector<int> rows;
  for (Method m : methods) rows.push_back(method_row(m));
  return rows;
}

inline std::string scene_path(const std::string& name) {
  return std::string(SPRINGLAB_SOURCE_DIR) + "/assets/scenes/" + name + ".json";
}

inline Scene shipped(const std::string& name, const std::vector<std::string>& overrides = {}) {
  return load_scene(scene_path(name), overrides);
}

// The RMS over the model's free particles of |a_i - b_i|.
inline double rms_over_free(const Model& model, const Points& a, const Points& b) {
  double sum = 0.0;
  int free = 0;
  for (int i = 0; i < model.particle_count(); ++i) {
    if (model.pinned(i)) continue;
    sum += (a.row(i) - b.row(i)).squaredNorm();
    ++free;
  }
  return free > 0 ? std::sqrt(sum / free) : 0.0;
}

// How far `out` is from the backward-Euler step of h from `in`: the largest |m_i (v1_i - v_i) -
// h f_i(x1, v1)| over the free particles (N s), with the largest |f_i(x1, v1)| beside it.
struct BackwardEulerResidual {
  double worst = 0.0, largest_force = 0.0;
};
inline BackwardEulerResidual backward_euler_residual(const Model& model, const State& in,
                                                     const State& out, double h) {
  Points f;
  SpringForces buffer;
  evaluate_forces(model, out.x, out.v, f, buffer, ForceOutput::Force);
  BackwardEulerResidual r;
  for (int i = 0; i < model.particle_count(); ++i) {
    if (model.pinned(i)) continue;
    r.worst =
        std::max(r.worst, (model.mass[i] * (out.v.row(i) - in.v.row(i)) - h * f.row(i)).norm());
    r.largest_force = std::max(r.largest_force, f.row(i).norm());
  }
  return r;
}

// substeps 0: automatic (a scene's own setting unless it fixes them).
inline Simulation simulation(const Scene& scene, Method method, double dt, int substeps = 1) {
  SimulationSettings s;
  s.method = method;
  s.dt = dt;
  s.substeps = std::max(1, substeps);
  s.auto_substeps = substeps == 0;
  s.safety = scene.safety;
  s.step.tolerance = scene.tolerance;
  return Simulation(scene.model, scene.state, s);
}

// A state in motion: every position moved and every velocity set at random (normal, standard
// deviations dx and dv), so that every spring is stretched and moving and the drag works; the same
// numbers each run.
inline void jitter(State& s, double dx, double dv, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int i = 0; i < s.particle_count(); ++i)
    for (int c = 0; c < 3; ++c) {
      s.x(i, c) += dx * n(rng);
      s.v(i, c) = dv * n(rng);
    }
}

// The reference oscillator of docs/numerics.md ("Accuracy and cost") with optional damping: anchor
// at the origin, unit mass at (1.5, 0, 0), rest length 1, k_s, k_d.
inline Scene oscillator(double ks = 100.0, double kd = 0.0) {
  Scene s = shipped("spring");
  set_stiffness(s.model, ks);
  set_damping(s.model, kd);
  return s;
}

// The test oscillator of docs/numerics.md's "Stability", x'' = -w^2 x - c x', exactly linear at
// any amplitude: the notes' idealised spring (rest length 0), anchor at the origin, the unit mass
// at (0.5, 0, 0). On `spring` itself (rest length 1) a method that pumps the amplitude past 1
// sends the particle through its anchor, where the double well k (|x| - 1)^2 / 2 lowers the
// effective frequency and can stop the growth, so instability is tested on this one.
inline Scene linear_oscillator(double ks = 100.0, double kd = 0.0) {
  Scene s = shipped("spring", {"springs.0.rest_length=0", "particles.1.position=[0.5,0,0]"});
  set_stiffness(s.model, ks);
  set_damping(s.model, kd);
  return s;
}

// Two particles on top of each other (the loader refuses this; a simulation can come to it),
// joined by a spring of rest length 1, k_s, k_d; the first one pinned if `pinned`.
inline Scene coincident_pair(bool pinned, double ks, double kd) {
  Scene s;
  add_particle(s.model, 1.0, pinned);
  add_particle(s.model, 1.0, false);
  add_spring(s.model, 0, 1, 1.0, add_material(s.model, {ks, kd}));
  finalize(s.model);
  s.state.resize(2);
  s.state.x.setZero();
  s.state.v.setZero();
  return s;
}

// Largest over the steps of the RMS over free particles of |x - x_exact| (docs/numerics.md,
// "Accuracy and cost").
inline double error_against_exact(const Scene& scene, Method method, double h, double duration,
                                  double tolerance = 1e-4) {
  const auto exact = ExactOscillator::detect(scene.model, scene.state);
  SimulationSettings s;
  s.method = method;
  s.dt = h;
  s.step.tolerance = tolerance;
  s.audit_fraction = 0.0;  // the error is what is measured, however the energy goes
  Simulation sim(scene.model, scene.state, s);
  const auto steps = static_cast<std::int64_t>(std::llround(duration / h));
  double worst = 0.0;
  for (std::int64_t k = 0; k < steps; ++k) {
    if (!sim.step()) return std::numeric_limits<double>::infinity();
    worst = std::max(worst, rms_over_free(sim.model(), sim.state().x, exact->at(sim.state().t).x));
  }
  return worst;
}

}  // namespace springlab::test
