// Inputs that once broke the loaders, found while fuzzing them (tests/fuzz): each now loads or
// fails with an InputError naming the file and the field, never a crash or another exception
// (which the command line would report with exit status 1 instead of 2).
#include <gtest/gtest.h>

#include <chrono>

#include "springlab/error.hpp"
#include "support.hpp"

namespace springlab {
namespace {

// The InputError's message, or what else happened.
std::string outcome(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parse_scene(text, "bad.json", overrides);
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("not an InputError: ") + e.what();
  }
  return "loaded";
}

const std::string one = R"("particles": [{"position": [0,0,0]}])";

TEST(LoaderRegressions, ADeeplyNestedMethodIsDescribedNotPrinted) {
  // Printing the value recursed once per level: a 2 MB file overflowed the stack.
  const int depth = 1'000'000;
  const std::string text =
      "{" + one + R"(, "methods": [)" + std::string(depth, '[') + std::string(depth, ']') + "]}";
  EXPECT_EQ(
      outcome(text).rfind("scene 'bad.json': /methods/0: must be a method name, got an array", 0),
      0u)
      << outcome(text).substr(0, 200);
}

TEST(LoaderRegressions, AGeneratorNameThatIsNotAStringIsReportedWithItsPath) {
  // Looking a --set key up among the generators' names threw nlohmann's type_error.
  const std::string text = "{" + one + R"(, "generators": [{"type": "rope", "name": 5}]})";
  EXPECT_EQ(
      outcome(text, {"rope.nodes=3"}),
      "--set rope.nodes=3: scene 'bad.json' has no field 'rope' (nor a generator of that name)");
  EXPECT_EQ(outcome(text, {"gravity=0,-1,0"}),
            "scene 'bad.json': /generators/0/name: must be a string, got 5");
  EXPECT_EQ(outcome("{" + one + R"(, "generators": [{"type": 7}]})", {"rope.nodes=3"})
                .rfind("--set rope.nodes=3: ", 0),
            0u);
}

TEST(LoaderRegressions, ASetValueThatIsNotUtf8IsShownNotThrown) {
  // A file's strings are UTF-8 (the parser checks), a --set value's need not be: printing it in
  // the message threw nlohmann's type_error 316.
  EXPECT_EQ(outcome("{" + one + "}", {"particles.0.mass=\xff"}),
            "scene 'bad.json': /particles/0/mass: must be a number in [1e-09, 1e+09], got the "
            "string \"\xEF\xBF\xBD\"");
  EXPECT_EQ(outcome("{" + one + "}", {"methods=[1]", "methods.0=\xff"})
                .rfind("scene 'bad.json': /methods/0: unknown method \"\xEF\xBF\xBD\"", 0),
            0u);
}

TEST(LoaderRegressions, AMassTooSmallToInvertIsRefused) {
  // 5e-324 kg passed "(0, 1e9]" and gave an infinite inverse mass: the first step was NaN.
  EXPECT_EQ(outcome(R"({"particles": [{"position": [0,0,0], "mass": 5e-324}]})"),
            "scene 'bad.json': /particles/0/mass: must be in [1e-09, 1e+09], got 4.94066e-324");
  EXPECT_EQ(
      outcome(
          R"({"generators": [{"type": "rope", "start": [0,0,0], "end": [1,0,0], "nodes": 4, "stiffness": 1, "mass": 1e-310}]})"),
      "scene 'bad.json': /generators/0/mass: must be in [1e-09, 1e+09], got 1e-310");
}

TEST(LoaderRegressions, SpringsLoadInTimeLinearInTheirNumber) {
  // Each spring's material was found by scanning every material so far: 60,000 springs of
  // distinct k_s (1.5 MB) took 2.4 s, 200,000 would have taken half a minute before being
  // refused. Now the limit is reached at once, and the springs before it load in a blink.
  const auto springs = [](int n) {
    std::string text =
        R"({"particles": [{"position": [0,0,0]}, {"position": [1,0,0]}], "springs": [)";
    for (int k = 0; k < n; ++k)
      text += (k ? "," : "") + std::string(R"({"a": 0, "b": 1, "ks": )") + std::to_string(k) + "}";
    return text + "]}";
  };
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(outcome(springs(65535)), "loaded");
  EXPECT_EQ(outcome(springs(200000)),
            "scene 'bad.json': /springs: use more than 65535 distinct (ks, kd) pairs");
  // Quadratic, the two took 30 s in a Release build; linear, half a second (ten times that
  // with the sanitizers).
#ifdef SPRINGLAB_SANITIZE
  const double limit = 100.0;
#else
  const double limit = 10.0;
#endif
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), limit);
}

TEST(LoaderRegressions, SetReachesAnArrayElement) {
  // "--set methods.0=rk4" found the element, then left it unchanged.
  const Scene s = test::shipped("spring", {"methods.0=rk4", "particles.1.position.0=2"});
  EXPECT_EQ(s.methods.front(), Method::RK4);
  EXPECT_EQ(s.state.x(1, 0), 2.0);
}

}  // namespace
}  // namespace springlab
