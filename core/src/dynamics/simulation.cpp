#include "springlab/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "springlab/colliders.hpp"
#include "springlab/scene.hpp"
#include "springlab/spring_kernel.hpp"
#include "springlab/text.hpp"

namespace springlab {

namespace {
// A model's spring arrays, moved out and back in (a moved-from vector is empty). Moving keeps
// their buffers, and with them what the force pass and the implicit solver planned for them.
struct SpringArrays {
  std::vector<std::int32_t> a, b;
  std::vector<double> rest;
  std::vector<std::uint16_t> material;
  std::vector<SpringSpan> spans;
};
SpringArrays take_springs(Model& m) {
  return {std::move(m.spring_a), std::move(m.spring_b), std::move(m.rest_length),
          std::move(m.spring_material), std::move(m.spans)};
}
void put_springs(Model& m, SpringArrays&& s) {
  m.spring_a = std::move(s.a);
  m.spring_b = std::move(s.b);
  m.rest_length = std::move(s.rest);
  m.spring_material = std::move(s.material);
  m.spans = std::move(s.spans);
}

}  // namespace

SimulationSettings settings_for(const Scene& scene) {
  SimulationSettings s;
  s.method = scene.methods.front();
  s.dt = scene.dt;
  s.auto_substeps = scene.substeps == 0;
  s.substeps = std::max(1, scene.substeps);
  s.safety = scene.safety;
  s.step.tolerance = scene.tolerance;
  return s;
}

std::string Divergence::message() const {
  // (Each piece through tr(): the app shows this in its language; the command line in English.)
  const char* name = own_step.empty() ? method_info(method).name : own_step.c_str();
  if (unsolved)
    // The solver's failure, not the method's instability: no limit to state, nothing diverged.
    return format_text(
        tr("stopped during step %lld (last good state at t = %.4g s): %s. Method %s, h = %.4g s: "
           "the "
           "method's own equations were not solved at this step (the state did not blow up). Try a "
           "smaller --dt or more --substeps."),
        static_cast<long long>(step), t, reason.c_str(), name, h);
  std::string s = format_text(
      unstable ? tr("went numerically unstable during step %lld (last good state at t = %.4g s): "
                    "%s. Method %s, h = %.4g s")
               : tr("diverged during step %lld (last good state at t = %.4g s): %s. Method %s, "
                    "h = %.4g s"),
      static_cast<long long>(step), t, reason.c_str(), name, h);
  if (analysed)
    s += format_text(tr(", h w_max = %.4g (w_max = %.4g rad/s); limit: %s"), h * w_max, w_max,
                     describe(limit).c_str());
  if (analysed && limit.mode && std::isfinite(limit.h) && limit.h > 0.0)
    s += format_text(tr(", set by a mode of %.4g rad/s with damping ratio %.4g"), limit.mode->w,
                     limit.mode->damping_ratio());
  if (!own_step.empty())
    return s +
           tr(". A step of your own has no stated limit: try a smaller --dt or more --substeps.");
  if (analysed && limit.h == 0.0)
    s +=
        tr(". No step is small enough: try a method stable without damping (symplectic-euler, "
           "verlet, rk4, "
           "implicit-euler), or more damping.");
  else
    s += tr(". Try a smaller --dt, more --substeps, or a more stable --method (implicit-euler).");
  return s;
}

Simulation::Simulation(Model model, State initial, SimulationSettings settings)
    : model_(std::move(model)),
      initial_(std::move(initial)),
      settings_(std::move(settings)),
      audit_(settings_.audit_window) {
  SpringArrays springs = take_springs(model_);
  initial_model_ = model_;
  put_springs(model_, std::move(springs));
  reset();
}

void Simulation::reset() {
  SpringArrays springs = take_springs(model_);
  model_ = initial_model_;
  put_springs(model_, std::move(springs));
  current_ = initial_;
  emission_ = Emission();
  if (!model_.emitters.empty()) {
    emission_ = Emission(model_, current_);
    emission_.update(model_, current_);  // the births due at the start
  }
  next_ = current_;
  ws_ = Workspace();
  steps_ = 0;
  substeps_done_ = 0;
  t_since_ = current_.t;
  dissipated_ = 0.0;
  divergence_.reset();
  stability_.reset();
  provisional_ = quick_tried_ = false;
  ++model_version_;
  grabbed_ = -1;
  grabbed_springs_.clear();
  energy_scale_ = springlab::energy_scale(model_, current_);
  has_stiffness_ = false;
  for (const SpringMaterial& m : model_.materials) has_stiffness_ |= m.ks > 0.0;
  baseline_ = energy().total();
  external_ = 0.0;
  instability_.reset();
  audit_changed();
  choose_substeps();
}

// The audit looks for instabilities that saturate as well as those that blow up: those of the
// methods that damping makes stable (explicit Euler, midpoint, modified Euler: past their limits
// a mode grows at a rate proportional to how far past, and may settle into a buzz), RK4 (whose
// damped limit cycles it catches) and implicit Euler (a solve that did not converge could put
// energy in). Symplectic Euler and Verlet fail fast past their limits (their roots leave the unit
// disc through -1, at a rate growing like the square root of how far past), which the divergence
// test sees, and their step has no energy norm of its own to bound (Verlet keeps a history).
// Scenes without springs have no oscillating modes (the energy a method gains in free flight and
// bounces is first-order error, not instability), and the adaptive methods control their own
// steps. A held particle is moved by the user, not the method: the audit waits for its release.
bool Simulation::audited() const {
  const Method m = settings_.method;
  return settings_.audit_fraction > 0.0 && method_info(m).audited && has_stiffness_ &&
         grabbed_ < 0 && !settings_.own_step;
}

void Simulation::audit_changed() {
  audit_.reset();
  allowance_.reset();
}

template <typename Change>
void Simulation::from_outside(const Change& change) {
  const double before = energy().total();
  change();
  const double work = energy().total() - before;
  if (std::isfinite(work)) {
    baseline_ += work;
    external_ += work;
  }
}

const EnergyAudit::Allowance& Simulation::audit_allowance() {
  if (!allowance_) {
    const StabilityAnalysis& analysis = stability();
    allowance_ = EnergyAudit::Allowance{
        analysis.transient_growth(settings_.method, h(), method_parameters(model_)).factor,
        analysis.lowest_energy()};
  }
  return *allowance_;
}

void Simulation::audit(double total) {
  if (!audited()) return;
  const double floor = settings_.audit_fraction * energy_scale_;
  audit_.record(current_.t, steps_, total - baseline_, total, floor);
  if (!audit_.pending() || instability_) return;
  // A window rose above an earlier low: beyond what a stable step allows? (The analysis says; in
  // the app it is made on a worker thread, and the windows wait for it.)
  if (!stability_ && !settings_.analyse_when_needed) return;
  const EnergyAudit::Allowance& allowance = audit_allowance();
  const std::optional<EnergyAudit::Finding> found = audit_.decide(allowance, floor);
  if (!found) return;
  std::string reason = format_text(
      tr("the energy (less the work done on the scene) rose by %.4g J in %.4g s from its "
         "low at t = %.4g s, where no stable step raises it by more than %.4g J ("),
      found->rise, current_.t - found->low_t, found->low_t, found->allowed);
  if (found->growth > 1.0)
    reason += format_text(
        tr("its stable modes' energy grows at most x%.4g at this step: twice %.4g of the %.4g J of "
           "motion there, plus "),
        found->growth, found->growth - 1.0, found->motion);
  else
    reason += tr("no stable mode's energy can grow at this step; only rounding, ");
  reason += format_text(tr("%g of the scene's energy scale of %.4g J)"), settings_.audit_fraction,
                        energy_scale_);
  Divergence d = report(reason);
  d.unstable = true;
  d.audit = *found;
  explain(d);  // the analysis is there: it gave the allowance
  instability_ = d;
  if (settings_.audit_stops) divergence_ = std::move(d);
}

// One step of dt, as named stages (a stage that ends the run returns false, the divergence set):
//   ready_to_step    automatic sub-steps chosen, or the lane waits for its analysis
//   then per sub-step of h:
//     integrate          the method's step (or one's own) from current_ into next_
//     still_bounded      next_ finite, its kinetic energy within 1e6 times the scene's scale
//     advance_clock      next_.t = t_since_ + n h, no drift from adding h over and over
//     resolve_contacts   colliders push particles out (the workspace forgets what it derived)
//     count_outside_work what contacts, fields, wind and a held particle put in or took, and what
//                        damping dissipated (for the net energy and the audit), at current_
//     (swap)             next_ becomes current_
//     emit               an emitter's births and deaths
//   check_energy     the total energy (every step on a small scene) and the audit
bool Simulation::step() {
  if (divergence_) return false;
  if (!ready_to_step()) return true;  // nothing tells a safe step yet: wait
  const double h = this->h();
  const bool audit = audited();
  const bool outside =
      settings_.track_dissipation || audit;  // the work from outside, for the net energy
  ws_.measure_power = settings_.track_dissipation;
  for (int k = 0; k < settings_.substeps; ++k) {
    if (!integrate(h) || !still_bounded()) return false;
    advance_clock(h);
    const ContactResult contact = resolve_contacts(model_, next_);
    if (contact.contacts > 0) ws_.invalidate();
    if (outside) count_outside_work(h, contact);
    std::swap(current_, next_);
    if (!emission_.empty()) emit(outside);
  }
  ++steps_;
  return check_energy(audit);
}

bool Simulation::ready_to_step() {
  if (settings_.auto_substeps && !stability_) {
    if (settings_.analyse_when_needed)
      stability();  // chooses them
    else if (!provisional_)
      choose_substeps();  // from the quick bound, while it comes
    return ready();
  }
  return true;
}

bool Simulation::integrate(double h) {
  try {
    if (settings_.own_step)
      settings_.own_step(model_, current_, next_, h, ws_);
    else
      springlab::step(settings_.method, model_, current_, next_, h, settings_.step, ws_);
  } catch (const SolveFailure& failure) {
    ++steps_;
    divergence_ = report(failure.what());
    divergence_->unsolved = true;
    return false;
  } catch (const StepFailure& failure) {
    ++steps_;
    diverge(failure.what());
    return false;
  }
  return true;
}

bool Simulation::still_bounded() {
  // One pass over the particles: finite, and the kinetic part of the energy test, every step,
  // so that a blow-up is stopped near where it starts. The whole energy is checked by check_energy.
  const StepProbe check = ws_.step_probe ? *ws_.step_probe : probe(model_, next_);
  if (!check.finite) {
    ++steps_;
    diverge(tr("a position or velocity became infinite or NaN"));
    return false;
  }
  if (!(check.kinetic <= kDivergenceFactor * energy_scale_)) {
    ++steps_;
    std::swap(current_, next_);  // still finite: kept, as the state where it was caught
    diverge(format_text(tr("the kinetic energy reached %.4g J, more than 1e6 times the scene's "
                           "energy scale (%.4g J)"),
                        check.kinetic, energy_scale_));
    return false;
  }
  return true;
}

void Simulation::advance_clock(double h) {
  // Time as a multiple of h since h last changed: no drift from adding h over and over.
  next_.t = t_since_ + static_cast<double>(++substeps_done_) * h;
}

void Simulation::count_outside_work(double h, const ContactResult& contact) {
  // Work from outside: contacts push particles out of colliders (raising their potential), a
  // swirl or a wind puts energy in (the charts count them with what damping takes), and a held
  // particle's prescribed motion does work on the rest through its springs: -f . v, f their
  // force on it.
  const double pushed = contact.potential_gained +
                        (model_.attractors.empty() ? 0.0 : h * field_power(model_, current_));
  // A wind's work through the drag (which the dissipated power already nets out).
  const double blown = h * wind_power(model_, current_);
  baseline_ += pushed + blown;
  external_ += pushed + blown;
  // The power at the step's start (the explicit methods measured it in their force pass), over
  // h, and what contacts took.
  if (settings_.track_dissipation)
    dissipated_ += h * (ws_.input_power ? *ws_.input_power : dissipation_power(model_, current_)) +
                   contact.kinetic_lost - pushed;
  if (grabbed_ >= 0) {
    const double work = -h * held_force(model_, current_, grabbed_, grabbed_springs_)
                                 .dot(current_.v.row(grabbed_).transpose());
    baseline_ += work;
    external_ += work;
  }
}

void Simulation::emit(bool outside) {
  bool changed = false;
  const auto births_and_deaths = [&] { changed = emission_.update(model_, current_); };
  if (outside)
    from_outside(births_and_deaths);
  else
    births_and_deaths();
  if (changed) {
    ws_.invalidate();
    // A held particle whose time is up is let go of: it is no longer there.
    if (grabbed_ >= 0 && !model_.emitters.empty() && !emission_.alive(grabbed_) &&
        emission_.owned(grabbed_))
      grabbed_ = -1;
  }
}

bool Simulation::check_energy(bool audit) {
  // A small scene is checked every step: a pass over it costs little, and its energy, often all
  // in one mode, oscillates within a few steps near a symplectic method's limit; the audit needs
  // those oscillations sampled to see through them.
  const int interval = model_.particle_count() + model_.spring_count() <= kSmallScene
                           ? 1
                           : settings_.energy_check_interval;
  if (settings_.energy_check_interval > 0 && steps_ % interval == 0) {
    const double total = energy().total();
    if (!(std::abs(total) <= kDivergenceFactor * energy_scale_)) {
      diverge(format_text(tr("the total energy reached %.4g J, more than 1e6 times the scene's "
                             "energy scale (%.4g J)"),
                          total, energy_scale_));
      return false;
    }
    if (audit) {
      this->audit(total);
      if (divergence_) return false;
    }
  }
  return true;
}

std::int64_t Simulation::advance(std::int64_t steps) {
  std::int64_t taken = 0;
  while (taken < steps && step()) ++taken;
  return taken;
}

Divergence Simulation::report(std::string reason) const {
  Divergence d;
  d.step = steps_;
  d.t = current_.t;
  d.method = settings_.method;
  d.own_step = settings_.own_step ? settings_.own_step_name : std::string();
  d.h = h();
  d.reason = std::move(reason);
  return d;
}

void Simulation::diverge(std::string reason) {
  divergence_ = report(std::move(reason));
  // The limit, from the analysis if there is one already (a large scene's takes seconds, which
  // a batch of runs or the app's frame loop should not wait for): explain_divergence() makes it.
  if (stability_) explain_divergence();
}

void Simulation::explain(Divergence& d) {
  if (d.analysed || settings_.own_step) return;  // no row, no theory to explain it by
  // The analysis of the scene as it is (kept, or made from the last good state, which is finite).
  const StabilityAnalysis& analysis = stability();
  d.w_max = analysis.w_max();
  d.limit = analysis.limit(settings_.method);
  d.stable_h = d.limit.h;
  d.analysed = true;
}

const std::optional<Divergence>& Simulation::explain_divergence() {
  if (divergence_) explain(*divergence_);
  return divergence_;
}

const StabilityAnalysis& Simulation::stability() {
  if (!stability_) {
    stability_ = std::make_shared<const StabilityAnalysis>(model_, current_);
    choose_substeps();
  }
  return *stability_;
}

void Simulation::set_stability(std::shared_ptr<const StabilityAnalysis> analysis) {
  stability_ = std::move(analysis);
  allowance_.reset();
  choose_substeps();
}

void Simulation::choose_substeps() {
  if (!settings_.auto_substeps) return;
  StabilityLimit limit;
  if (stability_) {
    limit = stability_->limit(settings_.method);
    provisional_ = false;
  } else {
    // Awaiting the analysis (made elsewhere): the quick bound, if it tells, meanwhile.
    provisional_ = false;
    if (settings_.analyse_when_needed || quick_tried_) return;
    limit = quick_limit(settings_.method, model_, current_);
    quick_tried_ = true;
    if (!(limit.h > 0.0)) return;
    provisional_ = true;
  }
  const SubstepChoice choice = springlab::choose_substeps(limit, settings_.dt, settings_.safety);
  substeps_capped_ = choice.capped;
  if (choice.substeps != settings_.substeps) substeps_changed(choice.substeps);
}

void Simulation::substeps_changed(int substeps) {
  settings_.substeps = substeps;
  t_since_ = current_.t;
  substeps_done_ = 0;
  ws_.invalidate();
  audit_changed();  // a new step: what a stable run may do changes
}

void Simulation::model_changed() {
  ws_.invalidate();
  stability_.reset();
  provisional_ = quick_tried_ = false;
  ++model_version_;
  audit_changed();
  choose_substeps();  // from the quick bound, where the analysis is made elsewhere
}

void Simulation::set_analyse_when_needed(bool on) {
  settings_.analyse_when_needed = on;
  choose_substeps();
}

void Simulation::set_own_step(
    std::function<void(const Model&, const State&, State&, double, Workspace&)> step,
    std::string name) {
  settings_.own_step = std::move(step);
  settings_.own_step_name = settings_.own_step ? std::move(name) : std::string();
  audit_changed();
  ws_.invalidate();
}

void Simulation::set_method(Method method) {
  settings_.method = method;
  settings_.own_step = nullptr;  // a row of the table from now on
  quick_tried_ = false;
  audit_changed();  // a new step: what a stable run may do changes
  ws_.invalidate();
  ws_.adaptive_step = 0.0;
  choose_substeps();
}

void Simulation::set_dt(double dt) {
  settings_.dt = dt;
  quick_tried_ = false;
  audit_changed();
  t_since_ = current_.t;
  substeps_done_ = 0;
  ws_.invalidate();
  choose_substeps();
}

void Simulation::set_substeps(int substeps) {
  settings_.auto_substeps = false;
  substeps_capped_ = false;
  substeps_changed(substeps);
}

void Simulation::set_auto_substeps(double safety) {
  settings_.auto_substeps = true;
  settings_.safety = safety;
  choose_substeps();
}

void Simulation::set_step_settings(const StepSettings& step) {
  settings_.step = step;
}

// k_s and k_d of the first material; the others keep their ratio to it. Each change of the
// model counts the jump in energy it makes as work from outside (the audit), and makes the
// stability analysis again when next asked (the equilibrium sags with k_s, w_max scales).
void Simulation::set_stiffness(double ks) {
  if (model_.materials.empty()) return;
  from_outside([&] {
    const double first = model_.materials.front().ks;
    if (!(first > 0.0))
      springlab::set_stiffness(model_, ks);
    else
      for (auto& m : model_.materials) m.ks *= ks / first;
  });
  model_changed();
}

void Simulation::set_damping(double kd) {
  if (model_.materials.empty()) return;
  const double first = model_.materials.front().kd;
  if (!(first > 0.0))
    springlab::set_damping(model_, kd);
  else
    for (auto& m : model_.materials) m.kd *= kd / first;
  model_changed();
}

void Simulation::set_gravity(const Vec3& g) {
  from_outside([&] { model_.gravity = g; });
  model_changed();  // the equilibrium's tension follows gravity
}

void Simulation::set_drag(double drag) {
  model_.drag = drag;
  model_changed();
}

void Simulation::set_verlet_damping(double d) {
  model_.verlet_damping = d;
  model_changed();
}

void Simulation::set_friction(double mu) {
  for (auto& p : model_.planes) p.friction = mu;
  for (auto& s : model_.spheres) s.friction = mu;
  ws_.invalidate();  // friction is not in the stability analysis (colliders are left out)
}

void Simulation::set_mass(double mass) {
  from_outside([&] {
    for (Emitter& e : model_.emitters) {
      e.spawn.mass = mass;
      if (e.burst) e.burst->spawn.mass = mass;
    }
    for (int i = 0; i < model_.particle_count(); ++i) {
      model_.mass[i] = mass;
      if (!model_.pinned(i)) model_.inv_mass[i] = 1.0 / mass;
    }
  });
  model_changed();
}

void Simulation::grab(int particle) {
  release();
  from_outside([&] {
    grabbed_ = particle;
    // Remember whether it was pinned by the scene: it is pinned for as long as it is held.
    grabbed_was_pinned_ = model_.pinned(particle);
    set_pinned(model_, particle, true);
    current_.v.row(particle).setZero();
  });
  grabbed_springs_.clear();
  for (int s = 0; s < model_.spring_count(); ++s)
    if (model_.spring_a[s] == particle || model_.spring_b[s] == particle)
      grabbed_springs_.push_back(s);
  model_changed();
}

void Simulation::move_grabbed(const Vec3& target, double over) {
  if (grabbed_ < 0 || !(over > 0.0)) return;
  current_.v.row(grabbed_) = (target.transpose() - current_.x.row(grabbed_)) / over;
  ws_.invalidate();
}

void Simulation::place(int particle, const Vec3& position) {
  from_outside([&] {
    current_.x.row(particle) = position.transpose();
    current_.v.row(particle).setZero();
  });
  model_changed();
}

void Simulation::release() {
  if (grabbed_ < 0) return;
  from_outside([&] {
    if (!grabbed_was_pinned_)
      set_pinned(model_, grabbed_, false);
    else
      current_.v.row(grabbed_).setZero();
  });
  grabbed_ = -1;
  grabbed_springs_.clear();
  model_changed();
}

}  // namespace springlab
