#include "web/js_rope.hpp"

#include <emscripten.h>

#include <cstdlib>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "springlab/text.hpp"

namespace {

// (The values of a mass travel as homework.js's kValues = 8 doubles: x, last x, v, f.)
constexpr int kValues = 8;

// JavaScript, kept as written (clang-format would write `=>` as `= >`).
// clang-format off
EM_JS(void, js_rope_build, (int id, const double* masses, int n, const double* springs, int s), {
  window.springlabHomework.build(id, HEAPF64.slice(masses >> 3, (masses >> 3) + 4 * n),
                                 HEAPF64.slice(springs >> 3, (springs >> 3) + 4 * s));
});

EM_JS(void, js_rope_set_state, (int id, const double* state, int n), {
  window.springlabHomework.setState(id, HEAPF64.slice(state >> 3, (state >> 3) + 8 * n));
});

// The states after each step into `out`; the step that failed (from 0) into *failed_at, and what
// happened as malloc'ed UTF-8 ("time", or a sentence), or 0.
EM_JS(char*, js_rope_simulate, (int id, int which, double dt, double gx, double gy, int steps, double ms,
                                double* out, int* failed_at), {
  const r = window.springlabHomework.simulate(id, which, dt, gx, gy, steps, ms);
  if (r.states) {
    HEAPF64.set(r.states, out >> 3);
    return 0;
  }
  HEAP32[failed_at >> 2] = r.step;
  const size = lengthBytesUTF8(r.error) + 1;
  const p = _malloc(size);
  stringToUTF8(r.error, p, size);
  return p;
});

EM_JS(void, js_rope_drop, (int id), { window.springlabHomework.drop(id); });

EM_JS(int, js_rope_compiled, (), { return window.springlabHomework && window.springlabHomework.compiled ? 1 : 0; });
// clang-format on

int next_id = 1;

// What a call left wrong, as homework.js says it ("left not-a-mass I", "left not-a-vector I
// FIELD", "left count N M"), in words.
std::string left_text(const std::string& left) {
  std::istringstream in(left);
  std::string word, kind, field;
  int a = 0, b = 0;
  in >> word >> kind;
  if (kind == "not-a-mass" && in >> a)
    return springlab::format_text(springlab::tr("it left rope.masses[%d] not a mass"), a);
  if (kind == "not-a-vector" && in >> a >> field)
    return springlab::format_text(
        springlab::tr("it left rope.masses[%d].%s not a vector (an object with numbers x and y)"),
        a, field.c_str());
  if (kind == "count" && in >> a >> b)
    return springlab::format_text(springlab::tr("it changed the number of masses from %d to %d"), a,
                                  b);
  return left;
}

}  // namespace

namespace springlab::app::web {

using namespace homework;

bool js_code_ready() {
  return js_rope_compiled() != 0;
}

JsRope::JsRope(double limit_ms, double per_step_ms)
    : id_(next_id++), limit_ms_(limit_ms), per_step_ms_(per_step_ms) {}

JsRope::~JsRope() {
  js_rope_drop(id_);
}

BuiltRope JsRope::build(const RopeRequest& request) {
  BuiltRope rope = exercise_rope(request);
  std::vector<double> masses, springs;
  for (const BuiltMass& m : rope.masses)
    masses.insert(masses.end(), {m.start.x(), m.start.y(), m.mass, m.pinned ? 1.0 : 0.0});
  for (const BuiltSpring& s : rope.springs)
    springs.insert(springs.end(), {double(s.m1), double(s.m2), s.k, s.rest});
  masses_ = static_cast<int>(rope.masses.size());
  js_rope_build(id_, masses.data(), masses_, springs.data(), static_cast<int>(rope.springs.size()));
  return rope;
}

void JsRope::set_state(const RopeState& state) {
  if (static_cast<int>(state.size()) != masses_)
    throw CodeFailure("a state of " + std::to_string(state.size()) + " masses for a rope of " +
                      std::to_string(masses_));
  std::vector<double> values;
  for (const MassState& m : state)
    values.insert(values.end(), {m.x.x(), m.x.y(), m.x_last.x(), m.x_last.y(), m.v.x(), m.v.y(),
                                 m.f.x(), m.f.y()});
  js_rope_set_state(id_, values.data(), masses_);
}

std::vector<RopeState> JsRope::simulate(Step step, double dt, const Vec2& gravity, int steps) {
  std::vector<double> out(static_cast<std::size_t>(steps) * masses_ * kValues);
  int failed_at = 0;
  const double ms = limit_ms_ + per_step_ms_ * steps;
  std::unique_ptr<char, decltype(&std::free)> error(
      js_rope_simulate(id_, step == Step::Euler ? 0 : 1, dt, gravity.x(), gravity.y(), steps, ms,
                       out.data(), &failed_at),
      &std::free);
  if (error) {
    const std::string what = error.get();
    const std::string call = call_text(step, failed_at + 1, steps, dt);
    if (what == "time") throw CodeFailure(timed_out_text(call, ms / 1000.0));
    if (what.starts_with("left ")) throw CodeFailure(call + ": " + left_text(what));
    throw CodeFailure(threw_text(call, what));
  }
  std::vector<RopeState> states(steps, RopeState(masses_));
  for (int n = 0; n < steps; ++n)
    for (int i = 0; i < masses_; ++i) {
      const double* v = &out[(static_cast<std::size_t>(n) * masses_ + i) * kValues];
      states[n][i] = {Vec2(v[0], v[1]), Vec2(v[2], v[3]), Vec2(v[4], v[5]), Vec2(v[6], v[7])};
    }
  return states;
}

}  // namespace springlab::app::web
