// libFuzzer target: the homework checker (check_rope) on whatever a student's code can build and
// do. The input drives a RopeCode: its constructor builds ropes of any count of masses (0, 1, 2,
// ...), springs to masses outside the rope (-1), to null pointers (-2) or past its end, springs
// twice, NaN and infinite positions, masses, k and rest lengths; its steps return states of the
// right or the wrong size, NaN, infinities, or step the rope as a correct rope code would (so
// that the checks past the probes are reached), or fail as a crash, an exception or a timeout
// would (CodeFailure). The only acceptable outcome is a report: the checker reading past a rope,
// any other exception, a sanitizer report or a leak is a bug. The report is then written as text
// and as JSON, as the command line does.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "springlab/homework.hpp"

namespace {

using namespace springlab::homework;

class FuzzedRope : public RopeCode {
 public:
  explicit FuzzedRope(FuzzedDataProvider& data) : data_(data), own_(data.ConsumeBool()) {}

  BuiltRope build(const RopeRequest& request) override { return made(request, true); }
  BuiltRope build_exercise(const RopeRequest& request) override { return made(request, false); }

  void set_state(const RopeState& state) override {
    fail_maybe("set_state");
    state_ = state;
  }

  std::vector<RopeState> simulate(Step step, double dt, const Vec2& g, int steps) override {
    std::vector<RopeState> out;
    for (int n = 0; n < steps; ++n) {
      // A budget of states an input may ask for, as the real runner's time limit bounds them.
      if (++states_ > 40000)
        throw CodeFailure("the step did not return within its time and was stopped");
      fail_maybe("simulate");
      switch (data_.remaining_bytes() == 0 ? 0 : data_.ConsumeIntegralInRange(0, 5)) {
        case 0:
        case 1:
        case 2:
          correct_step(step, dt, g);  // as a right rope code would
          break;
        case 3:  // a state of another size
          state_.resize(data_.ConsumeIntegralInRange<std::size_t>(0, state_.size() + 2));
          break;
        case 4:  // a value of anything
          if (!state_.empty()) {
            MassState& m = state_[data_.ConsumeIntegralInRange<std::size_t>(0, state_.size() - 1)];
            m.x.x() = value();
            m.v.y() = value();
            m.x_last.y() = value();
          }
          break;
        default:  // nothing moves
          break;
      }
      out.push_back(state_);
    }
    return out;
  }

  bool own_constructor() const override { return own_; }

 private:
  double value() {
    switch (data_.ConsumeIntegralInRange(0, 6)) {
      case 0:
        return std::numeric_limits<double>::quiet_NaN();
      case 1:
        return std::numeric_limits<double>::infinity();
      case 2:
        return -std::numeric_limits<double>::infinity();
      case 3:
        return 0.0;
      case 4:
        return 1e300;
      case 5:
        return -1e-300;
      default:
        return data_.ConsumeFloatingPointInRange(-100.0, 100.0);
    }
  }

  void fail_maybe(const char* what) {
    if (data_.remaining_bytes() > 0 && data_.ConsumeIntegralInRange(0, 40) == 0)
      throw CodeFailure(std::string(what) +
                        " was killed by signal 11 (Segmentation fault); it printed: " +
                        data_.ConsumeRandomLengthString(40));
  }

  BuiltRope made(const RopeRequest& request, bool own) {
    fail_maybe("the constructor");
    BuiltRope rope = exercise_rope(request);
    if (own && data_.remaining_bytes() > 0 && data_.ConsumeBool()) {
      // Anything a constructor might build.
      rope.masses.resize(data_.ConsumeIntegralInRange<std::size_t>(
          0, static_cast<std::size_t>(request.nodes) + 2));
      for (BuiltMass& m : rope.masses) {
        if (data_.ConsumeBool()) m.state.x = Vec2(value(), value());
        if (data_.ConsumeBool()) m.mass = value();
        if (data_.ConsumeBool()) m.pinned = data_.ConsumeBool();
        if (data_.ConsumeBool()) m.start = Vec2(value(), value());
      }
      const int n = static_cast<int>(rope.masses.size());
      rope.springs.resize(
          data_.ConsumeIntegralInRange<std::size_t>(0, static_cast<std::size_t>(n) + 2));
      for (BuiltSpring& s : rope.springs) {
        if (data_.ConsumeBool()) s.m1 = data_.ConsumeIntegralInRange(-2, n + 1);
        if (data_.ConsumeBool()) s.m2 = data_.ConsumeIntegralInRange(-2, n + 1);
        if (data_.ConsumeBool()) s.k = value();
        if (data_.ConsumeBool()) s.rest = value();
      }
    }
    rope_ = rope;
    state_.clear();
    for (const BuiltMass& m : rope.masses) state_.push_back(m.state);
    return rope;
  }

  // The exercise's steps on the rope held (semi-implicit Euler, Verlet), reading only what is
  // there.
  void correct_step(Step step, double dt, const Vec2& g) {
    const int n = static_cast<int>(std::min(state_.size(), rope_.masses.size()));
    for (const BuiltSpring& s : rope_.springs) {
      if (s.m1 < 0 || s.m2 < 0 || s.m1 >= n || s.m2 >= n) continue;
      MassState &a = state_[s.m1], &b = state_[s.m2];
      const Vec2 d = b.x - a.x;
      const double l = d.norm();
      if (!(l > 0.0)) continue;
      const Vec2 f = s.k * (l - s.rest) * d / l;
      a.f += f;
      b.f -= f;
    }
    for (int i = 0; i < n; ++i) {
      MassState& m = state_[i];
      if (!rope_.masses[i].pinned) {
        const Vec2 a = m.f / rope_.masses[i].mass + g;
        if (step == Step::Euler) {
          m.v += a * dt;
          m.x += m.v * dt;
        } else {
          const Vec2 x = m.x;
          m.x = m.x + (m.x - m.x_last) + a * dt * dt;
          m.x_last = x;
        }
      }
      m.f.setZero();
    }
  }

  FuzzedDataProvider& data_;
  bool own_;
  BuiltRope rope_;
  RopeState state_;
  long states_ = 0;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  FuzzedDataProvider data(bytes, size);
  FuzzedRope code(data);
  const Report report = check_rope(code);
  (void)format_report(report);
  (void)report_json(report);
  return 0;
}
