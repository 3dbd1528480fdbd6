// The references the homework is measured against: the rope as a springlab Model (as asked, or
// as the code built it), one step of springlab's own rows from any state the code made, with
// every damping form students write; the forces a step implies; and what float's rounding
// allows.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "parts.hpp"

namespace springlab::homework {

namespace {

bool listed(const std::vector<int>& list, int i) {
  return std::find(list.begin(), list.end(), i) != list.end();
}

// springlab's drag is one force coefficient for every particle: a drag rate takes the mass of the
// rope's first particle (the exercise's ropes have one node mass).
void set_forces(Model& model, const Vec2& gravity, const Damping& damping) {
  model.gravity = Vec3(gravity.x(), gravity.y(), 0.0);
  model.drag = damping.drag_on(model.mass.empty() ? 0.0 : model.mass[0]);
  model.verlet_damping = damping.verlet;
}

}  // namespace

Model rope_model(const RopeRequest& request, const Vec2& gravity, const Damping& damping) {
  Model model;
  const int material = add_material(model, {request.k, damping.along});
  for (int i = 0; i < request.nodes; ++i)
    add_particle(model, request.node_mass, listed(request.pinned, i));
  const double spacing =
      request.nodes > 1 ? (request.end - request.start).norm() / (request.nodes - 1) : 0.0;
  for (int i = 0; i + 1 < request.nodes; ++i) add_spring(model, i, i + 1, spacing, material);
  finalize(model);
  set_forces(model, gravity, damping);
  return model;
}

Model built_model(const BuiltRope& rope, const Vec2& gravity, const Damping& damping) {
  Model model;
  for (const BuiltMass& m : rope.masses) add_particle(model, m.mass, m.pinned);
  std::map<double, int> materials;  // a material for each k the springs have
  const int n = static_cast<int>(rope.masses.size());
  for (const BuiltSpring& s : rope.springs) {
    if (s.m1 < 0 || s.m2 < 0 || s.m1 >= n || s.m2 >= n || s.m1 == s.m2) continue;
    auto [it, added] = materials.try_emplace(s.k, 0);
    if (added) it->second = add_material(model, {s.k, damping.along});
    add_spring(model, std::min(s.m1, s.m2), std::max(s.m1, s.m2), s.rest, it->second);
  }
  finalize(model);
  set_forces(model, gravity, damping);
  return model;
}

BuiltRope exercise_rope(const RopeRequest& request) {
  BuiltRope rope;
  const int n = request.nodes;
  for (int i = 0; i < n; ++i) {
    BuiltMass m;
    m.start = request.start +
              (request.end - request.start) * (n > 1 ? static_cast<double>(i) / (n - 1) : 0.0);
    m.state.x = m.state.x_last = m.start;
    m.mass = request.node_mass;
    m.pinned = listed(request.pinned, i);
    rope.masses.push_back(m);
  }
  for (int i = 0; i + 1 < n; ++i)
    rope.springs.push_back(
        {i, i + 1, request.k, (rope.masses[i + 1].start - rope.masses[i].start).norm()});
  return rope;
}

std::vector<Vec2> undamped_accelerations(const Model& model, const RopeState& s) {
  const int n = static_cast<int>(s.size());
  Points x(n, 3), v(n, 3), a(n, 3);
  x.setZero();
  v.setZero();
  for (int i = 0; i < n; ++i) x.row(i).head<2>() = s[i].x.transpose();
  Model undamped = model;
  undamped.drag = 0.0;
  set_damping(undamped, 0.0);
  SpringForces buffer;
  evaluate_forces(undamped, x, v, a, buffer);
  std::vector<Vec2> out(n);
  for (int i = 0; i < n; ++i) out[i] = a.row(i).head<2>().transpose();
  return out;
}

std::vector<Vec2> relative_damping_forces(const Model& model, const RopeState& s, double relative) {
  // f_b = -k_d (v_b - v_a), f_a = -f_b: each spring's ends pulled towards a common velocity.
  std::vector<Vec2> f(s.size(), Vec2::Zero());
  if (relative == 0.0) return f;
  for (int k = 0; k < model.spring_count(); ++k) {
    const int a = model.spring_a[k], b = model.spring_b[k];
    const Vec2 on_b = -relative * (s[b].v - s[a].v);
    f[b] += on_b;
    f[a] -= on_b;
  }
  return f;
}

std::vector<Vec2> damping_forces(const Model& model, const RopeState& s, const Damping& damping) {
  std::vector<Vec2> f = relative_damping_forces(model, s, damping.relative);
  for (size_t i = 0; i < s.size(); ++i) f[i] -= damping.drag_on(model.mass[i]) * s[i].v;
  if (damping.along != 0.0)
    for (int k = 0; k < model.spring_count(); ++k) {
      // f_b = -k_d ((v_b - v_a) . u) u, f_a = -f_b: the lecture's, along the spring.
      const int a = model.spring_a[k], b = model.spring_b[k];
      const Vec2 d = s[b].x - s[a].x;
      if (d.norm() == 0.0) continue;
      const Vec2 u = d.normalized();
      const Vec2 on_b = -damping.along * (s[b].v - s[a].v).dot(u) * u;
      f[b] += on_b;
      f[a] -= on_b;
    }
  return f;
}

namespace {

// How a row moves a free particle under a constant acceleration of 1 in a step of h: x by cx,
// v by cv (Euler 0 and h, symplectic Euler h^2 and h, the midpoint, modified Euler and RK4 h^2/2
// and h). A force held over the step moves each mass by these times its acceleration.
std::pair<double, double> response(Method method, double h) {
  Model free;
  add_particle(free, 1.0, false);
  finalize(free);
  free.gravity = Vec3(1.0, 0.0, 0.0);
  State s;
  s.resize(1);
  s.x.setZero();
  s.v.setZero();
  const State next = reference_step(method, free, s, h);
  return {next.x(0, 0), next.v(0, 0)};
}

}  // namespace

RopeState reference_step(Method method, const Model& model, const Damping& damping,
                         const RopeState& state, double h) {
  const int n = static_cast<int>(state.size());
  State in, out;
  in.resize(n);
  in.x.setZero();
  in.v.setZero();
  Workspace ws;
  const bool history = method_info(method).history;
  if (history) ws.x_prev.setZero(n, 3);
  for (int i = 0; i < n; ++i) {
    in.x.row(i).head<2>() = state[i].x.transpose();
    if (model.pinned(i)) continue;  // a pin holds still: its prescribed velocity is 0
    const Vec2 v = history ? Vec2((state[i].x - state[i].x_last) / h) : state[i].v;
    in.v.row(i).head<2>() = v.transpose();
  }
  if (history) {
    for (int i = 0; i < n; ++i)
      ws.x_prev.row(i).head<2>() = (model.pinned(i) ? state[i].x : state[i].x_last).transpose();
    accelerations(model, in.x, in.v, ws.a_now, ws);
    ws.verlet_ready = true;
    ws.verlet_h = h;
  }
  const Points a_start = history ? ws.a_now : Points();
  // A drag taken from the new velocity: the row's step without it, then v (1 - c h) below.
  const bool drag_after = !history && damping.drag_at != DragAt::Forces && model.drag != 0.0;
  if (drag_after) {
    Model undragged = model;
    undragged.drag = 0.0;
    step(method, undragged, in, out, h, StepSettings{}, ws);
  } else {
    step(method, model, in, out, h, StepSettings{}, ws);
  }
  RopeState next = state;
  for (int i = 0; i < n; ++i) {
    next[i].x = out.x.row(i).head<2>().transpose();
    next[i].v = out.v.row(i).head<2>().transpose();
    next[i].x_last = state[i].x;
  }
  // Verlet's factor on the whole displacement: x + (1 - d)((x - x_last) + h^2 a) is the row's
  // x + (1 - d)(x - x_last) + h^2 a less d h^2 a.
  if (history && damping.verlet_whole && damping.verlet != 0.0)
    for (int i = 0; i < n; ++i)
      if (!model.pinned(i))
        next[i].x -= damping.verlet * h * h * a_start.row(i).head<2>().transpose();
  // Damping along the relative velocity, a force at the step's start state.
  if (!history && damping.relative != 0.0) {
    const std::vector<Vec2> f = relative_damping_forces(model, state, damping.relative);
    const auto [cx, cv] = response(method, h);
    for (int i = 0; i < n; ++i) {
      if (model.pinned(i)) continue;
      const Vec2 a = f[i] * model.inv_mass[i];
      next[i].x += cx * a;
      next[i].v += cv * a;
    }
  }
  // Before the position moves by it (symplectic Euler's x + h v1: the rest of the rows step x
  // from the old velocity, or their own stages), or after.
  const bool moves_by_it =
      damping.drag_at == DragAt::NewVelocity && method == Method::SymplecticEuler;
  if (drag_after)
    for (int i = 0; i < n; ++i) {
      if (model.pinned(i)) continue;
      const Vec2 taken = model.drag * model.inv_mass[i] * h * next[i].v;
      next[i].v -= taken;
      if (moves_by_it) next[i].x -= h * taken;
    }
  return next;
}

State reference_step(Method method, const Model& model, const State& state, double h) {
  State out;
  Workspace ws;
  step(method, model, state, out, h, StepSettings{}, ws);
  return out;
}

std::vector<Method> candidate_rows(bool history) {
  std::vector<Method> rows;
  for (const MethodInfo& row : methods()) {
    const bool fixed_explicit =
        (row.family == MethodFamily::RungeKutta || row.family == MethodFamily::Partitioned);
    if (fixed_explicit && row.history == history) rows.push_back(row.id);
  }
  return rows;
}

namespace {

double ratio(double a, double b) {
  if (!std::isfinite(a) || !std::isfinite(b)) return std::numeric_limits<double>::infinity();
  return a == 0.0 ? 0.0 : (b == 0.0 ? std::numeric_limits<double>::infinity() : a / b);
}

}  // namespace

double step_deviation(const RopeState& before, const RopeState& after, const RopeState& reference,
                      bool velocities) {
  double moved = 0.0, off = 0.0, dv = 0.0, off_v = 0.0;
  for (size_t i = 0; i < after.size(); ++i) {
    moved = std::max(moved, (after[i].x - before[i].x).norm());
    off = std::max(off, (after[i].x - reference[i].x).norm());
    if (!velocities)
      off = std::max(off, (after[i].x_last - reference[i].x_last).norm());  // Verlet's bookkeeping
    dv = std::max(dv, (after[i].v - before[i].v).norm());
    off_v = std::max(off_v, (after[i].v - reference[i].v).norm());
  }
  if (!(off == off) || !(off_v == off_v)) return std::numeric_limits<double>::infinity();  // NaN
  const double d = ratio(off, moved);
  return velocities ? std::max(d, ratio(off_v, dv)) : d;
}

double float_floor(const Model& model, const Damping& damping, const RopeState& before,
                   const RopeState& after, double h, bool velocities, bool stored_in_float) {
  const int n = static_cast<int>(before.size());
  // Each mass's force scale: what float's rounding of the terms it sums can be off by.
  std::vector<double> scale(n, 0.0);
  for (int k = 0; k < model.spring_count(); ++k) {
    const int a = model.spring_a[k], b = model.spring_b[k];
    const double length = (before[b].x - before[a].x).norm();
    const double damping_force =
        (damping.along + std::abs(damping.relative)) * (before[b].v - before[a].v).norm();
    scale[a] += model.ks(k) * length + damping_force;
    scale[b] += model.ks(k) * length + damping_force;
  }
  const double g = Vec2(model.gravity.x(), model.gravity.y()).norm();
  constexpr double kRoundings = 8.0 * kFloatRounding;
  double moved = 0.0, dv = 0.0, off_x = 0.0, off_v = 0.0;
  for (int i = 0; i < n; ++i) {
    moved = std::max(moved, (after[i].x - before[i].x).norm());
    dv = std::max(dv, (after[i].v - before[i].v).norm());
    if (model.pinned(i)) continue;
    const double force = scale[i] + model.mass[i] * g +
                         std::abs(damping.drag_on(model.mass[i])) * before[i].v.norm();
    const double da = kRoundings * force * model.inv_mass[i];
    // Verlet's (1 - d)(x - x_last) is rounded too, where the factor is a float.
    // Positions and velocities kept in float (NumPy's float32) are rounded once more each step.
    const double kept_x = stored_in_float ? 2.0 * kFloatRounding * after[i].x.norm() : 0.0;
    const double kept_v = stored_in_float ? 2.0 * kFloatRounding * after[i].v.norm() : 0.0;
    off_x = std::max(off_x,
                     h * h * da + kept_x +
                         (velocities ? 0.0 : kRoundings * (before[i].x - before[i].x_last).norm()));
    off_v = std::max(off_v, h * da + kept_v);
  }
  return velocities ? std::max(ratio(off_x, moved), ratio(off_v, dv)) : ratio(off_x, moved);
}

std::vector<Vec2> implied_forces(Step step, const std::vector<double>& masses,
                                 const RopeState& before, const RopeState& after, double h,
                                 double verlet_damping, int h_power) {
  std::vector<Vec2> f(before.size());
  const double scale = std::pow(h, h_power);
  for (size_t i = 0; i < f.size(); ++i) {
    if (step == Step::Euler)
      f[i] = masses[i] * (after[i].v - before[i].v) / h;
    else
      f[i] =
          masses[i] *
          (after[i].x - before[i].x - (1.0 - verlet_damping) * (before[i].x - before[i].x_last)) /
          scale;
  }
  return f;
}

}  // namespace springlab::homework
