// The homework's report: the rope's construction checked against the constructor's arguments,
// then each step identified, probed for the usual mistakes and measured on a spring.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "parts.hpp"

namespace springlab::homework {

const char* step_name(Step step) { return step == Step::Euler ? "simulateEuler" : "simulateVerlet"; }

int Report::passed() const {
  int n = 0;
  for (const CheckSection& s : sections)
    n += static_cast<int>(std::count_if(s.lines.begin(), s.lines.end(), [](const CheckLine& l) { return l.kind == CheckLine::Pass; }));
  return n;
}

int Report::failed() const {
  int n = 0;
  for (const CheckSection& s : sections)
    n += static_cast<int>(std::count_if(s.lines.begin(), s.lines.end(), [](const CheckLine& l) { return l.kind == CheckLine::Fail; }));
  return n;
}

namespace {

const RopeRequest kRope = checked_rope();
// A second, slanted and pinned at both ends, for the constructor only.
const RopeRequest kSlanted{Vec2(1, 2), Vec2(-3, -1), 5, 0.5, 100.0, {0, 4}};

std::string request_text(const RopeRequest& r) {
  std::string pins;
  for (int p : r.pinned) pins += (pins.empty() ? "" : ", ") + std::to_string(p);
  return "Rope(" + vec(r.start) + ", " + vec(r.end) + ", " + std::to_string(r.nodes) + ", " + num(r.node_mass) + ", " +
         num(r.k) + ", {" + pins + "})";
}

// Returns whether the rope is built right; a line for each thing checked.
bool check_built(const RopeRequest& r, const BuiltRope& rope, CheckSection& section) {
  const std::string asked = request_text(r) + ": ";
  const int n = static_cast<int>(rope.masses.size());
  if (n != r.nodes) {
    fail(section, asked + std::to_string(n) + " masses, where num_nodes = " + std::to_string(r.nodes));
    return false;
  }
  bool ok = true;
  const double length = (r.end - r.start).norm(), spacing = length / (r.nodes - 1);
  double off = 0.0, mass_off = 0.0;
  int worst = 0;
  for (int i = 0; i < n; ++i) {
    const Vec2 due = r.start + (r.end - r.start) * (static_cast<double>(i) / (r.nodes - 1));
    const BuiltMass& m = rope.masses[i];
    const double d = std::max({(m.state.x - due).norm(), (m.start - due).norm(), (m.state.x_last - due).norm()});
    if (!(d <= off)) off = d, worst = i;
    mass_off = std::max(mass_off, std::abs(m.mass - r.node_mass));
  }
  if (off <= 1e-12 * length && mass_off <= 1e-7 * r.node_mass)
    pass(section, asked + std::to_string(n) + " masses of " + num(r.node_mass) + " kg, evenly spaced from start to end");
  else {
    ok = false;
    const Vec2 due = r.start + (r.end - r.start) * (static_cast<double>(worst) / (r.nodes - 1));
    if (off > 1e-12 * length)
      fail(section, asked + "mass " + std::to_string(worst) + " is at " + vec(rope.masses[worst].state.x) + ", not at " +
                        vec(due) + " (mass i goes at start + i / (num_nodes - 1) (end - start))");
    if (mass_off > 1e-7 * r.node_mass) fail(section, asked + "a mass is not node_mass = " + num(r.node_mass) + " kg");
  }

  std::vector<int> pinned;
  for (int i = 0; i < n; ++i)
    if (rope.masses[i].pinned) pinned.push_back(i);
  if (pinned == r.pinned) pass(section, asked + "pinned exactly the masses pinned_nodes names");
  else {
    ok = false;
    std::string got;
    for (int p : pinned) got += (got.empty() ? "" : ", ") + std::to_string(p);
    fail(section, asked + "pinned masses {" + got + "}, where pinned_nodes asks for the ones listed");
  }

  // One spring between each pair of neighbours, either way round, of stiffness k and rest length
  // the spacing.
  std::vector<int> joined(n, 0);
  std::string wrong;
  for (const BuiltSpring& s : rope.springs) {
    const int lo = std::min(s.m1, s.m2), hi = std::max(s.m1, s.m2);
    if (lo < 0 || hi != lo + 1) {
      wrong = "a spring joins masses " + std::to_string(s.m1) + " and " + std::to_string(s.m2) + ", not neighbours";
      continue;
    }
    ++joined[lo];
    if (std::abs(s.k - r.k) > 1e-6 * r.k) wrong = "a spring's k is " + num(s.k) + ", not k = " + num(r.k);
    if (std::abs(s.rest - spacing) > 1e-9 * spacing)
      wrong = "spring " + std::to_string(lo) + "-" + std::to_string(hi) + "'s rest length is " + num(s.rest) +
              " m, not the spacing " + num(spacing) + " m (a Spring takes its rest length from its masses' positions when it "
              "is made: make it after the masses are in place)";
  }
  for (int i = 0; i + 1 < n && wrong.empty(); ++i)
    if (joined[i] != 1)
      wrong = std::to_string(joined[i]) + " springs between masses " + std::to_string(i) + " and " + std::to_string(i + 1) +
              ", where there must be one";
  if (wrong.empty())
    pass(section, asked + std::to_string(rope.springs.size()) + " springs, one between each pair of neighbours, k = " + num(r.k) +
                      ", rest length " + num(spacing) + " m");
  else {
    ok = false;
    fail(section, asked + wrong);
  }
  return ok;
}

}  // namespace

Report check_rope(RopeCode& code) {
  Report report;
  report.sections.push_back({"The rope (the constructor)", {}});
  if (!code.own_constructor()) {
    note(report.sections.back(), "built by springlab's constructor (the exercise here is the two steps): not checked");
  } else {
    bool built = false;
    try {
      const bool first = check_built(kRope, code.build(kRope), report.sections.back());
      built = check_built(kSlanted, code.build(kSlanted), report.sections.back()) && first;
    } catch (const CodeFailure& e) {
      fail(report.sections.back(), e.what());
      return report;
    }
    if (!built) {
      note(report.sections.back(), "the steps are not checked until the rope is built right");
      return report;
    }
  }
  for (Step step : {Step::Euler, Step::Verlet}) {
    report.sections.push_back({step_name(step), {}});
    CheckSection& section = report.sections.back();
    Identified& found = step == Step::Euler ? report.euler : report.verlet;
    try {
      if (step == Step::Verlet) {
        if (const std::optional<std::string> held = constraint_probe(code)) {
          pass(section, "simulateVerlet is position Verlet with its springs held as constraints (position-based, as "
                        "CS 184's rope and the exercise's \"solving constraints\" have it), not pulled by their force: " + *held);
          probe_constraint_mistakes(code, section);
          note(section, "order, stability and energy on a spring: not measured: springlab's verlet row is the force-based "
                        "one, and a spring held at its length does not oscillate");
          continue;
        }
      }
      found = identify(code, step, kRope, section);
      probe_mistakes(code, step, found, section);
      check_on_a_spring([&](double h, int steps, double y_before) { return rope_swing(code, step, h, steps, y_before); },
                        found, section);
    } catch (const CodeFailure& e) {
      fail(section, e.what());
    }
  }
  return report;
}

std::string format_report(const Report& report) {
  std::ostringstream out;
  for (const CheckSection& s : report.sections) {
    out << s.title << "\n";
    for (const CheckLine& l : s.lines)
      out << (l.kind == CheckLine::Pass ? "  ok    " : l.kind == CheckLine::Fail ? "  FAIL  " : "        ") << l.text << "\n";
  }
  out << report.passed() << " checks passed, " << report.failed() << " failed.\n";
  return out.str();
}

}  // namespace springlab::homework
