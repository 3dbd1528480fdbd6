// A whole step of the student's own (Python's fn(x, v, force, h), homework.hpp's OwnStep) checked
// as the rope code's steps are: which of springlab's fixed-step rows it is, step by step from its
// own states on the rope falling from rest; whether it holds the pin; then its order, stability
// and energy on the spring against that row's.
#include <algorithm>
#include <cmath>
#include <limits>

#include "parts.hpp"

namespace springlab::homework {

namespace {

// The rows a step of (x, v) can be, to rounding: the explicit fixed-step ones. Verlet stepped
// from (x, v) with a fresh workspace is velocity Verlet (verlet.cpp's start).
constexpr Method kRows[] = {Method::Euler, Method::SymplecticEuler, Method::Midpoint, Method::ModifiedEuler,
                            Method::RK4, Method::Verlet};

State rope_at_rest(const RopeRequest& r) {
  State s;
  s.resize(r.nodes);
  s.x.setZero();
  s.v.setZero();
  for (int i = 0; i < r.nodes; ++i)
    s.x.row(i).head<2>() = (r.start + (r.end - r.start) * (static_cast<double>(i) / (r.nodes - 1))).transpose();
  return s;
}

// max |x - x_ref| / max |x - x_before|, and the same for v.
double deviation(const State& before, const State& after, const State& reference) {
  auto ratio = [](double a, double b) {
    if (!std::isfinite(a) || !std::isfinite(b)) return std::numeric_limits<double>::infinity();
    return a == 0.0 ? 0.0 : (b == 0.0 ? std::numeric_limits<double>::infinity() : a / b);
  };
  const double moved = (after.x - before.x).rowwise().norm().maxCoeff();
  const double off = (after.x - reference.x).rowwise().norm().maxCoeff();
  const double dv = (after.v - before.v).rowwise().norm().maxCoeff();
  const double off_v = (after.v - reference.v).rowwise().norm().maxCoeff();
  return std::max(ratio(off, moved), ratio(off_v, dv));
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

Identified identify_step(const OwnStep& step, const std::string& name, CheckSection& section) {
  const RopeRequest rope = checked_rope();
  const Model model = rope_model(rope, kCheckGravity);
  const double h = kCheckStep;
  std::vector<State> run{rope_at_rest(rope)};
  Workspace ws;
  for (int n = 0; n < kCheckSteps; ++n) run.push_back(own_step(step, model, run.back(), h, ws));

  double pin = 0.0;
  for (const State& s : run) pin = std::max(pin, (s.x.row(0) - run[0].x.row(0)).norm());
  if (pin == 0.0) pass(section, "pins: the pinned particle stays where it is (force(x, v) gives it no acceleration)");
  else fail(section, "a pinned particle moves, by " + num(pin) + " m over " + std::to_string(kCheckSteps) +
                         " steps: take every acceleration from force(x, v), which gives a pinned particle none");

  Identified best;
  best.deviation = std::numeric_limits<double>::infinity();
  for (Method row : kRows) {
    double worst = 0.0;
    for (size_t n = 0; n + 1 < run.size(); ++n)
      worst = std::max(worst, deviation(run[n], run[n + 1], reference_step(row, model, run[n], h)));
    if (worst < best.deviation) {
      best = {};
      best.method = method_info(row).name;
      best.velocity_verlet = row == Method::Verlet;
      best.deviation = worst;
    }
  }
  const std::optional<Method> found = find_method(best.method);
  const MethodInfo& row = method_info(found ? *found : Method::Euler);
  const std::string where = std::to_string(kCheckSteps) + " steps of a " + std::to_string(rope.nodes) +
                            "-particle rope falling from rest at h = " + step_text(h);
  const std::string form = best.velocity_verlet ? " in velocity form (x + h v + h^2/2 a, v + h/2 (a + a1))" : "";
  if (best.deviation <= kMatch) {
    pass(section, name + " is " + row.label + " (springlab's " + row.name + ")" + form + ": each of " + where +
                      " matches it to " + num(best.deviation) + " of the step's motion");
    return best;
  }
  fail(section, name + " is none of springlab's explicit fixed-step rows: over " + where + ", the nearest, " + row.label +
                    ", is off by " + num(best.deviation) + " of a step's motion (rounding: 1e-10)");
  best.method.clear();
  return best;
}

Swing own_swing(const OwnStep& step, double h, int steps) {
  const Model model = rope_model({Vec2(0, 0), Vec2(0, -kSpringRest), 2, kSpringMass, kSpringK, {0}},
                                 Vec2(0.0, -kSpringG));
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

Report check_step(const OwnStep& step, const std::string& name) {
  Report report;
  report.sections.push_back({name, {}});
  CheckSection& section = report.sections.back();
  try {
    report.euler = identify_step(step, name, section);
    check_on_a_spring([&](double h, int steps, double) { return own_swing(step, h, steps); }, report.euler, section);
  } catch (const CodeFailure& e) {
    fail(section, e.what());
  }
  return report;
}

}  // namespace springlab::homework
