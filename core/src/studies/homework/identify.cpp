// Which row of springlab's table a step is: the code's own rope falling from rest under gravity,
// 64 steps, each compared from the code's own state before it with one step of each candidate
// row (the explicit fixed-step rows of (x, v) for simulateEuler, the rows with a history for
// simulateVerlet), with the damping the probes fitted (and without, and for Verlet with its factor
// on (x - x_last) or on the whole displacement). A match is to double's rounding (1e-8 of a step's
// motion) or, for work done in float, to the floor float's rounding gives (reference.cpp's
// float_floor), said as such. A step that matches no row is explained where a named mistake
// explains it: the acceleration applied twice, the position stepped from last_position.
#include <algorithm>
#include <cmath>
#include <limits>

#include "parts.hpp"

namespace springlab::homework {

namespace {

struct Candidate {
  Method row;
  Damping damping;
  double worst = std::numeric_limits<double>::infinity();  // the largest deviation over the steps
  double floor = 0.0;                                      // the largest float floor over the steps
  bool within_float = false;                               // every step within its own floor
};

Candidate measure(Method row, const Damping& damping, const Model& model,
                  const std::vector<RopeState>& run, double h, bool velocities) {
  Candidate c{row, damping};
  c.worst = 0.0;
  c.within_float = true;
  for (size_t n = 0; n + 1 < run.size(); ++n) {
    const RopeState reference = reference_step(row, model, damping, run[n], h);
    const double d = step_deviation(run[n], run[n + 1], reference, velocities);
    const double f = float_floor(model, damping, run[n], run[n + 1], h, velocities);
    c.worst = std::max(c.worst, d);
    c.floor = std::max(c.floor, f);
    // (A step whose motion cannot be measured, a velocity never changed, matches nothing.)
    c.within_float = c.within_float && std::isfinite(d) && d <= std::max(kMatch, f);
  }
  return c;
}

// The steps' named mistakes, each a relation between the code's step and a row's that holds to
// 1e-3 over every step with motion to measure.
struct Explained {
  const char* key;
  const char* says;
};

std::optional<Explained> explain(const Model& model, const std::vector<RopeState>& run,
                                 const Damping& damping, double h) {
  // x1 = x + h v1 + h^2 a (symplectic Euler's position, with the acceleration once more), and
  // x1 = x_last + h v1 (the position stepped from where the rope began).
  double twice = 0.0, from_last = 0.0, scale_twice = 0.0, scale_last = 0.0;
  for (size_t n = 0; n + 1 < run.size(); ++n) {
    const RopeState symplectic = reference_step(Method::SymplecticEuler, model, damping, run[n], h);
    for (size_t i = 0; i < run[n].size(); ++i) {
      if (model.pinned(static_cast<int>(i))) continue;
      const MassState &s = run[n][i], &t = run[n + 1][i];
      const Vec2 a = (symplectic[i].v - s.v) / h;
      const Vec2 due_twice = symplectic[i].x + h * h * a;
      twice = std::max(twice, (t.x - due_twice).norm());
      scale_twice = std::max(scale_twice, h * h * a.norm());
      const Vec2 due_last = s.x_last + h * t.v;
      from_last = std::max(from_last, (t.x - due_last).norm());
      scale_last = std::max(scale_last, (s.x - s.x_last).norm() + h * t.v.norm());
    }
  }
  if (scale_twice > 0.0 && twice <= 1e-3 * scale_twice)
    return Explained{
        "accel-twice",
        N_("the acceleration is applied twice: after v += a h, the position moves by (v + a h) h. "
           "x += v h with the new v is semi-implicit (symplectic) Euler")};
  if (scale_last > 0.0 && from_last <= 1e-3 * scale_last)
    return Explained{
        "from-last-position",
        N_("the position is stepped from last_position, not position: x = last_position + "
           "v h starts every step from where the rope was built")};
  return std::nullopt;
}

std::string rows_text(const std::vector<Method>& rows) {
  std::string names;
  for (Method r : rows) names += (names.empty() ? "" : ", ") + std::string(method_info(r).name);
  return names;
}

// The damping's variants: none, and what the probes fitted (Verlet's on either part). Euler's
// drag (or factor a step) taken with the forces, from the new velocity, or from it after the
// position has moved.
std::vector<Damping> damping_variants(Step step, const Damping& damping) {
  std::vector<Damping> variants{Damping{}};
  if (!damping.any()) return variants;
  variants.push_back(damping);
  Damping other = damping;
  if (step == Step::Verlet) {
    other.verlet_whole = true;
    variants.push_back(other);
  } else if (damping.drag != 0.0 || damping.drag_step != 0.0) {
    for (DragAt at : {DragAt::NewVelocity, DragAt::AfterPosition}) {
      other.drag_at = at;
      variants.push_back(other);
    }
  }
  return variants;
}

// The row and damping variant nearest the code's run: within float's floor first, then the
// nearest (its damping as fitted, a factor a step not yet turned into its rate at h).
Candidate nearest_row(const std::vector<Method>& rows, const std::vector<Damping>& variants,
                      const BuiltRope& rope, const std::vector<RopeState>& run, bool velocities) {
  const double h = kCheckStep;
  Candidate best;
  for (Method row : rows)
    for (const Damping& d : variants) {
      const Damping here = d.at_step(h);
      Model damped = built_model(rope, kCheckGravity, here);
      Candidate c = measure(row, here, damped, run, h, velocities);
      c.damping = d;
      if (c.within_float != best.within_float ? c.within_float : c.worst < best.worst) best = c;
    }
  return best;
}

}  // namespace

Identified identify(const Bench& bench, Step step, const Damping& damping, bool judged,
                    CheckSection& section) {
  const double h = kCheckStep;
  const BuiltRope rope = bench.build(checked_rope());
  RopeState start;
  for (const BuiltMass& m : rope.masses) start.push_back(m.state);
  std::vector<RopeState> run = bench.run(start, step, h, kCheckGravity, kCheckSteps);
  run.insert(run.begin(), start);
  const bool velocities = step == Step::Euler;

  const std::vector<Method> rows = candidate_rows(step == Step::Verlet);
  const Candidate best = nearest_row(rows, damping_variants(step, damping), rope, run, velocities);
  const MethodInfo& row = method_info(best.row);
  Identified found;
  found.damping = best.damping;
  found.deviation = best.worst;
  found.float_floor = best.floor;
  const std::string where =
      format_text(tr("%d steps of a %d-mass rope falling from rest at h = %s"), kCheckSteps,
                  static_cast<int>(rope.masses.size()), step_text(h).c_str());
  const std::string damped = damping_text(best.damping, step);
  // (A Verlet step that keeps none of the velocity, d = 1, is no row: last_position overwritten.)
  const bool keeps_nothing = step == Step::Verlet && best.damping.verlet >= 1.0 - 1e-6;
  if ((best.worst <= kMatch || best.within_float) && !keeps_nothing) {
    found.method = row.name;
    found.in_float = best.worst > kMatch;
    const std::string how =
        found.in_float
            ? format_text(
                  tr("%s of the step's motion: float's rounding (the code computes in float, and "
                     "2^-24 of the forces it sums allows up to %s here)"),
                  num(best.worst).c_str(), num(best.floor).c_str())
            : format_text(tr("%s of the step's motion (double's rounding)"),
                          num(best.worst).c_str());
    pass(section, "method",
         format_text(tr("%s is %s (springlab's %s), with %s: each of %s matches it to %s"),
                     step_name(step), tr(row.label), row.name, damped.c_str(), where.c_str(),
                     how.c_str()));
    return found;
  }
  const std::string nearest =
      format_text(tr("the nearest, %s with %s, is off by %s of a step's motion (double's rounding "
                     "allows 1e-8, float's %s)"),
                  tr(row.label), damped.c_str(), num(best.worst).c_str(), num(best.floor).c_str());
  if (keeps_nothing) {
    note(section, "not-compared",
         format_text(tr("%s is compared with springlab's rows once the mistake above is mended: it "
                        "keeps none of a mass's velocity from step to step"),
                     step_name(step)));
    return found;
  }
  if (!judged) {
    note(section, "not-compared",
         format_text(tr("%s is compared with springlab's rows once its forces are right (above): "
                        "over %s, %s"),
                     step_name(step), where.c_str(), nearest.c_str()));
    return found;
  }
  if (step == Step::Euler)
    if (const std::optional<Explained> why = explain(
            built_model(rope, kCheckGravity, damping.at_step(h)), run, damping.at_step(h), h)) {
      fail(section, why->key,
           format_text(tr("%s: %s (over %s)"), step_name(step), tr(why->says), where.c_str()));
      return found;
    }
  fail(section, "not-textbook",
       format_text(
           tr("%s is none of springlab's rows (%s), with or without its damping: over %s, %s"),
           step_name(step), rows_text(rows).c_str(), where.c_str(), nearest.c_str()));
  return found;
}

}  // namespace springlab::homework
