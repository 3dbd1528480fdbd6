#include "springlab/simulation.hpp"

#include <cmath>
#include <sstream>
#include <utility>

#include "springlab/colliders.hpp"

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
  return {std::move(m.spring_a), std::move(m.spring_b), std::move(m.rest_length), std::move(m.spring_material),
          std::move(m.spans)};
}
void put_springs(Model& m, SpringArrays&& s) {
  m.spring_a = std::move(s.a);
  m.spring_b = std::move(s.b);
  m.rest_length = std::move(s.rest);
  m.spring_material = std::move(s.material);
  m.spans = std::move(s.spans);
}

std::string format(double value) {
  std::ostringstream s;
  s.precision(4);
  s << value;
  return s.str();
}
}  // namespace

std::string describe_limit(Method method, double stable_h) {
  if (std::isnan(stable_h)) return "the method chooses its own step sizes";
  if (std::isinf(stable_h)) return "stable at any step";
  if (stable_h == 0.0)
    return std::string(method == Method::Euler || method == Method::ModifiedEuler ||
                               method == Method::Midpoint
                           ? "unstable at any step (not enough damping)"
                           : "unstable at any step");
  return "stable up to h = " + format(stable_h) + " s";
}

std::string Divergence::message() const {
  std::ostringstream s;
  s << "diverged during step " << step << " (last good state at t = " << format(t)
    << " s): " << reason << ". Method " << method_info(method).name << ", h = " << format(h)
    << " s, h w_max = " << format(h * w_max) << " (w_max = " << format(w_max)
    << " rad/s); estimated limit: " << describe_limit(method, stable_h)
    << ". Try a smaller --dt, more --substeps, or a more stable --method (implicit-euler).";
  return s.str();
}

Simulation::Simulation(Model model, State initial, SimulationSettings settings)
    : model_(std::move(model)), initial_(std::move(initial)), settings_(settings) {
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
  stable_h_.reset();
  grabbed_ = -1;
  energy_scale_ = springlab::energy_scale(model_, current_);
}

bool Simulation::step() {
  if (divergence_) return false;
  const double h = this->h();
  ws_.measure_power = settings_.track_dissipation;
  for (int k = 0; k < settings_.substeps; ++k) {
    try {
      springlab::step(settings_.method, model_, current_, next_, h, settings_.step, ws_);
    } catch (const StepFailure& failure) {
      ++steps_;
      diverge(failure.what());
      return false;
    }
    // One pass over the particles: finite, and the kinetic part of the energy test, every step,
    // so that a blow-up is stopped near where it starts. The whole energy is checked below.
    const StepProbe check = ws_.step_probe ? *ws_.step_probe : probe(model_, next_);
    if (!check.finite) {
      ++steps_;
      diverge("a position or velocity became infinite or NaN");
      return false;
    }
    const double kinetic = check.kinetic;
    if (!(kinetic <= kDivergenceFactor * energy_scale_)) {
      ++steps_;
      std::swap(current_, next_);  // still finite: kept, as the state where it was caught
      std::ostringstream reason;
      reason << "the kinetic energy reached " << format(kinetic) << " J, more than 1e6 times the "
             << "scene's energy scale (" << format(energy_scale_) << " J)";
      diverge(reason.str());
      return false;
    }
    // Time as a multiple of h since h last changed: no drift from adding h over and over.
    next_.t = t_since_ + static_cast<double>(++substeps_done_) * h;
    const ContactResult contact = resolve_contacts(model_, next_);
    if (contact.contacts > 0) ws_.invalidate();
    // The power at the step's start (the explicit methods measured it in their force pass), over h.
    if (settings_.track_dissipation)
      dissipated_ += h * (ws_.input_power ? *ws_.input_power : dissipation_power(model_, current_)) +
                     contact.kinetic_lost;
    std::swap(current_, next_);
    if (!emission_.empty() && emission_.update(model_, current_)) {
      ws_.invalidate();
      // A held particle whose time is up is let go of: it is no longer there.
      if (grabbed_ >= 0 && !model_.emitters.empty() && !emission_.alive(grabbed_) && emission_.owned(grabbed_))
        grabbed_ = -1;
    }
  }
  ++steps_;
  if (settings_.energy_check_interval > 0 && steps_ % settings_.energy_check_interval == 0) {
    const double total = energy().total();
    if (!(std::abs(total) <= kDivergenceFactor * energy_scale_)) {
      std::ostringstream reason;
      reason << "the total energy reached " << format(total) << " J, more than 1e6 times the "
             << "scene's energy scale (" << format(energy_scale_) << " J)";
      diverge(reason.str());
      return false;
    }
  }
  return true;
}

std::int64_t Simulation::advance(std::int64_t steps) {
  std::int64_t taken = 0;
  while (taken < steps && step()) ++taken;
  return taken;
}

void Simulation::diverge(std::string reason) {
  Divergence d;
  d.step = steps_;
  d.t = current_.t;
  d.method = settings_.method;
  d.h = h();
  // Estimated on the initial state: the diverged one says nothing about the scene.
  const StabilityEstimate e = estimate_stability(model_, initial_);
  d.w_max = e.w_max;
  d.stable_h = springlab::stable_step(settings_.method, e.w_max, e.damping, model_.verlet_damping);
  d.reason = std::move(reason);
  divergence_ = std::move(d);
}

const StabilityEstimate& Simulation::stability() {
  if (!stability_) stability_ = estimate_stability(model_, current_);
  return *stability_;
}

double Simulation::stable_step() {
  if (!stable_h_) {
    const StabilityEstimate& e = stability();
    stable_h_ = springlab::stable_step(settings_.method, e.w_max, e.damping, model_.verlet_damping);
  }
  return *stable_h_;
}

void Simulation::model_changed() {
  ws_.invalidate();
  stability_.reset();
  stable_h_.reset();
}

void Simulation::set_method(Method method) {
  settings_.method = method;
  stable_h_.reset();
  ws_.invalidate();
  ws_.adaptive_step = 0.0;
}

void Simulation::set_dt(double dt) {
  settings_.dt = dt;
  t_since_ = current_.t;
  substeps_done_ = 0;
  ws_.invalidate();
}

void Simulation::set_substeps(int substeps) {
  settings_.substeps = substeps;
  t_since_ = current_.t;
  substeps_done_ = 0;
  ws_.invalidate();
}

void Simulation::set_step_settings(const StepSettings& step) { settings_.step = step; }

// Every k_s (k_d, the drag) multiplied by one factor leaves the highest mode as it is: the
// estimate is scaled (exact for the state it was made on) instead of made again, which on a
// large cloth takes a second; so a slider dragged in front of a class stays smooth.
void Simulation::set_stiffness(double ks) {
  if (model_.materials.empty()) return;
  const double first = model_.materials.front().ks;
  if (!(first > 0.0)) {
    springlab::set_stiffness(model_, ks);
    return model_changed();
  }
  for (auto& m : model_.materials) m.ks *= ks / first;
  if (stability_) stability_->scale_stiffness(ks / first);
  scaled_stability();
}

void Simulation::set_damping(double kd) {
  if (model_.materials.empty()) return;
  const double first = model_.materials.front().kd;
  if (!(first > 0.0)) {
    springlab::set_damping(model_, kd);
    return model_changed();
  }
  for (auto& m : model_.materials) m.kd *= kd / first;
  if (stability_) stability_->scale_spring_damping(kd / first);
  scaled_stability();
}

void Simulation::set_gravity(const Vec3& g) {
  model_.gravity = g;
  keep_stability();  // K and C do not depend on gravity
}

void Simulation::set_drag(double drag) {
  if (!(model_.drag > 0.0)) {
    model_.drag = drag;
    return model_changed();
  }
  if (stability_) stability_->scale_drag(drag / model_.drag);
  model_.drag = drag;
  scaled_stability();
}

void Simulation::set_friction(double mu) {
  for (auto& p : model_.planes) p.friction = mu;
  for (auto& s : model_.spheres) s.friction = mu;
  keep_stability();  // nor on friction
}

void Simulation::set_mass(double mass) {
  for (Emitter& e : model_.emitters) {
    e.spawn.mass = mass;
    if (e.burst) e.burst->spawn.mass = mass;
  }
  for (int i = 0; i < model_.particle_count(); ++i) {
    model_.mass[i] = mass;
    if (!model_.pinned(i)) model_.inv_mass[i] = 1.0 / mass;
  }
  model_changed();
}

void Simulation::grab(int particle) {
  release();
  grabbed_ = particle;
  // Remember whether it was pinned by the scene: it is pinned for as long as it is held.
  grabbed_was_pinned_ = model_.pinned(particle);
  set_pinned(model_, particle, true);
  current_.v.row(particle).setZero();
  keep_stability();
}

void Simulation::move_grabbed(const Vec3& target, double over) {
  if (grabbed_ < 0 || !(over > 0.0)) return;
  current_.v.row(grabbed_) = (target.transpose() - current_.x.row(grabbed_)) / over;
  ws_.invalidate();
}

void Simulation::place(int particle, const Vec3& position) {
  current_.x.row(particle) = position.transpose();
  current_.v.row(particle).setZero();
  model_changed();
}

void Simulation::release() {
  if (grabbed_ < 0) return;
  if (!grabbed_was_pinned_) set_pinned(model_, grabbed_, false);
  else current_.v.row(grabbed_).setZero();
  grabbed_ = -1;
  keep_stability();
}

// model_changed() for a change that leaves the stability estimate right, or safe: gravity and
// friction are not in K or C; a held particle is pinned, which can only lower w_max (the
// stiffness matrix loses a row and a column: by interlacing its largest eigenvalue does not
// grow), and letting go restores the pinning the estimate was made with. Making it again takes a
// visible pause on a large cloth, at every click.
void Simulation::keep_stability() {
  const std::optional<StabilityEstimate> kept = stability_;
  const std::optional<double> kept_h = stable_h_;
  model_changed();
  stability_ = kept;
  stable_h_ = kept_h;
}

// model_changed() after the estimate was scaled in place: kept, but not the step limit from it.
void Simulation::scaled_stability() {
  keep_stability();
  stable_h_.reset();
}

}  // namespace springlab
