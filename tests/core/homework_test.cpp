// The homework checker on steps written here in C++ as a student would write them in Python
// (homework.hpp's OwnStep: (x, v) -> (x, v), forces from the core): each textbook step is named
// as springlab's row, measured at its order, and its energy's rate is the row's; a step that is
// none of them is said to be none, and never named; and a Simulation takes such a step as its own.
#include "springlab/homework.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "springlab/simulation.hpp"

namespace springlab {
namespace {

using homework::CheckLine;
using homework::OwnStep;
using homework::Report;

Points accel(const Model& m, const Points& x, const Points& v, Workspace& ws) {
  Points a;
  accelerations(m, x, v, a, ws);
  return a;
}

const OwnStep kExplicitEuler = [](const Model& m, const State& in, State& out, double h,
                                  Workspace& ws) {
  const Points a = accel(m, in.x, in.v, ws);
  out.x = in.x + h * in.v;
  out.v = in.v + h * a;
};
const OwnStep kVelocityVerlet = [](const Model& m, const State& in, State& out, double h,
                                   Workspace& ws) {
  const Points a = accel(m, in.x, in.v, ws);
  out.x = in.x + h * in.v + (0.5 * h * h) * a;
  const Points a1 = accel(m, out.x, in.v, ws);
  out.v = in.v + (0.5 * h) * (a + a1);
};
const OwnStep kRk4 = [](const Model& m, const State& in, State& out, double h, Workspace& ws) {
  const Points k1v = accel(m, in.x, in.v, ws);
  const Points x2 = in.x + 0.5 * h * in.v, v2 = in.v + 0.5 * h * k1v;
  const Points k2v = accel(m, x2, v2, ws);
  const Points x3 = in.x + 0.5 * h * v2, v3 = in.v + 0.5 * h * k2v;
  const Points k3v = accel(m, x3, v3, ws);
  const Points x4 = in.x + h * v3, v4 = in.v + h * k3v;
  const Points k4v = accel(m, x4, v4, ws);
  out.x = in.x + (h / 6.0) * (in.v + 2.0 * v2 + 2.0 * v3 + v4);
  out.v = in.v + (h / 6.0) * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
};
// Half a step of gravity forgotten: x + h v + h^2 a / 4. A step of no textbook's.
const OwnStep kMadeUp = [](const Model& m, const State& in, State& out, double h, Workspace& ws) {
  const Points a = accel(m, in.x, in.v, ws);
  out.v = in.v + h * a;
  out.x = in.x + h * in.v + (0.25 * h * h) * a;
};

std::string text(const Report& r) {
  return homework::format_report(r);
}

double number_after(const std::string& s, const std::string& before) {
  const std::size_t at = s.find(before);
  return at == std::string::npos ? std::nan("") : std::stod(s.substr(at + before.size()));
}

TEST(Homework, EachTextbookStepIsNamedAsItsRowAndMeasuredAtItsOrder) {
  struct Case {
    const OwnStep* step;
    const char* row;
    double order;
  };
  for (const Case& c : {Case{&kExplicitEuler, "euler", 1.0}, Case{&kVelocityVerlet, "verlet", 2.0},
                        Case{&kRk4, "rk4", 4.0}}) {
    const Report r = homework::check_step(*c.step, "fn");
    const std::string t = text(r);
    EXPECT_EQ(r.euler.method, c.row) << t;
    EXPECT_EQ(r.failed(), 0) << t;
    EXPECT_NEAR(number_after(t, "order "), c.order, 0.15) << t;
  }
}

// Explicit Euler's energy grows by exactly 1 + (w h)^2 a step on the undamped spring (w = 8
// rad/s, h = 1/256 s: 1.0009765625); velocity Verlet's holds.
TEST(Homework, TheEnergyRateIsTheRowsOwn) {
  const std::string euler = text(homework::check_step(kExplicitEuler, "fn"));
  EXPECT_NE(euler.find("energy grows: x1.00097"), std::string::npos) << euler;
  EXPECT_NE(euler.find("= 1.000976562"), std::string::npos) << euler;
  const std::string verlet = text(homework::check_step(kVelocityVerlet, "fn"));
  EXPECT_NE(verlet.find("energy holds"), std::string::npos) << verlet;
}

// A global damping written as a factor a step, as students write it: v = (1 - d) v + a h, then
// x += v h; v = (1 - d)(v + a h), then x += v h; or x += (v + a h) h, then v = (1 - d)(v + a h).
// Each is symplectic Euler with that factor, named as one (it implies half the rate at 2h), its
// order not measured (no limit as h -> 0) and its energy's rate 1 - d.
TEST(Homework, ADampingFactorAStepIsNamedInEachPlaceItIsTaken) {
  constexpr double d = 5e-5;
  const OwnStep before = [](const Model& m, const State& in, State& out, double h, Workspace& ws) {
    out.v = (1.0 - d) * in.v + h * accel(m, in.x, in.v, ws);
    out.x = in.x + h * out.v;
  };
  const OwnStep on_new = [](const Model& m, const State& in, State& out, double h, Workspace& ws) {
    out.v = (1.0 - d) * (in.v + h * accel(m, in.x, in.v, ws));
    out.x = in.x + h * out.v;
  };
  const OwnStep after = [](const Model& m, const State& in, State& out, double h, Workspace& ws) {
    const Points v = in.v + h * accel(m, in.x, in.v, ws);
    out.x = in.x + h * v;
    out.v = (1.0 - d) * v;
  };
  for (const auto& [step, at] : {std::pair{&before, homework::DragAt::Forces},
                                 std::pair{&on_new, homework::DragAt::NewVelocity},
                                 std::pair{&after, homework::DragAt::AfterPosition}}) {
    const Report r = homework::check_step(*step, "fn");
    const std::string t = text(r);
    EXPECT_EQ(r.euler.method, "symplectic-euler") << t;
    EXPECT_NEAR(r.euler.damping.drag_step, d, 1e-9) << t;
    EXPECT_EQ(r.euler.damping.drag_at, at) << t;
    EXPECT_EQ(r.failed(), 0) << t;
    EXPECT_NE(t.find("order: not measured"), std::string::npos) << t;
    EXPECT_NE(t.find("= 0.999950000"), std::string::npos) << t;  // 1 - d, the energy's rate
  }
}

TEST(Homework, AStepOfNoTextbookIsNeverNamed) {
  const Report r = homework::check_step(kMadeUp, "fn");
  EXPECT_EQ(r.euler.method, "") << text(r);
  EXPECT_NE(text(r).find("fn is none of springlab's explicit fixed-step rows"), std::string::npos)
      << text(r);
  EXPECT_GT(r.failed(), 0);
}

TEST(Homework, ASimulationTakesAStepOfItsOwnAndNamesItWhenItDiverges) {
  // Two particles on a stiff spring, explicit Euler of one's own at a step past any use: it
  // diverges, and the message names the own step, with no row's limit to explain it.
  Model m;
  const int material = add_material(m, {1e4, 0.0});
  add_particle(m, 1.0, true);
  add_particle(m, 1.0, false);
  add_spring(m, 0, 1, 1.0, material);
  finalize(m);
  State s;
  s.resize(2);
  s.x.setZero();
  s.v.setZero();
  s.x(1, 0) = 1.1;
  SimulationSettings settings;
  settings.method = Method::SymplecticEuler;
  settings.dt = 0.05;
  settings.own_step = [](const Model& model, const State& in, State& out, double h, Workspace& ws) {
    kExplicitEuler(model, in, out, h, ws);
  };
  settings.own_step_name = "my_euler";
  Simulation sim(m, s, settings);
  EXPECT_LT(sim.advance(1000), 1000);
  ASSERT_TRUE(sim.divergence());
  const std::string message = sim.explain_divergence()->message();
  EXPECT_NE(message.find("Method my_euler"), std::string::npos) << message;
  EXPECT_NE(message.find("A step of your own has no stated limit"), std::string::npos) << message;
  EXPECT_GT(sim.counters().force_evals, 0);  // it asked for its forces through the workspace
  // The same run with the row itself diverges at the same step: the own step is explicit Euler.
  settings.own_step = nullptr;
  settings.method = Method::Euler;
  settings.audit_fraction = 0.0;
  Simulation row(m, s, settings);
  row.advance(1000);
  ASSERT_TRUE(row.divergence());
  EXPECT_EQ(row.divergence()->step, sim.divergence()->step);
}

// The exercise's rope held in this process: springlab's exercise_rope as its constructor and the
// exercise's two steps written as a student would (semi-implicit Euler, Verlet), each spring's
// force on both its masses, gravity on the free ones.
class InProcessRope : public homework::RopeCode {
 public:
  explicit InProcessRope(bool own) : own_(own) {}
  homework::BuiltRope build(const homework::RopeRequest& request) override {
    rope_ = homework::exercise_rope(request);
    return rope_;
  }
  void set_state(const homework::RopeState& state) override {
    for (std::size_t i = 0; i < state.size(); ++i) rope_.masses[i].state = state[i];
  }
  std::vector<homework::RopeState> simulate(homework::Step step, double dt, const homework::Vec2& g,
                                            int steps) override {
    std::vector<homework::RopeState> out;
    for (int n = 0; n < steps; ++n) {
      for (const homework::BuiltSpring& s : rope_.springs) {
        homework::MassState &a = rope_.masses[s.m1].state, &b = rope_.masses[s.m2].state;
        const homework::Vec2 d = b.x - a.x;
        const homework::Vec2 f = s.k * (d.norm() - s.rest) * d.normalized();
        a.f += f;
        b.f -= f;
      }
      homework::RopeState now;
      for (homework::BuiltMass& m : rope_.masses) {
        homework::MassState& st = m.state;
        if (!m.pinned) {
          const homework::Vec2 a = st.f / m.mass + g;
          if (step == homework::Step::Euler) {
            st.v += a * dt;
            st.x += st.v * dt;
          } else {
            const homework::Vec2 x = st.x;
            st.x = st.x + (st.x - st.x_last) + a * dt * dt;
            st.x_last = x;
          }
        }
        st.f.setZero();
        now.push_back(st);
      }
      out.push_back(now);
    }
    return out;
  }
  bool own_constructor() const override { return own_; }

 private:
  bool own_;
  homework::BuiltRope rope_;
};

// springlab's own constructor builds the rope the construction check asks for; code that brings
// only the steps (the browser's) has its construction said to be springlab's, and its steps
// checked.
TEST(Homework, TheExercisesRopeIsBuiltAsAskedAndStepsAloneAreCheckedAlone) {
  InProcessRope whole(true);
  const Report r = homework::check_rope(whole);
  EXPECT_EQ(r.failed(), 0) << text(r);
  EXPECT_EQ(r.euler.method, "symplectic-euler") << text(r);
  EXPECT_EQ(r.verlet.method, "verlet") << text(r);
  ASSERT_FALSE(r.sections.empty());
  EXPECT_EQ(r.sections[0].lines.size(), 7u)
      << text(r);  // three checks on each of two ropes, one for the small ones
  InProcessRope steps(false);
  const Report s = homework::check_rope(steps);
  EXPECT_EQ(s.failed(), 0) << text(s);
  EXPECT_EQ(s.passed(), r.passed() - 7) << text(s);
  EXPECT_NE(text(s).find("built by springlab's constructor"), std::string::npos) << text(s);
}

}  // namespace
}  // namespace springlab
