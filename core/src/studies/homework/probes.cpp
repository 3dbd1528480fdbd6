// The usual mistakes of the rope exercise, each shown by a probe built for it: one step from a
// state chosen so that the mistake, and only it, moves the masses where they should not go.
//   springs:  3 free masses, one spring stretched and one squeezed, no gravity: the forces a
//             step implies against Hooke's law and the patterns of its usual misreadings (one
//             end only, the sign, no rest length, added twice);
//             a second step shows whether the first step's forces were cleared;
//   gravity:  a rope at rest, pinned at one end: free masses fall at g, the pin stays;
//   motion:   (first) 3 free masses moving together, springs at rest: the damping each mass gets (alike,
//             or once per spring), and where Verlet's last_position goes.
#include <algorithm>
#include <cmath>
#include <optional>

#include "parts.hpp"

namespace springlab::homework {

namespace {

constexpr double kH = 1.0 / 1024;

RopeRequest three_masses(std::vector<int> pinned) { return {Vec2(0, 0), Vec2(1, 0), 3, 0.25, 64.0, std::move(pinned)}; }

RopeState at_rest(const BuiltRope& rope) {
  RopeState s;
  for (const BuiltMass& m : rope.masses) {
    MassState state;
    state.x = state.x_last = m.state.x;
    s.push_back(state);
  }
  return s;
}

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
  if (!std::isfinite(gap)) return INFINITY;
  return scale == 0.0 ? (gap == 0.0 ? 0.0 : INFINITY) : gap / scale;
}

std::string forces_text(const std::vector<Vec2>& f) {
  std::string t;
  for (size_t i = 0; i < f.size(); ++i) t += (i ? ", " : "") + vec(f[i]);
  return t;
}

// Spring forces by a rule: Hooke's law on both ends, or one of its usual misreadings.
enum class Rule { Hooke, Reversed, FirstEndOnly, SecondEndOnly, NoRestLength, Twice };

std::vector<Vec2> spring_forces(const BuiltRope& rope, const RopeState& s, double rest, Rule rule) {
  std::vector<Vec2> f(s.size(), Vec2::Zero());
  for (const BuiltSpring& spring : rope.springs) {
    if (spring.m1 < 0 || spring.m2 < 0) continue;
    const Vec2 ab = s[spring.m2].x - s[spring.m1].x;
    const double len = ab.norm();
    Vec2 on_a = rule == Rule::NoRestLength ? Vec2(spring.k * ab) : Vec2(spring.k * (len - rest) * ab / len);
    if (rule == Rule::Reversed) on_a = -on_a;
    if (rule == Rule::Twice) on_a *= 2.0;
    if (rule != Rule::SecondEndOnly) f[spring.m1] += on_a;
    if (rule != Rule::FirstEndOnly) f[spring.m2] -= on_a;
  }
  return f;
}

// Returns the rule the code's springs follow (Hooke's law when none of the readings fits).
Rule probe_springs(RopeCode& code, Step step, double damping, CheckSection& section) {
  const RopeRequest request = three_masses({});
  const BuiltRope rope = code.build(request);
  RopeState s = at_rest(rope);
  s[0].x = Vec2(0.0, 0.0);
  s[1].x = Vec2(0.625, 0.125);
  s[2].x = Vec2(1.0, 0.0);
  for (MassState& m : s) m.x_last = m.x;
  code.set_state(s);
  const std::vector<RopeState> run = code.simulate(step, kH, Vec2::Zero(), 2);
  const std::vector<double> masses(3, 0.25);
  const double d = step == Step::Verlet ? damping : 0.0;
  const std::vector<Vec2> got = implied_forces(step, masses, s, run[0], kH, d);
  const double rest = 0.5;
  struct Reading {
    Rule rule;
    const char* says;
  };
  const Reading readings[] = {
      {Rule::Hooke, ""},
      {Rule::Reversed, "the spring force has the wrong sign: a stretched spring pushes its masses apart"},
      {Rule::FirstEndOnly, "the spring force acts on one end only (m1): m2 must get the opposite force"},
      {Rule::SecondEndOnly, "the spring force acts on one end only (m2): m1 must get the opposite force"},
      {Rule::NoRestLength, "the rest length is not used: f = k (b - a) pulls as if every spring's rest length were 0"},
      {Rule::Twice, "the spring force is added twice"},
  };
  const Reading* best = &readings[0];
  double best_gap = INFINITY;
  for (const Reading& r : readings) {
    const double gap = relative_gap(got, spring_forces(rope, s, rest, r.rule));
    if (gap < best_gap) best_gap = gap, best = &r;
  }
  const std::vector<Vec2> hooke = spring_forces(rope, s, rest, Rule::Hooke);
  const std::string measured = "one step from springs stretched and squeezed implies forces " + forces_text(got) +
                               " N; Hooke's law gives " + forces_text(hooke);
  const Rule rule = best_gap <= 1e-3 ? best->rule : Rule::Hooke;
  if (best_gap <= 1e-3 && best->rule == Rule::Hooke)
    pass(section, "springs: Hooke's law on both ends, with the rest length (the forces a step implies match it to " +
                      num(best_gap) + ")");
  else if (best_gap <= 1e-3)
    fail(section, std::string(best->says) + " (" + measured + ")");
  else
    fail(section, "springs: the forces are not Hooke's law nor one of its usual misreadings: " + measured);

  // The second step: the forces it implies are those of the first step's end state, by the
  // code's own rule (and the drag at its velocity), or, left over, the first step's added to them.
  const RopeState& s1 = run[0];
  std::vector<Vec2> due = spring_forces(rope, s1, rest, rule), kept = due;
  for (int i = 0; i < 3; ++i) {
    if (step == Step::Euler) due[i] -= damping * s1[i].v, kept[i] -= damping * s1[i].v;
    kept[i] += got[i];
  }
  const std::vector<Vec2> second = implied_forces(step, masses, s1, run[1], kH, d);
  if (relative_gap(second, due) <= 1e-3) pass(section, "forces are cleared between steps");
  else if (relative_gap(second, kept) <= 1e-3)
    fail(section, "forces are not cleared between steps: the second step pushed with the first step's forces too (" +
                      vec(second[0]) + " N on mass 0 where " + vec(due[0]) + " N is due): set forces to 0 after each step");
  else
    fail(section, "the second step's forces are off: " + vec(second[0]) + " N on mass 0 where " + vec(due[0]) + " N is due");
  return rule;
}

void probe_gravity(RopeCode& code, Step step, double damping, Rule rule, CheckSection& section, bool pin_only = false) {
  const RopeRequest request = three_masses({0});
  const BuiltRope rope = code.build(request);
  const RopeState s = at_rest(rope);
  code.set_state(s);
  const Vec2 g(0.0, -8.0);
  const RopeState after = code.simulate(step, kH, g, 1).back();
  const std::vector<double> masses(3, 0.25);

  const double pin_moved = (after[0].x - s[0].x).norm() + (step == Step::Euler ? after[0].v.norm() : 0.0);
  if (pin_moved != 0.0 || !std::isfinite(pin_moved))
    fail(section, "a pinned mass moves: mass 0 went from " + vec(s[0].x) + " to " + vec(after[0].x) +
                      " in one step (pinned masses get no force, no gravity and no motion)");
  else pass(section, "pins: the pinned mass stays where it is");
  if (pin_only) return;

  // Gravity alone: what the step implies less what the code's springs give (nothing, by Hooke's
  // law, at rest length).
  std::vector<Vec2> got = implied_forces(step, masses, s, after, kH, step == Step::Verlet ? damping : 0.0);
  const std::vector<Vec2> springs = spring_forces(rope, s, 0.5, rule);
  const std::vector<Vec2> weight = {Vec2::Zero(), 0.25 * g, 0.25 * g};
  for (int i = 0; i < 3; ++i) got[i] = i == 0 ? Vec2::Zero() : Vec2(got[i] - springs[i]);
  const double gap = relative_gap(got, weight);
  if (gap <= 1e-3) pass(section, "gravity: each free mass falls at g = " + vec(g) + " m/s^2 (to " + num(gap) + ")");
  else {
    const Vec2 a = got[1] / 0.25;
    const bool no_mass = (a - g / 0.25).norm() <= 1e-3 * g.norm() / 0.25;
    fail(section, "gravity: a free mass falls at " + vec(a) + " m/s^2 where g = " + vec(g) +
                      (no_mass ? ": gravity was added as a force without its mass (the force is m g)" : ""));
  }
}

double probe_motion(RopeCode& code, Step step, CheckSection& section) {
  const BuiltRope rope = code.build(three_masses({}));
  RopeState s = at_rest(rope);
  const Vec2 u(1.0, 0.5);
  for (MassState& m : s) {
    if (step == Step::Euler) m.v = u;
    else m.x_last = m.x - kH * u;
  }
  code.set_state(s);
  const RopeState after = code.simulate(step, kH, Vec2::Zero(), 1).back();
  // Each mass's damping: Euler's drag c from v1 = v - h c/m v; Verlet's d from x1 - x = (1 - d)(x - x_last).
  double damping[3];
  for (int i = 0; i < 3; ++i) {
    damping[i] = step == Step::Euler ? 0.25 * (u - after[i].v).dot(u) / (kH * u.squaredNorm())
                                     : 1.0 - (after[i].x - s[i].x).dot(u * kH) / (kH * kH * u.squaredNorm());
  }
  const char* what = step == Step::Euler ? "drag c" : "damping factor d";
  const double ends = 0.5 * (damping[0] + damping[2]), middle = damping[1];
  const double scale = std::max(std::abs(ends), std::abs(middle));
  if (!std::isfinite(scale)) fail(section, "masses moving together get non-finite positions or velocities in one step");
  else if (scale < 1e-9 || std::abs(middle - ends) <= 1e-6 * scale)
    pass(section, std::string("damping: every mass gets the same ") + what + " (" + num(middle) + ")");
  else if (std::abs(middle - 2.0 * ends) <= 1e-3 * scale)
    fail(section, std::string("damping is applied twice on the middle masses: once per spring, so a mass with two springs "
                              "gets ") + what + " " + num(middle) + " and the ends " + num(ends) +
                      " (apply it once a mass, in the masses' loop)");
  else
    fail(section, std::string("damping differs from mass to mass: ") + what + " " + num(middle) + " in the middle, " +
                      num(ends) + " at the ends");

  if (step == Step::Verlet) {
    const double advanced = (after[1].x_last - s[1].x).norm(), stale = (after[1].x_last - s[1].x_last).norm(),
                 to_new = (after[1].x_last - after[1].x).norm();
    if (advanced <= 1e-12) pass(section, "last_position: advanced to the position the step started from");
    else if (stale <= 1e-12)
      fail(section, "last_position is never advanced: after a step it still holds the position before the last one, "
                    "so every step repeats the first step's velocity");
    else if (to_new <= 1e-12)
      fail(section, "last_position is set to the new position (keep the old one in temp_position and store that)");
    else fail(section, "last_position after a step is " + vec(after[1].x_last) + ", not the position " + vec(s[1].x) + " the step started from");
  }
  return std::isfinite(ends) ? ends : 0.0;
}

}  // namespace

std::optional<std::string> constraint_probe(RopeCode& code) {
  // One spring, both ends free, stretched by 25 %, no gravity, at rest: a force pulls its masses
  // back by h^2 k s / m a step (2e-4 of the stretch here); a constraint puts the length back.
  const BuiltRope rope = code.build({Vec2(0, 0), Vec2(1, 0), 2, 0.25, 64.0, {}});
  RopeState s = at_rest(rope);
  s[1].x = s[1].x_last = Vec2(1.25, 0.0);
  code.set_state(s);
  const RopeState after = code.simulate(Step::Verlet, kH, Vec2::Zero(), 1).back();
  const double length = (after[1].x - after[0].x).norm(), taken = (1.25 - length) / 0.25;
  if (!(taken > 0.1)) return std::nullopt;  // a force's pull (or nothing sane): the force probes say
  if (std::abs(length - 1.0) <= 1e-9)
    return "a spring stretched by 25 % is back at its rest length after one step (to " + num(std::abs(length - 1.0)) + " m)";
  return "a spring stretched by 25 % is pulled " + num(100.0 * taken) + " % of the way back in one step";
}

void probe_constraint_mistakes(RopeCode& code, CheckSection& section) {
  probe_motion(code, Step::Verlet, section);
  probe_gravity(code, Step::Verlet, 0.0, Rule::Hooke, section, true);
}

void probe_mistakes(RopeCode& code, Step step, const Identified&, CheckSection& section) {
  // The damping first, from masses moving together (no spring, no gravity at work): the other
  // probes take it out of what they measure.
  const double damping = probe_motion(code, step, section);
  const Rule rule = probe_springs(code, step, damping, section);
  probe_gravity(code, step, damping, rule, section);
}

}  // namespace springlab::homework
