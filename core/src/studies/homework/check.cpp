// The homework's report, in order: the rope's construction, then each step: does it move at all;
// (Verlet) does it pull springs by their force or hold them as constraints; its damping, form by
// form; the usual mistakes, probe by probe; which row it is; and on a spring its order, stability
// and energy. A constructor found wrong does not silence the steps: they are checked on
// springlab's own rope, built through the exercise's other constructor, and the report says so.
#include "parts.hpp"

namespace springlab::homework {

namespace {

void check_one_step(Bench bench, Step step, Identified& found, CheckSection& section) {
  try {
    if (!probe_moves(bench, step, section)) return;
    if (step == Step::Verlet && probe_verlet_kind(bench, section)) {
      // Springs held as constraints: the physics such a step must keep (its damping, last_position,
      // gravity and the pins); no spring oscillates to measure an order or an energy's rate on.
      found.constraints = true;
      found.damping = probe_damping(bench, step, section);
      probe_constraint_step(bench, found.damping, section);
      note(section, "not-measured",
           tr("order, stability and energy on a spring: not measured: springlab's verlet row is "
              "the force-based one, "
              "and a spring held at its length does not oscillate"));
      return;
    }
    const Damping damping = probe_damping(bench, step, section);
    probe_forces(bench, step, damping.at_step(kProbeH), section);
    const bool probes_passed = !any_failed(section);
    found = identify(bench, step, damping, probes_passed, section);
    if (found.method.empty() && probes_passed) {
      note(section, "not-measured",
           tr("order, stability and energy: not measured, since the step is none of the textbook "
              "methods"));
      return;
    }
    if (!probes_passed) {
      // Its update is a row's, but with the mistake above: measuring it would only show the mistake
      // again.
      note(section, "not-measured",
           tr("order, stability and energy: not measured while the mistake above stands"));
      return;
    }
    check_on_a_spring([&](double h, int steps,
                          double y_before) { return rope_swing(bench, step, h, steps, y_before); },
                      found, section);
  } catch (const CodeFailure& e) {
    fail(section, "code-failed", e.what());
  }
}

}  // namespace

Report check_rope(RopeCode& code) {
  Report report;
  report.sections.push_back({tr("The rope (the constructor)"), {}});
  Bench bench{code};
  if (!code.own_constructor()) {
    note(report.sections.back(), "constructor-not-checked",
         tr("built by springlab's constructor (the exercise here is the two steps): not checked"));
    report.springlab_rope = true;
  } else if (!check_construction(code, report.sections.back())) {
    report.constructor_wrong = true;
    // The steps, on springlab's rope: first make sure the code can hold one.
    try {
      code.build_exercise(checked_rope());
    } catch (const CodeFailure& e) {
      note(report.sections.back(), "steps-not-checked",
           format_text(tr("the steps cannot be checked on springlab's own rope either (%s)"),
                       e.what()));
      return report;
    }
    note(report.sections.back(), "springlab-rope",
         tr("the steps below are checked on springlab's own rope, built as the exercise states it "
            "through Rope(masses, "
            "springs), so that simulateEuler and simulateVerlet are told while the constructor is "
            "not yet right"));
    bench.springlab_rope = true;
    report.springlab_rope = true;
  }
  for (Step step : {Step::Euler, Step::Verlet}) {
    report.sections.push_back({step_name(step), {}});
    check_one_step(bench, step, step == Step::Euler ? report.euler : report.verlet,
                   report.sections.back());
  }
  return report;
}

}  // namespace springlab::homework
