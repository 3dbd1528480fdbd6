// The damping a step applies, fitted form by form from single steps of three free masses, springs
// at their rest length, no gravity (so that nothing but damping changes a velocity):
//   together:  every mass at u = (1, 0.5) m/s: only a global drag acts (no spring changes length
//              or turns): f = -c u on each mass; twice on the middle one where it is applied once a
//              spring; Verlet's factor likewise, x1 - x = (1 - d)(x - x_last), and last_position;
//   across:    the middle mass at w = (0, 1) m/s across its springs: the lecture's damping along
//              the spring sees no stretching and gives nothing; damping along the relative
//              velocity pulls the ends by +k_r w each and the middle by -2 k_r w;
//   along:     the middle mass at (1, 0) m/s along its springs: both spring dampings act, the ends
//              get +(k_p + k_r) w each.
// Each form is then named with its coefficient; a coefficient of the wrong sign pushes masses
// along their motion and is a mistake.
#include <cmath>

#include "parts.hpp"

namespace springlab::homework {

namespace {

// What the step did to each mass: Euler's implied force m (v1 - v0) / h; Verlet's kept fraction
// (x1 - x) . (x - x_last) / |x - x_last|^2.
struct Motion {
  RopeState before, after;
  double mass = kProbeMass;  // each mass's, kg
  double h = kProbeH;        // the step, s
};

Motion move(const Bench& bench, const BuiltRope& rope, Step step, const Vec2 velocity[3],
            double h = kProbeH) {
  Motion m;
  m.h = h;
  m.mass = rope.masses[0].mass;
  m.before = at_rest(rope);
  for (int i = 0; i < 3; ++i) {
    if (step == Step::Euler)
      m.before[i].v = velocity[i];
    else
      m.before[i].x_last = m.before[i].x - kProbeH * velocity[i];
  }
  m.after = bench.run(m.before, step, h, Vec2::Zero(), 1).back();
  return m;
}

// The force a motion's step implies on mass i, less what the same step gives masses at rest there
// (`still`: the springs' own forces, whatever rule the code has for them), so damping alone.
Vec2 force(const Motion& m, const Motion& still, int i) {
  return m.mass * ((m.after[i].v - m.before[i].v) - (still.after[i].v - still.before[i].v)) / m.h;
}

// A coefficient worth naming: beyond rounding of the probe's own scale (m / h = 256 N s/m).
bool present(double coefficient) {
  return std::abs(coefficient) > 1e-7 * kProbeMass / kProbeH;
}

void last_position_line(const Motion& m, CheckSection& section) {
  const MassState &s = m.before[1], &after = m.after[1];
  const double advanced = (after.x_last - s.x).norm(), stale = (after.x_last - s.x_last).norm(),
               to_new = (after.x_last - after.x).norm();
  if (advanced <= 1e-12)
    pass(section, "last-position",
         tr("last_position: advanced to the position the step started from"));
  else if (stale <= 1e-12)
    fail(section, "last-stale",
         tr("last_position is never advanced: after a step it still holds the position before the "
            "last one, so every "
            "step repeats the first step's velocity"));
  else if (to_new <= 1e-12)
    fail(section, "last-is-new",
         tr("last_position is set to the new position (keep the old one in temp_position and store "
            "that)"));
  else
    fail(section, "last-position",
         format_text(
             tr("last_position after a step is %s, not the position %s the step started from"),
             vec(after.x_last).c_str(), vec(s.x).c_str()));
}

// Verlet's factor d from the masses moving together; last_position from the same step.
Damping verlet_damping(const Bench& bench, const BuiltRope& rope, CheckSection& section) {
  const Vec2 u(1.0, 0.5);
  const Vec2 together[3] = {u, u, u};
  const Vec2 zero[3] = {Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};
  const Motion m = move(bench, rope, Step::Verlet, together),
               still = move(bench, rope, Step::Verlet, zero);
  double d[3];
  for (int i = 0; i < 3; ++i) {
    const Vec2 moved = (m.after[i].x - m.before[i].x) - (still.after[i].x - still.before[i].x);
    d[i] = 1.0 - moved.dot(kProbeH * u) / (kProbeH * kProbeH * u.squaredNorm());
  }
  const double ends = 0.5 * (d[0] + d[2]), middle = d[1];
  Damping out;
  const double scale = std::max(std::abs(ends), std::abs(middle));
  if (!std::isfinite(scale)) {
    fail(section, "damping-not-finite",
         tr("masses moving together get non-finite positions in one step"));
    return out;
  }
  if (scale > 1e-9 && std::abs(middle - 2.0 * ends) <= 1e-3 * scale && std::abs(ends) > 1e-9) {
    fail(section, "damping-per-spring",
         format_text(tr("damping is applied twice on the middle masses: once per spring, so a mass "
                        "with two springs gets "
                        "d = %s and the ends %s (apply it once a mass, in the masses' loop)"),
                     num(middle).c_str(), num(ends).c_str()));
    out.verlet = ends;
  } else if (scale > 1e-9 && std::abs(middle - ends) > 1e-6 * scale) {
    fail(section, "damping-uneven",
         format_text(tr("damping differs from mass to mass: d = %s in the middle, %s at the ends"),
                     num(middle).c_str(), num(ends).c_str()));
    out.verlet = middle;
  } else {
    out.verlet = std::abs(middle) <= 1e-12 ? 0.0 : middle;
    if (out.verlet < 0.0)
      fail(section, "damping-sign",
           format_text(tr("the damping has the wrong sign: (x - x_last) is multiplied by %s, more "
                          "than 1, so every step "
                          "speeds the masses up (x_next = x + (1 - d)(x - x_last) + a h^2, with a "
                          "small d > 0)"),
                       num(1.0 - out.verlet).c_str()));
    else if (std::abs(1.0 - out.verlet) <= 1e-6 &&
             (m.after[1].x_last - m.before[1].x).norm() <= 1e-12) {
      fail(section, "last-overwritten",
           tr("the step moves masses as if x - x_last were 0: last_position is set to position "
              "before x_next is computed from it, so every step forgets the velocity (compute "
              "x_next from the old last_position first, keeping position in temp_position, then "
              "store temp_position in last_position)"));
    } else if (out.verlet > 0.5)
      fail(section, "verlet-d-swapped",
           format_text(tr("(x - x_last) is multiplied by %s, so a mass keeps only that much of its "
                          "velocity each step: "
                          "that is d where 1 - d belongs (x_next = x + (1 - d)(x - x_last) + a "
                          "h^2, d = 0.00005)"),
                       num(1.0 - out.verlet).c_str()));
    else if (out.verlet == 0.0)
      note(section, "no-damping",
           tr("no damping: masses moving together keep their velocity (Part 4 adds a small d, "
              "x_next = x + (1 - d)(x - "
              "x_last) + a h^2)"));
    else
      pass(section, "damping",
           format_text(tr("damping: each step keeps 1 - d of a mass's velocity, d = %s (fitted "
                          "from masses moving together)"),
                       num(out.verlet).c_str()));
  }
  last_position_line(m, section);
  return out;
}

}  // namespace

std::string damping_text(const Damping& d, Step step) {
  if (step == Step::Verlet) {
    if (d.verlet == 0.0) return tr("no damping");
    return d.verlet_whole
               ? format_text(tr("damping factor d = %s on the whole displacement, x + (1 - d)((x - "
                                "x_last) + a h^2)"),
                             num(d.verlet).c_str())
               : format_text(
                     tr("damping factor d = %s on (x - x_last), x + (1 - d)(x - x_last) + a h^2"),
                     num(d.verlet).c_str());
  }
  if (!d.any()) return tr("no damping");
  std::string t;
  auto add = [&t](const std::string& part) { t += (t.empty() ? "" : tr("; ")) + part; };
  if (d.drag_step != 0.0)
    add(format_text(tr("a global damping factor on the velocity, v = (1 - d) v each step, d = %s "
                       "(a drag of rate d / h: halving h doubles the damping a second)"),
                    num(d.drag_step).c_str()));
  else if (d.drag != 0.0 && d.drag_rate)
    add(format_text(tr("a global drag on the velocity, a = f / m - c v, c = %s 1/s (the same rate "
                       "for any mass: a force "
                       "of c m v)"),
                    num(d.drag).c_str()));
  else if (d.drag != 0.0)
    add(format_text(tr("a global drag f = -c v, c = %s N s/m"), num(d.drag).c_str()));
  // Where the drag is taken, in the symbols of its form: (1 - d) a step, or (1 - c h).
  const bool factor = d.drag_step != 0.0;
  // (Explicit Euler's position moves by the old velocity either way: there the two are one.)
  if (d.drag_at == DragAt::NewVelocity && (d.drag != 0.0 || factor))
    t += factor ? tr(", taken from the new velocity: v = (1 - d)(v + a h)")
                : tr(", taken from the new velocity: v = (1 - c h)(v + a h)");
  if (d.drag_at == DragAt::AfterPosition && (d.drag != 0.0 || factor))
    t += factor ? tr(", taken from the new velocity after the position has moved by the undamped "
                     "one: x += (v + a h) h, then v = (1 - d)(v + a h)")
                : tr(", taken from the new velocity after the position has moved by the undamped "
                     "one: x += (v + a h) h, then v = (1 - c h)(v + a h)");
  if (d.along != 0.0)
    add(format_text(tr("the lecture's spring damping, along the spring, f_b = -k_d ((v_b - v_a) . "
                       "u) u, k_d = %s N s/m"),
                    num(d.along).c_str()));
  if (d.relative != 0.0)
    add(format_text(tr("damping along the relative velocity, f_b = -k_d (v_b - v_a), k_d = %s N "
                       "s/m (it damps the "
                       "rope's bending and spinning too, not only its springs' stretching)"),
                    num(d.relative).c_str()));
  return t;
}

namespace {

// The drag c (from f = -c u) that masses moving together feel in one step of h.
double drag_felt(const Bench& bench, const BuiltRope& rope, double h) {
  const Vec2 u(1.0, 0.5), zero = Vec2::Zero();
  const Vec2 together[3] = {u, u, u}, none[3] = {zero, zero, zero};
  const Motion t = move(bench, rope, Step::Euler, together, h),
               still = move(bench, rope, Step::Euler, none, h);
  return -force(t, still, 1).dot(u) / u.squaredNorm();
}

// The drag `drag` (c from f = -c u on the probe masses) measured again on masses four times
// heavier (last: the code holds the rope built last): a drag written as an acceleration
// (a -= c v) is four times the force there; as a force, the same. Whether it is the former.
bool euler_drag_is_a_rate(const Bench& bench, double drag) {
  const double c_heavy = drag_felt(bench, bench.build(three_heavy_masses()), kProbeH);
  return std::abs(c_heavy - 4.0 * drag) <= 1e-3 * std::abs(4.0 * drag);
}

// Whether the drag `drag` (c at kProbeH) is a factor a step, v = (1 - d) v: at twice the step
// such a drag takes the same d, so the force it implies, m d / h, is half as large; a drag written
// with h (v -= c v h, or a force) is the same at any step.
bool euler_drag_is_per_step(const Bench& bench, double drag) {
  const double c_double = drag_felt(bench, bench.build(three_masses({})), 2.0 * kProbeH);
  return std::abs(c_double - 0.5 * drag) <= 1e-3 * std::abs(0.5 * drag);
}

// The verdict on an even damping found: a wrong sign fails, none is a note, else it passes,
// said in its forms (damping_text).
void euler_damping_verdict(const Damping& out, CheckSection& section) {
  const std::string forms = damping_text(out, Step::Euler);
  if (out.drag < 0.0 || out.drag_step < 0.0 || out.along < 0.0 || out.relative < 0.0)
    fail(section, "damping-sign",
         format_text(tr("the damping has the wrong sign: it pushes the masses along their motion "
                        "(%s: a damping "
                        "coefficient must be positive, f = -c v opposes the velocity)"),
                     forms.c_str()));
  else if (!out.any())
    note(section, "no-damping",
         tr("no damping: masses moving together, or apart, keep their velocity (Part 2 adds a "
            "global damping, a drag f "
            "= -c v)"));
  else
    pass(section, "damping",
         format_text(
             tr("damping: %s (fitted from single steps of masses moving together, across and along "
                "their springs)"),
             forms.c_str()));
}

Damping euler_damping(const Bench& bench, const BuiltRope& rope, CheckSection& section) {
  Damping out;
  const Vec2 u(1.0, 0.5), across(0.0, 1.0), along(1.0, 0.0), zero = Vec2::Zero();
  const Vec2 together[3] = {u, u, u}, middle_across[3] = {zero, across, zero},
             middle_along[3] = {zero, along, zero}, none[3] = {zero, zero, zero};

  // Together: a drag alone, c from f = -c u.
  const Motion still = move(bench, rope, Step::Euler, none);
  const Motion t = move(bench, rope, Step::Euler, together);
  double c[3];
  for (int i = 0; i < 3; ++i) c[i] = -force(t, still, i).dot(u) / u.squaredNorm();
  const double ends = 0.5 * (c[0] + c[2]), middle = c[1];
  const double scale = std::max(std::abs(ends), std::abs(middle));
  if (!std::isfinite(scale)) {
    fail(section, "damping-not-finite",
         tr("masses moving together get non-finite velocities in one step"));
    return out;
  }
  bool uneven = false;
  if (present(ends) && std::abs(middle - 2.0 * ends) <= 1e-3 * scale) {
    fail(section, "damping-per-spring",
         format_text(
             tr("damping is applied twice on the middle masses: once per spring, so a mass with "
                "two springs gets "
                "drag c = %s N s/m and the ends %s (apply it once a mass, in the masses' loop)"),
             num(middle).c_str(), num(ends).c_str()));
    out.drag = ends;
    uneven = true;
  } else if (present(scale) && std::abs(middle - ends) > 1e-6 * scale) {
    fail(section, "damping-uneven",
         format_text(tr("damping differs from mass to mass: drag c = %s N s/m in the middle, %s at "
                        "the ends"),
                     num(middle).c_str(), num(ends).c_str()));
    out.drag = middle;
    uneven = true;
  } else {
    out.drag = present(middle) ? middle : 0.0;
  }

  // Across, then along: the spring dampings from the ends' forces.
  const Motion a = move(bench, rope, Step::Euler, middle_across);
  const Motion l = move(bench, rope, Step::Euler, middle_along);
  const double relative = force(a, still, 0).dot(across),
               relative_other = force(a, still, 2).dot(across);
  const double both = force(l, still, 0).dot(along), both_other = force(l, still, 2).dot(along);
  if (!std::isfinite(relative + relative_other + both + both_other)) {
    fail(section, "damping-not-finite",
         tr("masses moving apart get non-finite velocities in one step"));
    return out;
  }
  const double spread =
      std::max({std::abs(relative - relative_other), std::abs(both - both_other)});
  if (present(spread) &&
      spread > 1e-3 * std::max({std::abs(relative), std::abs(both), std::abs(relative_other),
                                std::abs(both_other)})) {
    fail(section, "damping-one-end",
         format_text(tr("the spring damping acts on one end of a spring only: the ends of a mass "
                        "moving along its springs "
                        "get %s and %s N s/m (each spring's damping acts on both its masses, "
                        "opposite ways)"),
                     num(both).c_str(), num(both_other).c_str()));
    return out;
  }
  out.relative = present(relative) ? relative : 0.0;
  out.along = present(both - relative) ? both - relative : 0.0;
  if (out.drag != 0.0 && !uneven && euler_drag_is_a_rate(bench, out.drag)) {
    out.drag /= kProbeMass;
    out.drag_rate = true;
    if (euler_drag_is_per_step(bench, out.drag * kProbeMass)) {
      out.drag_step = out.drag * kProbeH;  // d = c h
      out.drag = 0.0;
    }
  }

  if (uneven) return out;
  euler_damping_verdict(out, section);
  return out;
}

}  // namespace

Damping probe_damping(const Bench& bench, Step step, CheckSection& section) {
  const BuiltRope rope = bench.build(three_masses({}));
  return step == Step::Euler ? euler_damping(bench, rope, section)
                             : verlet_damping(bench, rope, section);
}

}  // namespace springlab::homework
