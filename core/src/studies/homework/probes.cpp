// The usual mistakes of the rope exercise, each shown by a probe built for it: one step from a
// state chosen so that the mistake, and only it, moves the masses where they should not go.
//   moves:    the identification's rope, one step under gravity from rest: a step that moves
//             nothing is not written yet (the skeleton's);
//   kind:     (Verlet) one free spring stretched by 25 %, a step of h and one of h/2: a force pulls
//             it back by h^2 k s / m (four times less at h/2), a constraint by the same fraction at
//             any step, a force times h instead of h^2 twice less;
//   springs:  3 free masses, one spring stretched and one squeezed, no gravity: the forces a step
//             implies against Hooke's law and its usual misreadings (one end only, the sign, no
//             rest length, added twice, times the step); a second step shows whether the first
//             step's forces were cleared;
//   gravity:  a rope at rest, pinned at one end: free masses fall at g (or at g / m, 2 g, 0, -g,
//             g h: each named), the pin stays.
// The damping's probes are in damping.cpp.
#include <algorithm>
#include <cmath>

#include "parts.hpp"

namespace springlab::homework {

namespace {

double largest(const std::vector<Vec2>& f) {
  double m = 0.0;
  for (const Vec2& v : f) m = std::max(m, v.norm());
  return m;
}

// max |a - b| over the masses, against the size of b.
double relative_gap(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double gap = 0.0;
  for (size_t i = 0; i < a.size(); ++i) gap = std::max(gap, (a[i] - b[i]).norm());
  const double scale = largest(b);
  if (!std::isfinite(gap) || !(gap == gap)) return INFINITY;
  return scale == 0.0 ? (gap == 0.0 ? 0.0 : INFINITY) : gap / scale;
}

std::string forces_text(const std::vector<Vec2>& f) {
  std::string t;
  for (size_t i = 0; i < f.size(); ++i) t += (i ? ", " : "") + vec(f[i]);
  return t;
}

// Spring forces by a rule: Hooke's law on both ends, or one of its usual misreadings.
enum class Rule {
  Hooke,
  Reversed,
  FirstEndOnly,
  SecondEndOnly,
  NoRestLength,
  Twice,
  TimesStep,
  OverStep,
  TimesMass,  // used as the acceleration: the force a step implies is m f
  Assigned,   // forces = f, each spring's replacing what its ends had
  Half        // Verlet's a h^2 / 2
};

// `flipped`: with the wrong sign as well (two slips at once, a misreading's sign reversed).
std::vector<Vec2> spring_forces(const BuiltRope& rope, const RopeState& s, Rule rule,
                                bool flipped = false) {
  std::vector<Vec2> f(s.size(), Vec2::Zero());
  const int n = static_cast<int>(s.size());
  for (const BuiltSpring& spring : rope.springs) {
    if (spring.m1 < 0 || spring.m2 < 0 || spring.m1 >= n || spring.m2 >= n) continue;
    const Vec2 ab = s[spring.m2].x - s[spring.m1].x;
    const double len = ab.norm();
    if (len == 0.0) continue;
    Vec2 on_a = rule == Rule::NoRestLength ? Vec2(spring.k * ab)
                                           : Vec2(spring.k * (len - spring.rest) * ab / len);
    if (rule == Rule::Reversed) on_a = -on_a;
    if (rule == Rule::Twice) on_a *= 2.0;
    if (rule == Rule::TimesStep) on_a *= kProbeH;
    if (rule == Rule::OverStep) on_a /= kProbeH;
    if (rule == Rule::TimesMass) on_a *= kProbeMass;
    if (rule == Rule::Half) on_a *= 0.5;
    if (flipped) on_a = -on_a;
    if (rule == Rule::Assigned) {
      f[spring.m1] = on_a;
      f[spring.m2] = -on_a;
      continue;
    }
    if (rule != Rule::SecondEndOnly) f[spring.m1] += on_a;
    if (rule != Rule::FirstEndOnly) f[spring.m2] -= on_a;
  }
  return f;
}

struct Reading {
  Rule rule;
  const char* key;
  const char* says;
};

const Reading kReadings[] = {
    {Rule::Hooke, "springs", ""},
    {Rule::Reversed, "wrong-sign",
     N_("the spring force has the wrong sign: a stretched spring pushes its masses apart")},
    {Rule::FirstEndOnly, "one-end",
     N_("the spring force acts on one end only (m1): m2 must get the opposite force")},
    {Rule::SecondEndOnly, "one-end",
     N_("the spring force acts on one end only (m2): m1 must get the opposite force")},
    {Rule::NoRestLength, "no-rest-length",
     N_("the rest length is not used: f = k (b - a) pulls as if every spring's rest length were "
        "0")},
    {Rule::Twice, "spring-twice", N_("the spring force is added twice")},
    {Rule::TimesStep, "euler-a-h2",
     N_("the velocity changes by a h^2, not a h: the acceleration is multiplied by delta_t twice "
        "(v += a delta_t)")},
    {Rule::OverStep, "euler-no-dt",
     N_("the velocity changes by a, not a h: the acceleration is not multiplied by delta_t (v += a "
        "delta_t)")},
    {Rule::TimesMass, "spring-no-mass",
     N_("the spring force is used as the acceleration without dividing it by the mass (a = f / m; "
        "with the exercise's masses of 1 kg the slip does not show)")},
    {Rule::Assigned, "forces-assigned",
     N_("each spring's force replaces what its masses had (forces = f instead of forces += f): a "
        "mass with two springs keeps only the last one's")},
    {Rule::Half, "verlet-half",
     N_("the acceleration moves a mass by a h^2 / 2, not a h^2: position Verlet is x_next = x + "
        "(1 - d)(x - x_last) + a delta_t^2 (the 1/2 belongs to x + v h + a h^2 / 2, a step from a "
        "velocity)")},
};

// Returns the rule the code's springs follow (Hooke's law when none of the readings fits).
Rule probe_springs(const Bench& bench, Step step, const Damping& damping, CheckSection& section) {
  const BuiltRope rope = bench.build(three_masses({}));
  RopeState s = at_rest(rope);
  s[0].x = Vec2(0.0, 0.0);
  s[1].x = Vec2(0.625, 0.125);
  s[2].x = Vec2(1.0, 0.0);
  for (MassState& m : s) m.x_last = m.x;
  const std::vector<RopeState> run = bench.run(s, step, kProbeH, Vec2::Zero(), 2);
  const std::vector<double> masses(3, kProbeMass);
  const double d = step == Step::Verlet ? damping.verlet : 0.0;
  const std::vector<Vec2> got = implied_forces(step, masses, s, run[0], kProbeH, d, bench.h_power);
  const Reading* best = &kReadings[0];
  double best_gap = INFINITY;
  bool flipped = false;  // the reading with the wrong sign too
  for (const Reading& r : kReadings) {
    if ((r.rule == Rule::TimesStep || r.rule == Rule::OverStep) && step != Step::Euler) continue;
    if (r.rule == Rule::Half && step != Step::Verlet) continue;
    for (bool flip : {false, true}) {
      if (flip && (r.rule == Rule::Hooke || r.rule == Rule::Reversed)) continue;
      const double gap = relative_gap(got, spring_forces(rope, s, r.rule, flip));
      if (gap < best_gap) best_gap = gap, best = &r, flipped = flip;
    }
  }
  const std::vector<Vec2> hooke = spring_forces(rope, s, Rule::Hooke);
  const std::string measured = format_text(
      tr("one step from springs stretched and squeezed implies forces %s N; Hooke's law gives %s"),
      forces_text(got).c_str(), forces_text(hooke).c_str());
  const Rule rule = best_gap <= 1e-3 ? best->rule : Rule::Hooke;
  if (best_gap <= 1e-3 && best->rule == Rule::Hooke)
    pass(section, "springs",
         format_text(tr("springs: Hooke's law on both ends, with the rest length (the forces a "
                        "step implies match it to %s)"),
                     num(best_gap).c_str()));
  else if (best_gap <= 1e-3) {
    if (flipped) {  // the wrong sign, said first
      const Reading& sign =
          *std::find_if(std::begin(kReadings), std::end(kReadings),
                        [](const Reading& r) { return r.rule == Rule::Reversed; });
      fail(section, sign.key, tr(sign.says));
    }
    fail(section, best->key, std::string(tr(best->says)) + " (" + measured + ")");
  } else
    fail(section, "springs-off",
         format_text(
             tr("springs: the forces are not Hooke's law nor one of its usual misreadings: %s"),
             measured.c_str()));

  // The second step: the forces it implies are those of the first step's end state, by the
  // code's own rule and damping, or, left over, the first step's added to them.
  const RopeState& s1 = run[0];
  const Model model = built_model(rope, Vec2::Zero());
  std::vector<Vec2> due = spring_forces(rope, s1, rule, flipped), kept = due;
  if (step == Step::Euler) {
    const std::vector<Vec2> damped = damping_forces(model, s1, damping);
    for (int i = 0; i < 3; ++i) due[i] += damped[i], kept[i] += damped[i];
  }
  for (int i = 0; i < 3; ++i) kept[i] += got[i];
  const std::vector<Vec2> second =
      implied_forces(step, masses, s1, run[1], kProbeH, d, bench.h_power);
  if (relative_gap(second, due) <= 1e-3)
    pass(section, "cleared", tr("forces are cleared between steps"));
  else if (relative_gap(second, kept) <= 1e-3)
    fail(section, "forces-kept",
         format_text(tr("forces are not cleared between steps: the second step pushed with the "
                        "first step's forces too (%s N "
                        "on mass 0 where %s N is due): set forces to 0 after each step"),
                     vec(second[0]).c_str(), vec(due[0]).c_str()));
  else if (rule == Rule::Hooke && best_gap <= 1e-3)
    fail(section, "second-step-off",
         format_text(tr("the second step's forces are off: %s N on mass 0 where %s N is due (the "
                        "first step's were right)"),
                     vec(second[0]).c_str(), vec(due[0]).c_str()));
  return rule;
}

struct GravityReading {
  double factor;  // of g (Verlet with h_power: as implied)
  const char* key;
  const char* says;
};

void probe_gravity(const Bench& bench, Step step, const Damping& damping, Rule rule,
                   bool constraints, CheckSection& section) {
  const BuiltRope rope = bench.build(three_masses({0}));
  const RopeState s = at_rest(rope);
  const Vec2 g(0.0, -8.0);
  const RopeState after = bench.run(s, step, kProbeH, g, 1).back();
  const std::vector<double> masses(3, kProbeMass);

  const double pin_moved =
      (after[0].x - s[0].x).norm() + (step == Step::Euler ? after[0].v.norm() : 0.0);
  if (!(pin_moved == 0.0))
    fail(section, "pin-moves",
         format_text(tr("a pinned mass moves: mass 0 went from %s to %s in one step (pinned masses "
                        "get no force, no gravity "
                        "and no motion)"),
                     vec(s[0].x).c_str(), vec(after[0].x).c_str()));
  else
    pass(section, "pins", tr("pins: the pinned mass stays where it is"));

  // Gravity alone: what the step implies less what the code's springs give (nothing, by Hooke's
  // law, at rest length; a constraint holds a horizontal rope to within (g h^2)^2 / L).
  std::vector<Vec2> got = implied_forces(
      step, masses, s, after, kProbeH, step == Step::Verlet ? damping.verlet : 0.0, bench.h_power);
  if (!constraints) {
    const std::vector<Vec2> springs = spring_forces(rope, s, rule);
    for (int i = 1; i < 3; ++i) got[i] -= springs[i];
  }
  const Vec2 a = got[1] / kProbeMass;
  const double along = a.dot(g) / g.squaredNorm(), across = (a - along * g).norm() / g.norm();
  const GravityReading readings[] = {
      {1.0, "gravity", ""},
      {1.0 / kProbeMass, "gravity-no-mass",
       N_("gravity was added as a force without its mass (the force is m g)")},
      {2.0, "gravity-twice",
       N_("gravity is applied twice (added as m g to the forces and as g to the acceleration?)")},
      {0.0, "no-gravity", N_("gravity is left out")},
      {-1.0, "gravity-sign", N_("gravity has the wrong sign")},
      {kProbeMass, "gravity-times-mass",
       N_("gravity was multiplied by the mass where it is an acceleration (a = g, not m g)")},
      {kProbeH, "gravity-times-step",
       N_("gravity was multiplied by the step (its force is m g, not m g h)")},
      {0.5, "verlet-half",
       N_("gravity moves a mass by g h^2 / 2 in a step, not g h^2: position Verlet is x_next = x + "
          "(1 - d)(x - x_last) + a delta_t^2")},
      {1.0 / kProbeH, "verlet-a-h",
       N_("gravity moves a mass by g h in a step, not g h^2: the acceleration is multiplied by "
          "delta_t "
          "once (x_next = x + (1 - d)(x - x_last) + a delta_t^2)")},
  };
  // The nearest reading within 1e-3 of its own size (of h's, for none: 0 and h are 1e-3 apart).
  const GravityReading* found = nullptr;
  double nearest = INFINITY;
  for (const GravityReading& r : readings) {
    const double size = std::max(std::abs(r.factor), kProbeH),
                 off = std::abs(along - r.factor) / size;
    if (off <= 1e-3 && across <= 1e-3 * std::max(1.0, std::abs(r.factor)) && off < nearest)
      nearest = off, found = &r;
  }
  if (found && found->factor == 1.0)
    pass(section, "gravity",
         format_text(tr("gravity: each free mass falls at g = %s m/s^2 (to %s)"), vec(g).c_str(),
                     num(std::abs(along - 1.0) + across).c_str()));
  else if (found && ((found->factor == kProbeH && rule == Rule::TimesStep) ||
                     (found->factor == 1.0 / kProbeH && rule == Rule::OverStep) ||
                     (found->factor == 0.5 && rule == Rule::Half)))
    note(section, "gravity", tr("gravity: scaled with the springs' forces (above)"));
  else if (found &&
           !((found->factor == 1.0 / kProbeH || found->factor == 0.5) && step == Step::Euler))
    fail(section, found->key,
         format_text(tr("%s: a free mass falls at %s m/s^2 where g = %s"), tr(found->says),
                     vec(a).c_str(), vec(g).c_str()));
  else
    fail(section, "gravity-off",
         format_text(tr("gravity: a free mass falls at %s m/s^2 where g = %s"), vec(a).c_str(),
                     vec(g).c_str()));
}

}  // namespace

bool probe_moves(const Bench& bench, Step step, CheckSection& section) {
  // Under gravity from rest, then (should that move nothing: a step that loses gravity) moving
  // together with no gravity.
  const BuiltRope rope = bench.build(checked_rope());
  const RopeState s = at_rest(rope);
  RopeState moving = s;
  for (MassState& m : moving) {
    m.v = Vec2(1.0, 0.5);
    m.x_last = m.x - kCheckStep * m.v;
  }
  bool positions = false, velocities = false;  // under gravity from rest: what changed
  auto moved = [&](const RopeState& from, const Vec2& g) {
    const RopeState after = bench.run(from, step, kCheckStep, g, 1).back();
    for (size_t i = 0; i < from.size(); ++i) {
      positions = positions || !(after[i].x == from[i].x);
      velocities = velocities || !(after[i].v == from[i].v);
    }
    return positions || velocities;
  };
  if (moved(s, kCheckGravity)) {
    // Every other probe reads the velocities a step leaves: one that never stores them is said
    // alone (its forces would read as none, its row as none).
    if (step == Step::Euler && positions && !velocities) {
      fail(section, "velocity-not-stored",
           tr("simulateEuler never stores the new velocity: under gravity the masses move, but "
              "every mass's velocity is still what it was after the step (m->velocity += a "
              "delta_t, or assign the new velocity to m->velocity)"));
      return false;
    }
    return true;
  }
  if (moved(moving, Vec2::Zero())) return true;
  fail(section, "not-written",
       step == Step::Euler ? tr("simulateEuler moves nothing yet: after a step every mass is where "
                                "it was, under gravity or moving. "
                                "Part 2: each spring's force by Hooke's law, gravity on each free "
                                "mass, then its new velocity and position")
                           : tr("simulateVerlet moves nothing yet: after a step every mass is "
                                "where it was, under gravity or moving. Part "
                                "3: the springs' forces and gravity, then x_next = x + (x - "
                                "x_last) + a h^2, and last_position = x"));
  return false;
}

bool probe_verlet_kind(Bench& bench, CheckSection& section) {
  // One spring, both ends free, stretched by 25 %, no gravity, at rest: a force pulls its masses
  // back by h^2 k s / m a step (2e-4 of the stretch here, four times less at h/2); a constraint
  // puts back the same fraction of the stretch at any step.
  const BuiltRope rope = bench.build(pair_rope());
  RopeState s = at_rest(rope);
  s[1].x = s[1].x_last = Vec2(1.25, 0.0);
  auto taken = [&](double h) {
    const RopeState after = bench.run(s, Step::Verlet, h, Vec2::Zero(), 1).back();
    return (1.25 - (after[1].x - after[0].x).norm()) / 0.25;
  };
  const double at_h = taken(kProbeH), at_half = taken(0.5 * kProbeH);
  const double ratio = at_half == 0.0 ? INFINITY : at_h / at_half;
  if (at_h > 0.1 && std::abs(std::log2(ratio)) <= 0.3) {
    const double length = 1.25 - 0.25 * at_h;
    if (std::abs(length - 1.0) <= 1e-6)
      pass(section, "constraints",
           format_text(tr("simulateVerlet holds its springs as constraints (position-based, as CS "
                          "184's rope and the "
                          "exercise's \"solving constraints\" have it): a spring stretched by 25 "
                          "%% is back at its rest "
                          "length after one step (to %s m), at h and at h/2 alike"),
                       num(std::abs(length - 1.0)).c_str()));
    else
      pass(section, "constraints",
           format_text(tr("simulateVerlet holds its springs as constraints (position-based, as CS "
                          "184's rope and the "
                          "exercise's \"solving constraints\" have it): a spring stretched by 25 "
                          "%% is pulled %s %% of the "
                          "way back in one step, at h and at h/2 alike"),
                       num(100.0 * at_h).c_str()));
    return true;
  }
  if (at_h > 0.0 && std::isfinite(ratio) && std::abs(std::log2(ratio) - 1.0) <= 0.3) {
    bench.h_power = 1;
    fail(section, "verlet-a-h",
         format_text(tr("the acceleration is multiplied by delta_t once, not by delta_t^2: a "
                        "spring stretched by 25 %% is "
                        "pulled %s %% of the way back in a step of h and %s %% at h/2, where a "
                        "force's pull goes as h^2 "
                        "(x_next = x + (1 - d)(x - x_last) + a delta_t^2)"),
                     num(100.0 * at_h).c_str(), num(100.0 * at_half).c_str()));
  }
  return false;
}

void probe_forces(const Bench& bench, Step step, const Damping& damping, CheckSection& section) {
  const Rule rule = probe_springs(bench, step, damping, section);
  probe_gravity(bench, step, damping, rule, false, section);
}

void probe_constraint_step(const Bench& bench, const Damping& damping, CheckSection& section) {
  probe_gravity(bench, Step::Verlet, damping, Rule::Hooke, true, section);
}

}  // namespace springlab::homework
