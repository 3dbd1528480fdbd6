#include "session/session.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>

#include "springlab/text.hpp"

namespace springlab::app {

namespace {
std::uint64_t next_serial() {
  static std::atomic<std::uint64_t> made{0};
  return ++made;
}
}  // namespace

Session::Session(Scene scene, SimulationSettings settings, double fps)
    : Session(std::move(scene), std::move(settings), fps, nullptr) {}

Session::Session(Scene scene, SimulationSettings settings, double fps,
                 std::unique_ptr<SceneKind> kind)
    : serial_(next_serial()),
      scene_(std::move(scene)),
      kind_(kind ? std::move(kind) : make_scene_kind(scene_)),
      settings_(std::move(settings)),
      fps_(fps) {
  settings_.track_dissipation = true;
  // An unstable lane goes on, marked (Simulation::trouble()), until it diverges or is reset: the
  // class sees where the instability leads; `run` stops there instead.
  settings_.audit_stops = false;
  lanes_.push_back(make_lane(kind_->initial_row(settings_)));
  // Watch the last free particle (a rope's free end, the spring's mass), along the spring of an
  // exact oscillator, else along gravity, else along x.
  for (int i = scene_.model.particle_count() - 1; i >= 0; --i)
    if (!scene_.model.pinned(i)) {
      watched_ = i;
      break;
    }
  if (lanes_.front().exact) {
    const Vec3 d =
        (scene_.state.x.row(watched_) - scene_.state.x.row(scene_.model.spring_a[0])).transpose();
    d.cwiseAbs().maxCoeff(&watched_axis_);
  } else if (scene_.model.gravity.squaredNorm() > 0.0) {
    scene_.model.gravity.cwiseAbs().maxCoeff(&watched_axis_);
  }
  sane_reach_ = scene_reach(scene_);
  for (Lane& lane : lanes_) sample(lane);
}

void Session::set_background_analysis(bool on) {
  background_ = on;
  settings_.analyse_when_needed = !on;
  for (Lane& lane : lanes_) lane.sim.set_analyse_when_needed(!on);
}

bool Session::analysing() const {
  for (const Lane& lane : lanes_)
    if (lane.job.running()) return true;
  return false;
}

void Session::update_analyses() {
  for (Lane& lane : lanes_) {
    Simulation& sim = lane.sim;
    if (!background_) {
      if (sim.has_stability()) lane.analysis = sim.stability_if_any();
      continue;
    }
    if (std::optional<StabilityJob::Result> done = lane.job.take()) {
      lane.analysis = done->analysis;  // shown even if the scene has moved on since
      if (done->version == sim.model_version()) sim.set_stability(done->analysis);
    }
    if (sim.has_stability()) {
      lane.analysis = sim.stability_if_any();
      if (sim.diverged()) sim.explain_divergence();  // the limit in its message, now at no cost
    } else if (!lane.job.running()) {
      lane.job.start(sim.model(), sim.state(), sim.model_version());
    }
  }
}

Lane Session::make_lane(int row) const {
  SimulationSettings s = settings_;
  kind_->configure(s, row);
  Lane lane(Simulation(scene_.model, scene_.state, s));
  lane.exact = ExactOscillator::detect(scene_.model, scene_.state);
  lane.kind = kind_.get();
  lane.sane = scene_.state;
  kind_->start(lane, row);
  return lane;
}

void Session::restart_lanes(const std::vector<int>& rows) {
  release();
  lanes_.clear();
  for (int row : rows)
    if (lanes_.size() < kMaxLanes) lanes_.push_back(make_lane(row));
  target_ = scene_.state.t;
  for (Lane& lane : lanes_) sample(lane);
}

void Session::choose(int row) {
  ++edits_;
  kind_->configure(settings_, row);
  if (!comparing()) kind_->switch_to(lanes_.front(), row);
}

void Session::set_compare_rows(const std::vector<int>& rows) {
  ++edits_;
  restart_lanes(rows.empty() ? std::vector<int>{kind_->row_of(lanes_.front())} : rows);
}

// What every kind has (its simulation's energies, the watched particle, the adaptive step), then
// the kind's own (SceneKind::sample).
void Session::sample(Lane& lane) {
  const Simulation& sim = lane.sim;
  const Energy e = sim.energy();
  History& h = lane.history;
  const double t = sim.state().t;
  h.t.push(t);
  h.kinetic.push(e.kinetic);
  h.potential.push(e.potential());
  h.total.push(e.total());
  h.dissipated.push(sim.dissipated());
  h.net.push(sim.net_energy());
  h.x.push(sim.state().x(watched_, watched_axis_));
  h.v.push(sim.state().v(watched_, watched_axis_));
  if (lane.exact) h.exact_x.push(lane.exact->at(t).x(watched_, watched_axis_));
  h.step.push(sim.adaptive_step());
  h.rejected.push(static_cast<double>(sim.counters().rejected));
  kind_->sample(lane, *this);
}

void Session::advance_frame() {
  // Script events due now, and the dragged point at the end of this frame.
  if (script_) {
    const double now = presentation_time();
    while (next_event_ < script_->events.size() && script_->events[next_event_].t <= now + 1e-9)
      apply(script_->events[next_event_++]);
    if (path_ && grabbed_ >= 0) {
      const double elapsed = static_cast<double>(frame_ + 1) / fps_ - path_->first;
      drag_to(path_position(path_->second, elapsed));
      if (elapsed >= path_->second.back().first) path_.reset();
    }
  }

  update_analyses();
  const double frame_time = speed_ / fps_;
  if (!paused_) target_ += frame_time;
  for (Lane& lane : lanes_) {
    Simulation& sim = lane.sim;
    if (sim.diverged()) continue;
    if (background_ && lane.waiting())
      continue;  // its sub-steps are not chosen yet: it starts when they are
    if (grabbed_ >= 0 && drag_target_) {
      if (paused_)
        sim.place(grabbed_, *drag_target_);
      else
        sim.move_grabbed(*drag_target_, frame_time);
    }
    const double dt = sim.settings().dt;
    const double due = std::floor((target_ - sim.state().t) / dt + 1e-9);
    if (due > 0) sim.advance(static_cast<std::int64_t>(due));
    kind_->after_steps(lane, paused_ ? SceneKind::Steps::Paused : SceneKind::Steps::Frame);
  }
  ++frame_;
  if (grabbed_ >= 0) drags_.back().to = primary().sim.state().x.row(grabbed_).transpose();
  for (Lane& lane : lanes_) {
    keep_if_sane(lane);
    sample(lane);
  }
}

void Session::keep_if_sane(Lane& lane) {
  const Simulation& sim = lane.sim;
  lane.blowing_up = false;
  if (sim.diverged()) return;
  const State& s = sim.state();
  // Within the scene's bounds: every particle within the reach of the camera's target.
  const Vec3& target = scene_.camera.target;
  const bool within =
      s.particle_count() == 0 ||
      (s.x.rowwise() - target.transpose()).rowwise().norm().maxCoeff() <= sane_reach_;
  // No spring past twice its longest sane length (its rest length, or its length at the start):
  // a state blowing up stretches its springs before it leaves the bounds. (NaN counts as past.)
  const Model& m = sim.model();
  double stretch = 0.0;
  for (int k = 0; k < m.spring_count(); ++k) {
    const int a = m.spring_a[k], b = m.spring_b[k];
    const double start = (scene_.state.x.row(b) - scene_.state.x.row(a)).norm();
    const double ratio = (s.x.row(b) - s.x.row(a)).norm() / std::max(m.rest_length[k], start);
    stretch = std::isnan(ratio) ? INFINITY : std::max(stretch, ratio);
    if (stretch == INFINITY) break;
  }
  // Blowing up: a spring past ten times its length on a step past its stability limit (by the
  // analysis shown) or caught growing by the energy audit. Never a stable run: a soft rope sags
  // far, a thrown body leaves the view, and a teacher's drag may pull a cloth's corner across it.
  const StabilityLimit* limit =
      lane.analysis ? &lane.analysis->limit(sim.settings().method) : nullptr;
  const bool past = limit && !std::isnan(limit->h) && sim.h() > limit->h;
  lane.blowing_up = grabbed_ < 0 && stretch > 10.0 && (past || sim.instability());
  if (!within || !(stretch <= 2.0)) return;
  lane.sane.x = s.x;
  lane.sane.v = s.v;
  lane.sane.t = s.t;
}

double scene_reach(const Scene& scene) {
  // The half-diagonal of a 16:9 frame of the scene's camera (planar: `height` shown; orbit: the
  // height the field of view shows at the target's distance), or the farthest starting particle.
  const Camera& c = scene.camera;
  const double half_height = c.view == View::Planar
                                 ? 0.5 * c.height
                                 : c.distance * std::tan(0.5 * c.fov * std::numbers::pi / 180.0);
  double reach = half_height * std::hypot(1.0, 16.0 / 9.0);
  const Points& x = scene.state.x;
  if (x.rows() > 0)
    reach = std::max(reach, (x.rowwise() - c.target.transpose()).rowwise().norm().maxCoeff());
  return reach;
}

void Session::step_once() {
  double latest = target_;
  update_analyses();
  for (Lane& lane : lanes_) {
    if (lane.sim.diverged() || (background_ && lane.waiting())) continue;
    lane.sim.step();
    kind_->after_steps(lane, SceneKind::Steps::One);
    latest = std::max(latest, lane.sim.state().t);
    keep_if_sane(lane);
    sample(lane);
  }
  target_ = latest;
}

LaneRow lane_row(const Lane& lane) {
  return lane.kind->row(lane.kind->row_of(lane));
}

std::string lane_label(const Lane& lane) {
  return lane.own.empty() ? tr(lane_row(lane).label) : lane.own;
}

std::string lane_name(const Lane& lane) {
  return lane.own.empty() ? std::string(lane_row(lane).name) : lane.own;
}

void Session::set_own_lanes(const std::vector<OwnLane>& own, const std::vector<BesideRow>& beside) {
  ++edits_;
  release();
  lanes_.clear();
  for (const OwnLane& o : own) {
    if (lanes_.size() == kMaxLanes) break;
    Lane lane = make_lane(static_cast<int>(o.like));  // (homework's rope: a mass-spring scene)
    lane.sim.set_own_step(o.step, o.label);
    lane.own = o.label;
    lane.own_known = o.known;
    lane.own_index = static_cast<int>(lanes_.size());
    lanes_.push_back(std::move(lane));
  }
  for (const BesideRow& row : beside) {
    if (lanes_.size() == kMaxLanes) break;
    Lane lane = make_lane(static_cast<int>(row.method));
    if (row.drag) lane.sim.set_drag(*row.drag);
    if (row.kd) lane.sim.set_damping(*row.kd);
    if (row.verlet_damping) lane.sim.set_verlet_damping(*row.verlet_damping);
    model_changed(lane);
    lanes_.push_back(std::move(lane));
  }
  if (lanes_.empty()) lanes_.push_back(make_lane(kind_->initial_row(settings_)));
  target_ = scene_.state.t;
  for (Lane& lane : lanes_) sample(lane);
}

void Session::model_changed(Lane& lane) {
  // The exact solution now starts from the current state, with the new constants.
  lane.exact = ExactOscillator::detect(lane.sim.model(), lane.sim.state());
}

void Session::set_dt(double dt) {
  ++edits_;
  settings_.dt = dt;
  for (Lane& l : lanes_) l.sim.set_dt(dt);
}

void Session::set_substeps(int substeps) {
  ++edits_;
  settings_.substeps = substeps;
  settings_.auto_substeps = false;
  for (Lane& l : lanes_) l.sim.set_substeps(substeps);
}

void Session::set_auto_substeps() {
  ++edits_;
  settings_.auto_substeps = true;
  for (Lane& l : lanes_) l.sim.set_auto_substeps(settings_.safety);
}

void Session::set_tolerance(double tolerance) {
  ++edits_;
  settings_.step.tolerance = tolerance;
  for (Lane& l : lanes_) l.sim.set_step_settings(settings_.step);
}

void Session::set_iterations(int iterations) {
  ++edits_;
  settings_.step.iterations = iterations;
  for (Lane& l : lanes_) l.sim.set_step_settings(settings_.step);
}

void Session::set_stiffness(double ks) {
  ++edits_;
  for (Lane& l : lanes_) {
    l.sim.set_stiffness(ks);
    model_changed(l);
  }
}

void Session::set_damping(double kd) {
  ++edits_;
  for (Lane& l : lanes_) {
    l.sim.set_damping(kd);
    model_changed(l);
  }
}

void Session::set_gravity(const Vec3& g) {
  ++edits_;
  for (Lane& l : lanes_) {
    l.sim.set_gravity(g);
    model_changed(l);
  }
}

void Session::set_drag(double drag) {
  ++edits_;
  for (Lane& l : lanes_) {
    l.sim.set_drag(drag);
    model_changed(l);
  }
}

void Session::set_friction(double mu) {
  ++edits_;
  for (Lane& l : lanes_) l.sim.set_friction(mu);
}

void Session::set_mass(double mass) {
  ++edits_;
  for (Lane& l : lanes_) {
    l.sim.set_mass(mass);
    model_changed(l);
  }
}

void Session::set_speed(double speed) {
  ++edits_;
  speed_ = std::clamp(speed, 1.0 / 16.0, 4.0);
}

void Session::reset() {
  release();
  for (Lane& l : lanes_) {
    l.sim.reset();
    l.history.clear();
    l.exact = ExactOscillator::detect(l.sim.model(), l.sim.state());
    l.sane = l.sim.state();
    kind_->start(l, kind_->row_of(l));  // a new part: its samples, trails and momentum gone
  }
  target_ = scene_.state.t;
  for (Lane& lane : lanes_) sample(lane);
}

double Session::stiffness() const {
  const Model& m = primary().sim.model();
  return m.materials.empty() ? 0.0 : m.materials.front().ks;
}

double Session::damping() const {
  const Model& m = primary().sim.model();
  return m.materials.empty() ? 0.0 : m.materials.front().kd;
}

double Session::mass() const {
  return primary().sim.model().mass[watched_];
}

double Session::friction() const {
  const Model& m = primary().sim.model();
  if (!m.planes.empty()) return m.planes.front().friction;
  if (!m.spheres.empty()) return m.spheres.front().friction;
  return 0.0;
}

int Session::pick(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                  double radius) const {
  const State& s = primary().sim.state();
  const Emission& emission = primary().sim.emission();
  int best = -1;
  double best_along = std::numeric_limits<double>::infinity();
  for (int i = 0; i < s.particle_count(); ++i) {
    if (emission.owned(i) && !emission.alive(i)) continue;  // not born yet, or gone
    if (!kind_->holdable(i)) continue;  // (an IK chain's joints: its solver places them)
    const Vec3 p = s.x.row(i).transpose() - origin;
    const double along = p.dot(direction);
    if (along < 0.0) continue;
    const double off = (p - along * direction).norm();
    // Of the particles under the cursor, the nearest the eye.
    if (off <= radius && along < best_along) {
      best = i;
      best_along = along;
    }
  }
  return best;
}

int Session::nearest(const Vec3& point) const {
  const State& s = primary().sim.state();
  int best = 0;
  (s.x.rowwise() - point.transpose()).rowwise().squaredNorm().minCoeff(&best);
  return best;
}

void Session::grab(int particle) {
  ++edits_;
  if (particle < 0 || particle >= scene_.model.particle_count()) return;
  grabbed_ = particle;
  drag_target_ = primary().sim.state().x.row(particle).transpose();
  drags_.push_back({particle, *drag_target_, *drag_target_});
  for (Lane& l : lanes_)
    if (!l.sim.diverged()) l.sim.grab(particle);
}

void Session::drag_to(const Vec3& target) {
  if (grabbed_ >= 0) drag_target_ = target;
}

void Session::release() {
  if (grabbed_ < 0) return;
  drags_.back().to = primary().sim.state().x.row(grabbed_).transpose();
  for (Lane& l : lanes_)
    if (!l.sim.diverged()) l.sim.release();
  grabbed_ = -1;
  drag_target_.reset();
  path_.reset();
}

void Session::watch(int particle) {
  if (particle < 0 || particle >= scene_.model.particle_count()) return;
  watched_ = particle;
  for (Lane& l : lanes_) {
    l.history.clear();
    if (l.part) l.part->clear_samples();
  }
}

void Session::play(Script script) {
  script_ = std::move(script);
  next_event_ = 0;
  path_.reset();
}

void Session::stop_script() {
  script_.reset();
  path_.reset();
}

void Session::apply(const ScriptEvent& e) {
  switch (e.kind) {
    case ScriptEvent::Kind::Grab:
      grab(e.near ? nearest(*e.near) : e.particle);
      break;
    case ScriptEvent::Kind::Path:
    case ScriptEvent::Kind::Move: {
      if (grabbed_ < 0) break;
      auto path = e.path;
      // A move, or a path whose first waypoint is later than its event, starts from where the
      // particle is, so that nothing jumps.
      if (path.front().first > 0.0) path.insert(path.begin(), {0.0, *drag_target_});
      path_ = {{e.t, std::move(path)}};
      break;
    }
    case ScriptEvent::Kind::Release:
      release();
      break;
    case ScriptEvent::Kind::Pause:
      paused_ = true;
      break;
    case ScriptEvent::Kind::Resume:
      paused_ = false;
      break;
    case ScriptEvent::Kind::Reset:
      reset();
      break;
    case ScriptEvent::Kind::Set:
      // A method is a row of a mass-spring scene's kind, found by its name; in compare mode the
      // lanes keep theirs.
      if (e.method)
        if (const std::optional<int> row = kind_->find(std::string(method_info(*e.method).name)))
          choose(*row);
      if (e.ks) set_stiffness(*e.ks);
      if (e.kd) set_damping(*e.kd);
      if (e.dt) set_dt(*e.dt);
      if (e.substeps) set_substeps(*e.substeps);
      if (e.gravity) set_gravity(*e.gravity);
      if (e.drag) set_drag(*e.drag);
      if (e.friction) set_friction(*e.friction);
      if (e.mass) set_mass(*e.mass);
      if (e.speed) set_speed(*e.speed);
      break;
  }
}

}  // namespace springlab::app
