// The Simulation: a model, its state and a method, advanced step by step, with everything a run
// must watch: contacts after each integrator step, divergence, cost, and the energy dissipated.
//
// A step advances the time by dt in `substeps` integrator steps of h = dt / substeps, each
// followed by contacts and then by the emitters' deaths and births (emission.hpp). The app
// and the command line change the scene only through the setters below, each of which tells
// the method that the state it remembers is stale.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "springlab/emission.hpp"
#include "springlab/energy.hpp"
#include "springlab/methods.hpp"
#include "springlab/model.hpp"
#include "springlab/stability.hpp"
#include "springlab/state.hpp"

namespace springlab {

struct SimulationSettings {
  Method method = Method::SymplecticEuler;
  double dt = 0.01;  // s, one step
  int substeps = 1;  // integrator steps per step
  StepSettings step;
  int energy_check_interval = 16;  // steps between divergence checks of the total energy
  bool track_dissipation = false;  // integrate the dissipated power (free with the explicit methods)
};

// NUMERICS.md: a run has diverged when a position or velocity is not finite, or when the total
// energy exceeds 1e6 times the scene's energy scale; an adaptive step below its floor too. The
// kinetic energy is tested every step (cheap), the total every energy_check_interval steps.
inline constexpr double kDivergenceFactor = 1e6;

struct Divergence {
  std::int64_t step = 0;  // the step during which it happened (1-based)
  double t = 0.0;         // time of the last good state kept
  Method method = Method::Euler;
  double h = 0.0;
  double w_max = 0.0;
  double stable_h = 0.0;  // the method's estimated largest stable step
  std::string reason;

  std::string message() const;  // one paragraph for people
};

// "stable up to h = 0.0283 s", "unstable at any step without damping", ...
std::string describe_limit(Method method, double stable_h);

class Simulation {
 public:
  Simulation(Model model, State initial, SimulationSettings settings);

  // One step of dt. Returns false (and does nothing) once the run has diverged; the state is then
  // the last good one.
  bool step();
  // Up to `steps` steps; returns how many were taken.
  std::int64_t advance(std::int64_t steps);

  const Model& model() const { return model_; }
  const State& state() const { return current_; }
  const State& initial_state() const { return initial_; }
  const Emission& emission() const { return emission_; }
  const SimulationSettings& settings() const { return settings_; }
  double h() const { return settings_.dt / settings_.substeps; }
  const Counters& counters() const { return ws_.counters; }
  std::int64_t steps_taken() const { return steps_; }
  const std::optional<Divergence>& divergence() const { return divergence_; }
  bool diverged() const { return divergence_.has_value(); }

  Energy energy() const { return springlab::energy(model_, current_); }
  double energy_scale() const { return energy_scale_; }
  // Energy taken out by spring damping, drag and contacts since the start (J). Only counted
  // with settings.track_dissipation.
  double dissipated() const { return dissipated_; }

  // Highest frequency and the current method's largest stable step, for the current state.
  // Computed when first asked after a change, then cached.
  const StabilityEstimate& stability();
  double stable_step();

  // Changes. Each takes effect at the next step.
  void set_method(Method method);
  void set_dt(double dt);
  void set_substeps(int substeps);
  void set_step_settings(const StepSettings& step);
  // k_s and k_d of the first material; the others keep their ratio to it (a cloth's stretch,
  // shear and bend springs stay in proportion). A ratio from zero sets every material.
  void set_stiffness(double ks);
  void set_damping(double kd);
  void set_gravity(const Vec3& g);
  void set_drag(double drag);
  void set_friction(double mu);  // every collider
  void set_mass(double mass);    // every particle, and the emitters' new ones

  // Dragging a particle: while grabbed it is pinned and moves with the velocity that brings it to
  // the target in `over` seconds of simulated time; released, it keeps that velocity.
  void grab(int particle);
  void move_grabbed(const Vec3& target, double over);
  void release();
  int grabbed() const { return grabbed_; }
  // Puts a particle somewhere at rest (dragging while paused).
  void place(int particle, const Vec3& position);

  // Back to the initial state (and the model as built), keeping the settings.
  void reset();

 private:
  void model_changed();
  void keep_stability();    // model_changed(), keeping the stability estimate (see the .cpp)
  void scaled_stability();  // the same after scaling it, with the step limit made again
  void diverge(std::string reason);

  Model model_;
  // The model as built, for reset(), without its springs: they never change, so the simulation
  // keeps one copy of them (a 512 x 512 cloth's are 28 MB).
  Model initial_model_;
  State initial_, current_, next_;
  Emission emission_;
  SimulationSettings settings_;
  Workspace ws_;
  std::int64_t steps_ = 0;
  std::int64_t substeps_done_ = 0;  // integrator steps since the last change of h
  double t_since_ = 0.0;            // time of that change
  double energy_scale_ = 1.0;
  double dissipated_ = 0.0;
  std::optional<Divergence> divergence_;
  std::optional<StabilityEstimate> stability_;
  std::optional<double> stable_h_;  // for the current method and estimate
  int grabbed_ = -1;
  bool grabbed_was_pinned_ = false;
};

}  // namespace springlab
