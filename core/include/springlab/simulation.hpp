// The Simulation: a model, its state and a method, advanced step by step, with everything a run
// must watch: contacts after each integrator step, divergence, cost, and the energy dissipated.
//
// A step advances the time by dt in `substeps` integrator steps of h = dt / substeps, each
// followed by contacts and then by the emitters' deaths and births (emission.hpp). The app
// and the command line change the scene only through the setters below, each of which tells
// the method that the state it remembers is stale.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "springlab/emission.hpp"
#include "springlab/energy.hpp"
#include "springlab/energy_audit.hpp"
#include "springlab/methods.hpp"
#include "springlab/model.hpp"
#include "springlab/stability.hpp"
#include "springlab/state.hpp"

namespace springlab {

struct ContactResult;  // colliders.hpp

/// The energy audit (energy_audit.hpp): a rise of the net energy counts only beyond what a stable
/// step allows plus this fraction of the scene's energy scale (rounding, contacts' pushes).
inline constexpr double kAuditFraction = 1e-3;

/// How a Simulation steps: its method, step and sub-steps, and what it watches (plain values
/// with defaults; the app and the command line own them and pass them in).
struct SimulationSettings {
  Method method = Method::SymplecticEuler;
  double dt = 0.01;  ///< s, one step
  int substeps = 1;  ///< integrator steps per step (chosen, with auto_substeps)
  /// Automatic sub-steps (stability.hpp, choose_substeps): the fewest that keep h within `safety`
  /// of the method's stated limit, chosen again whenever the analysis is made again (the scene
  /// changed: k_s, mass, pins...) and when the method or dt change.
  bool auto_substeps = false;
  double safety = kSafeFraction;
  /// A step that needs the analysis (automatic sub-steps, the audit) makes it there and then; the
  /// app instead makes it on a worker thread and hands it over (set_stability), stepping on
  /// meanwhile: automatic sub-steps come first from a quick bound (stability.hpp, quick_limit),
  /// then from the analysis when it arrives.
  bool analyse_when_needed = true;
  StepSettings step;
  int energy_check_interval = 16;  ///< steps between divergence checks of the total energy
  bool track_dissipation =
      false;  ///< integrate the dissipated power (free with the explicit methods)
  /// The audit's floor as a fraction of the energy scale (0: no audit). Which methods it watches,
  /// and why: Simulation::audited().
  double audit_fraction = kAuditFraction;
  /// What a finding does: stops the run as a divergence (`run`), or is only reported
  /// (Simulation::instability()) while the run goes on: the app keeps an unstable lane moving,
  /// marked, so that the class sees where it goes; a sweep measures the error over the whole run.
  bool audit_stops = true;
  /// The audit's window in seconds (energy_audit.hpp; tests shorten it to see the audit at work
  /// within a run a budget cuts short).
  double audit_window = EnergyAudit::kWindow;
  /// A step from outside the method table (a student's own, from Python: springlab.homework),
  /// taken instead of `method`'s row, which then only stands for the scene's defaults. Nothing
  /// that needs a row's theory reads it (no stability analysis explains its divergence, no audit
  /// watches it, sub-steps stay as set); the divergence tests watch it as any step. It counts its
  /// force evaluations through `ws` (accelerations(), methods.hpp). Named `own_step_name`.
  std::function<void(const Model& model, const State& in, State& out, double h, Workspace& ws)>
      own_step;
  std::string own_step_name;
};

/// A scene's own settings: its first method, its step, its sub-steps (automatic unless it fixes
/// them) and safe fraction, its tolerance.
struct Scene;
SimulationSettings settings_for(const Scene& scene);

/// docs/numerics.md, "Divergence": a run has diverged when a position or velocity is not finite, or
/// when the total energy exceeds 1e6 times the scene's energy scale; an adaptive step below its
/// floor too. The kinetic energy is tested every step (cheap), the total every
/// energy_check_interval steps. The audit (above) reports a run that went numerically unstable the
/// same way, even when the growth saturates and nothing becomes infinite.
inline constexpr double kDivergenceFactor = 1e6;
/// Scenes with at most this many particles and springs have their total energy checked every step.
inline constexpr int kSmallScene = 512;

/// How a run diverged or went numerically unstable, and the stability analysis's word on it.
struct Divergence {
  std::int64_t step = 0;  ///< the step during which it happened (1-based)
  double t = 0.0;         ///< time of the last good state kept
  Method method = Method::Euler;
  double h = 0.0;
  /// The stability analysis's word on it (once analysed: Simulation::explain_divergence()).
  bool analysed = false;
  double w_max = 0.0;
  double stable_h = 0.0;  ///< the method's largest stable step (limit.h)
  StabilityLimit limit;
  /// Caught by the energy audit (energy_audit.hpp): what it found.
  bool unstable = false;
  /// Not a blow-up: the method's own equations were not solved at this step (SolveFailure), a
  /// stage of an implicit tableau whose Newton iteration did not converge.
  bool unsolved = false;
  EnergyAudit::Finding audit;
  std::string reason;
  std::string own_step;  ///< the name of a step from outside the table, if it was one

  std::string message() const;  ///< one paragraph for people
};

/// The Simulation: a model, its state and a method, advanced step by step, with everything a run
/// must watch: contacts after each integrator step, divergence, cost, the energy dissipated and
/// the energy audit. A step advances the time by dt in `substeps` integrator steps of
/// h = dt / substeps. The app and the command line change the scene only through its setters.
class Simulation {
 public:
  Simulation(Model model, State initial, SimulationSettings settings);

  /// One step of dt. Returns false (and does nothing) once the run has diverged; the state is then
  /// the last good one. Does nothing either while it is not ready() (the app's lane waits).
  bool step();
  /// Up to `steps` steps; returns how many were taken.
  std::int64_t advance(std::int64_t steps);

  const Model& model() const { return model_; }
  const State& state() const { return current_; }
  const Emission& emission() const { return emission_; }
  const SimulationSettings& settings() const { return settings_; }
  double h() const { return settings_.dt / settings_.substeps; }
  const Counters& counters() const { return ws_.counters; }
  /// An adaptive method's internal step, as its controller last chose it (0 before the first).
  double adaptive_step() const { return ws_.adaptive_step; }
  std::int64_t steps_taken() const { return steps_; }
  const std::optional<Divergence>& divergence() const { return divergence_; }
  /// The same with the stability analysis's limit in it (made now if it was not kept).
  const std::optional<Divergence>& explain_divergence();
  bool diverged() const { return divergence_.has_value(); }

  Energy energy() const { return springlab::energy(model_, current_); }
  double energy_scale() const { return energy_scale_; }
  /// Energy taken out by spring damping, drag and contacts since the start (J). Only counted
  /// with settings.track_dissipation.
  double dissipated() const { return dissipated_; }

  /// The stability analysis of the scene as it is now (stability.hpp), and the current method's
  /// limit from it. Computed when first asked after a change (or given, by set_stability, from
  /// an analysis made elsewhere, e.g. on a worker thread), then kept.
  const StabilityAnalysis& stability();
  const StabilityLimit& stability_limit() { return stability().limit(settings_.method); }
  double stable_step() { return stability_limit().h; }
  bool has_stability() const { return stability_ != nullptr; }
  void set_stability(std::shared_ptr<const StabilityAnalysis> analysis);
  std::shared_ptr<const StabilityAnalysis> stability_if_any() const { return stability_; }
  /// Automatic sub-steps: whether on, and whether the choice reached kMaxAutoSubsteps.
  bool auto_substeps() const { return settings_.auto_substeps; }
  bool substeps_capped() const { return substeps_capped_; }
  /// Automatic sub-steps chosen from the quick bound while the analysis is awaited.
  bool substeps_provisional() const { return provisional_; }
  /// Whether a step can be taken now without the analysis: false only for automatic sub-steps
  /// with neither the analysis nor a quick bound that tells (the app's lane waits).
  bool ready() const {
    return !settings_.auto_substeps || stability_ || provisional_ || settings_.analyse_when_needed;
  }
  void set_analyse_when_needed(bool on);
  /// The model and state an analysis must be made from to be the one stability() would make.
  /// Changes every time the model or the pinning changes (a counter, compared by the app).
  std::uint64_t model_version() const { return model_version_; }

  /// The work done from outside since the start (J): drags, parameter changes, births and deaths,
  /// contacts' pushes, fields. The net energy E - E0 - W never rises in the physics.
  double external_work() const { return external_; }
  double net_energy() const { return energy().total() - baseline_; }
  /// The energy audit's finding as a report (unstable, with the limit once analysed), kept whether
  /// or not it stopped the run (settings.audit_stops).
  const std::optional<Divergence>& instability() const { return instability_; }
  /// The audit's windows closed since it last started again (0: it has not looked yet).
  std::int64_t audit_windows() const { return audit_.windows(); }
  /// What is wrong with the run, if anything: its divergence, else the audit's report.
  const Divergence* trouble() const {
    return divergence_ ? &*divergence_ : instability_ ? &*instability_ : nullptr;
  }
  /// What the audit allows at the current step and method (computed from the analysis when first
  /// asked after a change).
  const EnergyAudit::Allowance& audit_allowance();

  // Changes. Each takes effect at the next step.
  void set_method(Method method);
  /// A step of one's own (SimulationSettings::own_step) in place of the row's, from the next step;
  /// `method` stays the row that stands for it. An empty step goes back to the row.
  void set_own_step(
      std::function<void(const Model&, const State&, State&, double, Workspace&)> step,
      std::string name);
  void set_dt(double dt);
  void set_substeps(int substeps);  ///< fixes them (automatic sub-steps off)
  void set_auto_substeps(double safety = kSafeFraction);
  void set_step_settings(const StepSettings& step);
  /// k_s and k_d of the first material; the others keep their ratio to it (a cloth's stretch,
  /// shear and bend springs stay in proportion). A ratio from zero sets every material.
  void set_stiffness(double ks);
  void set_damping(double kd);
  void set_gravity(const Vec3& g);
  void set_drag(double drag);
  void set_verlet_damping(double d);  ///< position Verlet's factor d (Model::verlet_damping)
  void set_friction(double mu);       ///< every collider
  void set_mass(double mass);         ///< every particle, and the emitters' new ones

  /// Dragging a particle: while grabbed it is pinned and moves with the velocity that brings it to
  /// the target in `over` seconds of simulated time; released, it keeps that velocity.
  void grab(int particle);
  void move_grabbed(const Vec3& target, double over);
  void release();
  int grabbed() const { return grabbed_; }
  /// Puts a particle somewhere at rest (dragging while paused).
  void place(int particle, const Vec3& position);

  /// Back to the initial state (and the model as built), keeping the settings.
  void reset();

 private:
  void model_changed();
  // step()'s stages, in order (simulation.cpp says what each does and when it ends the run).
  bool ready_to_step();
  bool integrate(double h);
  bool still_bounded();
  void advance_clock(double h);
  void count_outside_work(double h, const ContactResult& contact);
  void emit(bool outside);
  bool check_energy(bool audit);
  void choose_substeps();
  void substeps_changed(int substeps);
  // Runs `change`, counting the jump in the total energy it makes as work done from outside.
  template <typename Change>
  void from_outside(const Change& change);
  bool audited() const;
  void audit(double total);
  void audit_changed();  // the step, the method or the model changed: the audit starts again
  void diverge(std::string reason);
  Divergence report(std::string reason) const;
  void explain(Divergence& d);

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
  std::shared_ptr<const StabilityAnalysis> stability_;
  std::uint64_t model_version_ = 0;
  int grabbed_ = -1;
  bool grabbed_was_pinned_ = false;
  std::vector<int> grabbed_springs_;  // the springs of the held particle (its drag's work)
  // The audit: the initial energy plus the work done from outside, and that work alone.
  double baseline_ = 0.0, external_ = 0.0;
  EnergyAudit audit_;
  std::optional<EnergyAudit::Allowance> allowance_;  // for the current step, method and analysis
  std::optional<Divergence> instability_;
  bool has_stiffness_ = false;
  bool substeps_capped_ = false;
  bool provisional_ = false;  // the sub-steps come from quick_limit()
  bool quick_tried_ = false;  // since the last change: quick_limit() could not tell
};

}  // namespace springlab
