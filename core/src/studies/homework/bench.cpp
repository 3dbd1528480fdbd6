// The ropes the checks build, each checked in shape before anything reads it: a rope whose
// masses are not as many as asked, or whose springs reach outside it, ends the step's checks
// with a sentence, never a read past its end (the checker is never crashed by what the code
// builds).
#include <cmath>

#include "parts.hpp"

namespace springlab::homework {

std::vector<RopeRequest> every_rope() {
  return {checked_rope(),       slanted_rope(), three_masses({}), three_masses({0}),
          three_heavy_masses(), pair_rope(),    hanging_spring()};
}

namespace {

std::string rope_words(const RopeRequest& r) {
  return format_text(tr("a rope of %d masses"), r.nodes);
}

}  // namespace

BuiltRope Bench::build(const RopeRequest& request) const {
  BuiltRope rope = springlab_rope ? code.build_exercise(request) : code.build(request);
  const int n = static_cast<int>(rope.masses.size());
  if (n != request.nodes)
    throw CodeFailure(format_text(
        tr("asked for %s, the constructor built %d masses, so the steps cannot be checked on it"),
        rope_words(request).c_str(), n));
  for (const BuiltSpring& s : rope.springs) {
    // Springs to masses the rope does not hold are left out of every reference (built_model):
    // they are the constructor's mistake, told there.
    if (s.m1 >= n || s.m2 >= n)
      throw CodeFailure(format_text(tr("%s has a spring to mass %d, past its end"),
                                    rope_words(request).c_str(), std::max(s.m1, s.m2)));
  }
  return rope;
}

std::vector<RopeState> Bench::run(const RopeState& from, Step step, double h, const Vec2& gravity,
                                  int steps) const {
  code.set_state(from);
  std::vector<RopeState> states = code.simulate(step, h, gravity, steps);
  if (static_cast<int>(states.size()) != steps)
    throw CodeFailure(format_text(tr("%s gave %d states for %d steps"), step_name(step),
                                  static_cast<int>(states.size()), steps));
  for (const RopeState& s : states)
    if (s.size() != from.size())
      throw CodeFailure(format_text(tr("%s changed the number of masses from %d to %d"),
                                    step_name(step), static_cast<int>(from.size()),
                                    static_cast<int>(s.size())));
  return states;
}

RopeState at_rest(const BuiltRope& rope) {
  RopeState s;
  for (const BuiltMass& m : rope.masses) {
    MassState state;
    state.x = state.x_last = m.state.x;
    s.push_back(state);
  }
  return s;
}

}  // namespace springlab::homework
