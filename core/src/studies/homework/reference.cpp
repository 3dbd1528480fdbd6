// The references the homework is measured against: the rope as asked, built as a springlab Model,
// and one step of springlab's own rows from any state the code made; then which row a step is.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "parts.hpp"
#include "springlab/text.hpp"

namespace springlab::homework {

std::string num(double value) { return format_text("%.4g", value); }

std::string vec(const Vec2& v) { return "(" + num(v.x()) + ", " + num(v.y()) + ")"; }

std::string step_text(double h) {
  const double inverse = 1.0 / h;
  if (inverse >= 2.0 && inverse == std::round(inverse) && inverse < 1e9)
    return "1/" + std::to_string(static_cast<long long>(inverse)) + " s";
  return num(h) + " s";
}

Model rope_model(const RopeRequest& request, const Vec2& gravity, double drag, double verlet_damping) {
  Model model;
  const int material = add_material(model, {request.k, 0.0});
  for (int i = 0; i < request.nodes; ++i)
    add_particle(model, request.node_mass,
                 std::find(request.pinned.begin(), request.pinned.end(), i) != request.pinned.end());
  const double spacing = (request.end - request.start).norm() / (request.nodes - 1);
  for (int i = 0; i + 1 < request.nodes; ++i) add_spring(model, i, i + 1, spacing, material);
  finalize(model);
  model.gravity = Vec3(gravity.x(), gravity.y(), 0.0);
  model.drag = drag;
  model.verlet_damping = verlet_damping;
  return model;
}

BuiltRope exercise_rope(const RopeRequest& request) {
  BuiltRope rope;
  const int n = request.nodes;
  for (int i = 0; i < n; ++i) {
    BuiltMass m;
    m.start = request.start + (request.end - request.start) * (n > 1 ? static_cast<double>(i) / (n - 1) : 0.0);
    m.state.x = m.state.x_last = m.start;
    m.mass = request.node_mass;
    m.pinned = std::find(request.pinned.begin(), request.pinned.end(), i) != request.pinned.end();
    rope.masses.push_back(m);
  }
  for (int i = 0; i + 1 < n; ++i)
    rope.springs.push_back({i, i + 1, request.k, (rope.masses[i + 1].start - rope.masses[i].start).norm()});
  return rope;
}

RopeState reference_step(Method method, const Model& model, const RopeState& state, double h) {
  const int n = static_cast<int>(state.size());
  State in, out;
  in.resize(n);
  in.x.setZero();
  in.v.setZero();
  Workspace ws;
  const bool verlet = method == Method::Verlet;
  if (verlet) ws.x_prev.setZero(n, 3);
  for (int i = 0; i < n; ++i) {
    in.x.row(i).head<2>() = state[i].x.transpose();
    if (model.pinned(i)) continue;  // a pin holds still: its prescribed velocity is 0
    const Vec2 v = verlet ? Vec2((state[i].x - state[i].x_last) / h) : state[i].v;
    in.v.row(i).head<2>() = v.transpose();
  }
  if (verlet) {
    for (int i = 0; i < n; ++i) ws.x_prev.row(i).head<2>() = (model.pinned(i) ? state[i].x : state[i].x_last).transpose();
    accelerations(model, in.x, in.v, ws.a_now, ws);
    ws.verlet_ready = true;
    ws.verlet_h = h;
  }
  step(method, model, in, out, h, StepSettings{}, ws);
  RopeState next = state;
  for (int i = 0; i < n; ++i) {
    next[i].x = out.x.row(i).head<2>().transpose();
    next[i].v = out.v.row(i).head<2>().transpose();
    next[i].x_last = state[i].x;
  }
  return next;
}

State reference_step(Method method, const Model& model, const State& state, double h) {
  State out;
  Workspace ws;
  step(method, model, state, out, h, StepSettings{}, ws);
  return out;
}

double step_deviation(const RopeState& before, const RopeState& after, const RopeState& reference, bool velocities) {
  double moved = 0.0, off = 0.0, dv = 0.0, off_v = 0.0;
  for (size_t i = 0; i < after.size(); ++i) {
    moved = std::max(moved, (after[i].x - before[i].x).norm());
    off = std::max(off, (after[i].x - reference[i].x).norm());
    if (!velocities) off = std::max(off, (after[i].x_last - reference[i].x_last).norm());  // Verlet's bookkeeping
    dv = std::max(dv, (after[i].v - before[i].v).norm());
    off_v = std::max(off_v, (after[i].v - reference[i].v).norm());
  }
  auto ratio = [](double a, double b) {
    if (!std::isfinite(a) || !std::isfinite(b)) return std::numeric_limits<double>::infinity();
    return a == 0.0 ? 0.0 : (b == 0.0 ? std::numeric_limits<double>::infinity() : a / b);
  };
  const double d = ratio(off, moved);
  return velocities ? std::max(d, ratio(off_v, dv)) : d;
}

std::vector<Vec2> implied_forces(Step step, const std::vector<double>& masses, const RopeState& before,
                                 const RopeState& after, double h, double verlet_damping) {
  std::vector<Vec2> f(before.size());
  for (size_t i = 0; i < f.size(); ++i) {
    if (step == Step::Euler) f[i] = masses[i] * (after[i].v - before[i].v) / h;
    else f[i] = masses[i] * (after[i].x - before[i].x - (1.0 - verlet_damping) * (before[i].x - before[i].x_last)) / (h * h);
  }
  return f;
}

namespace {

// The accelerations of the springs and gravity alone (no drag) at a state's positions.
Points undamped_accelerations(const Model& model, const RopeState& s) {
  const int n = static_cast<int>(s.size());
  Points x(n, 3), v(n, 3), a(n, 3);
  x.setZero();
  v.setZero();
  for (int i = 0; i < n; ++i) x.row(i).head<2>() = s[i].x.transpose();
  SpringForces buffer;
  evaluate_forces(model, x, v, a, buffer);
  return a;
}

// The least-squares fit of the damping from the code's own steps (free masses only):
//   Euler:  v1 - v - h a0(x) = -h c/m v       (a drag f = -c v, c in N s/m)
//   Verlet: x1 - x - h^2 a0(x) = (1 - d)(x - x_last)
double fit_damping(Step step, const Model& undamped, const std::vector<RopeState>& run, double h) {
  double num = 0.0, den = 0.0;
  for (size_t n = 0; n + 1 < run.size(); ++n) {
    const Points a = undamped_accelerations(undamped, run[n]);
    for (size_t i = 0; i < run[n].size(); ++i) {
      if (undamped.pinned(static_cast<int>(i))) continue;
      const Vec2 a0 = a.row(static_cast<Eigen::Index>(i)).head<2>().transpose();
      const MassState &s = run[n][i], &t = run[n + 1][i];
      const Vec2 r = step == Step::Euler ? Vec2(t.v - s.v - h * a0) : Vec2(t.x - s.x - h * h * a0);
      const Vec2 b = step == Step::Euler ? Vec2(-h * s.v / undamped.mass[i]) : Vec2(s.x - s.x_last);
      num += r.dot(b);
      den += b.dot(b);
    }
  }
  if (den == 0.0 || !std::isfinite(num)) return 0.0;
  return step == Step::Euler ? num / den : 1.0 - num / den;
}

constexpr int kSteps = kCheckSteps;

}  // namespace

Identified identify(RopeCode& code, Step step, const RopeRequest& request, CheckSection& section) {
  const double h = kCheckStep;
  const Vec2 g = kCheckGravity;
  const BuiltRope rope = code.build(request);
  RopeState start;
  for (const BuiltMass& m : rope.masses) start.push_back(m.state);
  std::vector<RopeState> run = code.simulate(step, h, g, kSteps);
  run.insert(run.begin(), start);

  const double fitted = fit_damping(step, rope_model(request, g), run, h);
  std::vector<Method> rows = step == Step::Euler ? std::vector{Method::Euler, Method::SymplecticEuler}
                                                 : std::vector{Method::Verlet};
  Identified best;
  best.deviation = std::numeric_limits<double>::infinity();
  for (Method row : rows) {
    for (double damping : {0.0, fitted}) {
      const Model model = step == Step::Euler ? rope_model(request, g, damping) : rope_model(request, g, 0.0, damping);
      double worst = 0.0;
      for (size_t n = 0; n + 1 < run.size(); ++n)
        worst = std::max(worst, step_deviation(run[n], run[n + 1], reference_step(row, model, run[n], h), step == Step::Euler));
      if (worst < best.deviation) {
        best = {};
        best.method = method_info(row).name;
        best.drag = step == Step::Euler ? damping : 0.0;
        best.verlet_damping = step == Step::Verlet ? damping : 0.0;
        best.deviation = worst;
      }
    }
  }
  const std::optional<Method> found = find_method(best.method);
  const MethodInfo& row = method_info(found ? *found : rows[0]);
  const std::string damping =
      step == Step::Euler ? (best.drag == 0.0 ? "no damping" : "a global drag f = -c v, c = " + num(best.drag) + " N s/m (fitted)")
                          : (best.verlet_damping == 0.0 ? "no damping"
                                                        : "damping factor d = " + num(best.verlet_damping) + " (fitted)");
  const std::string where = std::to_string(kSteps) + " steps of a " + std::to_string(request.nodes) +
                            "-mass rope falling from rest at h = 1/1024 s";
  if (best.deviation <= kMatch) {
    pass(section, std::string(step_name(step)) + " is " + row.label + " (springlab's " + row.name + "), with " + damping +
                      ": each of " + where + " matches it to " + num(best.deviation) + " of the step's motion");
    return best;
  }
  std::string names;
  for (Method r : rows) names += std::string(names.empty() ? "" : " or ") + method_info(r).label;
  fail(section, std::string(step_name(step)) + " is not " + names + ", with or without damping: over " + where +
                    ", the nearest, " + row.label + ", is off by " + num(best.deviation) +
                    " of a step's motion (rounding: 1e-10); the probes below say where");
  best.method.clear();
  return best;
}

}  // namespace springlab::homework
