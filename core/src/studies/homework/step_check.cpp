// A whole step of the student's own (Python's fn(x, v, force, h), homework.hpp's OwnStep) checked
// as the rope code's steps are: which of springlab's fixed-step rows it is (every explicit one in
// the table, Verlet started from (x, v) being velocity Verlet), step by step from its own states on
// the rope falling from rest, with a global drag fitted where the step adds one; whether it holds
// the pin; then its order, stability and energy on the spring against that row's. Work in float
// (NumPy's float32) is judged to float's rounding, positions and velocities included.
#include <algorithm>
#include <cmath>
#include <limits>

#include "parts.hpp"

namespace springlab::homework {

namespace {

State rope_at_rest(const RopeRequest& r) {
  State s;
  s.resize(r.nodes);
  s.x.setZero();
  s.v.setZero();
  for (int i = 0; i < r.nodes; ++i)
    s.x.row(i).head<2>() =
        (r.start + (r.end - r.start) * (static_cast<double>(i) / (r.nodes - 1))).transpose();
  return s;
}

RopeState as_rope_state(const State& s) {
  RopeState r(s.particle_count());
  for (int i = 0; i < s.particle_count(); ++i) {
    r[i].x = s.x.row(i).head<2>().transpose();
    r[i].v = s.v.row(i).head<2>().transpose();
  }
  return r;
}

State own_step(const OwnStep& step, const Model& model, const State& in, double h, Workspace& ws) {
  State out;
  out.resize(in.particle_count());
  out.x = in.x;
  out.v = in.v;
  step(model, in, out, h, ws);
  out.t = in.t + h;
  return out;
}

// The drag a step adds, as a rate (Python's step takes accelerations from force(x, v) and damps
// them, a = force(x, v) - c v), by least squares over the free particles and steps, as an
// Euler-like step has it: v1 - v - h a0(x) = -h c v.
double fit_drag(const Model& undamped, const std::vector<State>& run, double h) {
  double num_sum = 0.0, den = 0.0;
  for (size_t n = 0; n + 1 < run.size(); ++n) {
    const RopeState s = as_rope_state(run[n]), t = as_rope_state(run[n + 1]);
    const std::vector<Vec2> a = undamped_accelerations(undamped, s);
    for (size_t i = 0; i < s.size(); ++i) {
      if (undamped.pinned(static_cast<int>(i))) continue;
      const Vec2 r = t[i].v - s[i].v - h * a[i];
      const Vec2 b = -h * s[i].v;
      num_sum += r.dot(b);
      den += b.dot(b);
    }
  }
  const double c = den == 0.0 || !std::isfinite(num_sum) ? 0.0 : num_sum / den;
  return std::abs(c) > 1e-9 ? c : 0.0;
}

// The drag rate one step of h takes from the rope's particles all moving at u = (1, 0.5) m/s with
// no gravity, its springs at rest length (no force acts: only damping changes a velocity), read on
// the middle particle: c from v1 = (1 - c h) u. A factor a step, v = (1 - d) v, reads d / h.
double drag_felt(const OwnStep& step, const RopeRequest& rope, double h) {
  const Model still = rope_model(rope, Vec2::Zero());
  State s = rope_at_rest(rope);
  const Vec2 u(1.0, 0.5);
  for (int i = 0; i < rope.nodes; ++i)
    if (!still.pinned(i)) s.v.row(i).head<2>() = u.transpose();
  Workspace ws;
  const State next = own_step(step, still, s, h, ws);
  const int middle = rope.nodes / 2;
  const Vec2 v1 = next.v.row(middle).head<2>().transpose();
  return -(v1 - u).dot(u) / (h * u.squaredNorm());
}

// The pin: the pinned particle (0) must stay where it started over the whole run.
void check_own_pin(const std::vector<State>& run, CheckSection& section) {
  double pin = 0.0;
  for (const State& s : run) pin = std::max(pin, (s.x.row(0) - run[0].x.row(0)).norm());
  if (pin == 0.0)
    pass(section, "pins",
         tr("pins: the pinned particle stays where it is (force(x, v) gives it no acceleration)"));
  else
    fail(section, "pin-moves",
         format_text(tr("a pinned particle moves, by %s m over %d steps: take every acceleration "
                        "from force(x, v), which "
                        "gives a pinned particle none"),
                     num(pin).c_str(), kCheckSteps));
}

// The row, with the damping variant, that each step of the run (at kCheckStep) matches best: one
// every step matches within kMatch (or float's rounding, in float) before any other, then the
// smallest worst deviation. `best_within`: whether every step matched it.
Identified nearest_own_row(const std::vector<State>& run, const RopeRequest& rope,
                           const std::vector<Method>& rows, const std::vector<Damping>& variants,
                           bool in_float, bool& best_within) {
  const double h = kCheckStep;
  Identified best;
  best.deviation = std::numeric_limits<double>::infinity();
  for (Method row : rows)
    for (const Damping& d : variants) {
      Model damped = rope_model(rope, kCheckGravity, d.at_step(h));
      double worst = 0.0, floor = 0.0;
      bool within = true;
      for (size_t n = 0; n + 1 < run.size(); ++n) {
        const RopeState before = as_rope_state(run[n]), after = as_rope_state(run[n + 1]);
        // (A drag taken from the new velocity: the rope's reference step, which takes it so; the
        // rows with a history start from (x, v) here, as velocity Verlet, through State's.)
        const RopeState reference = d.drag_at != DragAt::Forces && !method_info(row).history
                                        ? reference_step(row, damped, d, before, h)
                                        : as_rope_state(reference_step(row, damped, run[n], h));
        const double dev = step_deviation(before, after, reference, true);
        const double f = float_floor(damped, d, before, after, h, true, in_float);
        worst = std::max(worst, dev);
        floor = std::max(floor, f);
        within = within && dev <= std::max(kMatch, in_float ? f : 0.0);
      }
      if (within != best_within ? within : worst < best.deviation) {
        best = {};
        best.method = method_info(row).name;
        best.velocity_verlet = method_info(row).history;
        best.damping = d;
        best.deviation = worst;
        best.float_floor = floor;
        best.in_float = in_float && worst > kMatch;
        best_within = within;
      }
    }
  return best;
}

Identified identify_step(const OwnStep& step, const std::string& name, const bool* single_precision,
                         CheckSection& section) {
  const RopeRequest rope = checked_rope();
  const Model model = rope_model(rope, kCheckGravity);
  const double h = kCheckStep;
  std::vector<State> run{rope_at_rest(rope)};
  Workspace ws;
  for (int n = 0; n < kCheckSteps; ++n) run.push_back(own_step(step, model, run.back(), h, ws));
  const bool in_float = single_precision && *single_precision;

  check_own_pin(run, section);

  std::vector<Method> rows = candidate_rows(false);
  for (Method verlet : candidate_rows(true))
    rows.push_back(verlet);  // from (x, v): velocity Verlet
  std::vector<Damping> variants{Damping{}};
  if (const double c = fit_drag(model, run, h); c != 0.0) {
    // A drag of rate c, or a factor a step, v = (1 - d) v: from the same state at twice the step
    // that implies half the rate, d / 2h. Each taken with the forces or from the new velocity.
    Damping rate;
    rate.drag = c;
    rate.drag_rate = true;
    const double c_here = drag_felt(step, rope, h), c_double = drag_felt(step, rope, 2.0 * h);
    if (c_here != 0.0 && std::abs(c_double - 0.5 * c_here) <= 1e-3 * std::abs(0.5 * c_here)) {
      rate.drag_step = c_here * h;
      rate.drag = 0.0;
    }
    for (DragAt at : {DragAt::Forces, DragAt::NewVelocity, DragAt::AfterPosition}) {
      rate.drag_at = at;
      variants.push_back(rate);
    }
  }

  bool best_within = false;
  Identified best = nearest_own_row(run, rope, rows, variants, in_float, best_within);
  const std::optional<Method> found = find_method(best.method);
  const MethodInfo& row = method_info(found ? *found : Method::Euler);
  const std::string where =
      format_text(tr("%d steps of a %d-particle rope falling from rest at h = %s"), kCheckSteps,
                  rope.nodes, step_text(h).c_str());
  const std::string form =
      best.velocity_verlet ? tr(" in velocity form (x + h v + h^2/2 a, v + h/2 (a + a1))") : "";
  const std::string damped = damping_text(best.damping, Step::Euler);
  if (best_within) {
    const std::string how =
        best.in_float
            ? format_text(
                  tr("%s of the step's motion: float's rounding (the step returns float32 arrays, "
                     "which hold their numbers to 2^-24: up to %s here)"),
                  num(best.deviation).c_str(), num(best.float_floor).c_str())
            : format_text(tr("%s of the step's motion (double's rounding)"),
                          num(best.deviation).c_str());
    pass(section, "method",
         format_text(tr("%s is %s (springlab's %s)%s, with %s: each of %s matches it to %s"),
                     name.c_str(), tr(row.label), row.name, form.c_str(), damped.c_str(),
                     where.c_str(), how.c_str()));
    if (best.damping.drag < 0.0 || best.damping.drag_step < 0.0)
      fail(section, "damping-sign",
           format_text(tr("the drag has the wrong sign: c = %s 1/s pushes each particle along its "
                          "velocity (a = force(x, v) "
                          "- c v with c > 0 opposes it)"),
                       num(best.damping.at_step(h).drag).c_str()));
    return best;
  }
  fail(section, "not-textbook",
       format_text(tr("%s is none of springlab's explicit fixed-step rows: over %s, the nearest, "
                      "%s, is off by %s of a step's "
                      "motion (double's rounding allows 1e-8)"),
                   name.c_str(), where.c_str(), tr(row.label), num(best.deviation).c_str()));
  best.method.clear();
  return best;
}

Swing own_swing(const OwnStep& step, double h, int steps) {
  const Model model = rope_model(hanging_spring(), Vec2(0.0, -kSpringG));
  State s;
  s.resize(2);
  s.x.setZero();
  s.v.setZero();
  s.x(1, 1) = -kSpringRest;
  Workspace ws;
  Swing out;
  out.y.push_back(s.x(1, 1));
  out.v.push_back(0.0);
  for (int n = 0; n < steps; ++n) {
    s = own_step(step, model, s, h, ws);
    out.y.push_back(s.x(1, 1));
    out.v.push_back(s.v(1, 1));
  }
  return out;
}

}  // namespace

Report check_step(const OwnStep& step, const std::string& name, const bool* single_precision) {
  Report report;
  report.sections.push_back({name, {}});
  CheckSection& section = report.sections.back();
  try {
    report.euler = identify_step(step, name, single_precision, section);
    check_on_a_spring([&](double h, int steps, double) { return own_swing(step, h, steps); },
                      report.euler, section);
  } catch (const CodeFailure& e) {
    fail(section, "code-failed", e.what());
  }
  return report;
}

}  // namespace springlab::homework
