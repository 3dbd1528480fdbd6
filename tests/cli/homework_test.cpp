// Homework 8 checked (springlab homework check): a correct rope.cpp passes every check, either
// Euler; each usual mistake planted in it (tests/homework/ropes/, one file a mistake) is named,
// and silent where it is not made; a crash, an exception and an endless loop in the student's
// code are reported with when, and the check goes on; a compile error is bad input, with its line.
#include <gtest/gtest.h>

#include <cmath>

#include "cli/cli_support.hpp"

namespace springlab::test {
namespace {

const std::string kRopes = std::string(SPRINGLAB_SOURCE_DIR) + "/tests/homework/ropes/";

Result check(const std::string& file, const std::string& options = "") {
  return springlab("homework check " + kRopes + file + options);
}

// The section of the report about one step ("simulateEuler" up to the next section).
std::string section(const std::string& report, const std::string& step) {
  const std::size_t at = report.find("\n" + step + "\n");
  if (at == std::string::npos) return "";
  const std::size_t end = report.find("\nsimulate", at + 2);
  return report.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

double number_after(const std::string& text, const std::string& before) {
  const std::size_t at = text.find(before);
  return at == std::string::npos ? std::nan("") : std::stod(text.substr(at + before.size()));
}

// The usual mistakes' sentences: none may appear in a correct rope's report.
const char* const kMistakes[] = {"FAIL", "not cleared", "one end only", "wrong sign", "rest length is not used",
                                 "pinned mass moves", "never advanced", "applied twice"};

TEST(Homework, ACorrectRopePassesEveryCheck) {
  const Result r = check("correct.cpp");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("simulateEuler is Symplectic Euler (springlab's symplectic-euler), with a global drag f = -c v, c = 0.01 N s/m"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("simulateVerlet is Verlet (springlab's verlet), with damping factor d = 5e-05"), std::string::npos) << r.out;
  for (const char* mistake : kMistakes) EXPECT_EQ(r.out.find(mistake), std::string::npos) << mistake << r.out;
  // The measurements beside the row's theory: symplectic Euler's order 1, its energy falling by
  // exactly its drag's 1 - (c/m) h a step, damped Verlet's by 1 - d.
  EXPECT_NEAR(number_after(section(r.out, "simulateEuler"), "order "), 1.0, 0.05) << r.out;
  EXPECT_NE(section(r.out, "simulateEuler").find("energy falls: x0.9999609"), std::string::npos) << r.out;
  EXPECT_NE(section(r.out, "simulateVerlet").find("energy falls: x0.99995000"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" 0 failed."), std::string::npos) << r.out;
}

// The exercise asks for both Eulers in simulateEuler: explicit Euler is named and passes, its
// energy growing at 1 + (w h)^2 - (c/m) h a step.
TEST(Homework, ExplicitEulerIsNamedAndPasses) {
  const Result r = check("explicit.cpp");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("simulateEuler is Explicit Euler (springlab's euler)"), std::string::npos) << r.out;
  EXPECT_NE(section(r.out, "simulateEuler").find("energy grows: x1.00093"), std::string::npos) << r.out;
}

// Undamped, Verlet's order is measured (2) and both steps' energies are told apart: symplectic
// Euler and Verlet hold theirs.
TEST(Homework, UndampedVerletIsSecondOrderAndHoldsItsEnergy) {
  const Result r = check("no_damping.cpp");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("simulateVerlet is Verlet (springlab's verlet), with no damping"), std::string::npos) << r.out;
  EXPECT_NEAR(number_after(section(r.out, "simulateVerlet"), "order "), 2.0, 0.05) << r.out;
  EXPECT_NE(section(r.out, "simulateVerlet").find("energy holds"), std::string::npos) << r.out;
  EXPECT_NE(section(r.out, "simulateEuler").find("energy holds"), std::string::npos) << r.out;
}

// The exercise's "explicit Verlet (solving constraints)" done CS 184's way, the springs held at
// their length by moving the masses: said as such and passed, never called Hooke's law gone wrong.
TEST(Homework, VerletWithItsSpringsAsConstraintsIsSaidAndPasses) {
  const Result r = check("constraints.cpp");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  const std::string verlet = section(r.out, "simulateVerlet");
  EXPECT_NE(verlet.find("simulateVerlet is position Verlet with its springs held as constraints"), std::string::npos) << r.out;
  EXPECT_NE(verlet.find("a spring stretched by 25 % is back at its rest length after one step"), std::string::npos) << r.out;
  EXPECT_NE(verlet.find("damping: every mass gets the same damping factor d (5e-05)"), std::string::npos) << r.out;
  for (const char* mistake : kMistakes) EXPECT_EQ(r.out.find(mistake), std::string::npos) << mistake << r.out;
  // A force-based Verlet is never taken for one.
  EXPECT_EQ(check("correct.cpp").out.find("held as constraints"), std::string::npos);
}

// What the student prints goes to its own place: the replies are on another descriptor.
TEST(Homework, TheStudentsPrintingDoesNotDisturbTheCheck) {
  const Result r = check("prints.cpp");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
}

struct Planted {
  const char* file;
  const char* named;  // the sentence that names the mistake
};

class Mistakes : public testing::TestWithParam<Planted> {};

TEST_P(Mistakes, EachPlantedMistakeIsNamed) {
  const Result r = check(GetParam().file);
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_NE(r.out.find(GetParam().named), std::string::npos) << r.out;
}

INSTANTIATE_TEST_SUITE_P(
    Homework, Mistakes,
    testing::Values(Planted{"uneven.cpp", "mass 15 is at (7.031, 0), not at (7.5, 0)"},
                    Planted{"forces_kept.cpp", "forces are not cleared between steps"},
                    Planted{"one_end.cpp", "the spring force acts on one end only (m1)"},
                    Planted{"wrong_sign.cpp", "the spring force has the wrong sign"},
                    Planted{"no_rest_length.cpp", "the rest length is not used"},
                    Planted{"pin_falls.cpp", "a pinned mass moves"},
                    Planted{"last_stale.cpp", "last_position is never advanced"},
                    Planted{"damping_per_spring.cpp", "damping is applied twice on the middle masses"}),
    [](const testing::TestParamInfo<Planted>& info) {
      std::string name = info.param.file;
      name = name.substr(0, name.find('.'));
      for (char& c : name)
        if (c == '_') c = 'X';
      return name;
    });

// A crash ends the step's checks with what happened and when; the other step is still checked.
TEST(Homework, ACrashIsReportedAndTheOtherStepStillChecked) {
  const Result r = check("crash.cpp");
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("simulateVerlet (step 1 of 1, h = 1/1024 s) was killed by signal 11 (Segmentation fault)"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("simulateEuler is Symplectic Euler"), std::string::npos) << r.out;
}

TEST(Homework, AnEndlessLoopIsStoppedAtTheLimit) {
  const Result r = check("endless.cpp", " --time-limit 0.5");
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("simulateVerlet (step 1 of 1, h = 1/1024 s) did not return within 0.5 s and was stopped"),
            std::string::npos) << r.out;
}

TEST(Homework, AnExceptionIsReportedWithItsMessage) {
  const Result r = check("throws.cpp");
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("simulateEuler (step 1 of 64, h = 1/1024 s) threw an exception: not written yet"),
            std::string::npos) << r.out;
}

TEST(Homework, ACompileErrorIsBadInputWithItsFileAndLine) {
  const Result r = check("does_not_compile.cpp");
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("does_not_compile.cpp does not compile: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("does_not_compile.cpp:10:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("damping"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
  const Result missing = springlab("homework check no-such-rope.cpp");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("cannot read no-such-rope.cpp: no such file"), std::string::npos) << missing.err;
}

// The starter kit compiles as shipped, and the checker says what is still to write; the kit
// never writes over a student's work.
TEST(Homework, TheStarterKitCompilesAndSaysWhatIsMissing) {
  TempDir dir;
  const Result kit = springlab("homework kit " + (dir / "hw8").string());
  ASSERT_EQ(kit.status, 0) << kit.err;
  const Result r = springlab("homework check " + (dir / "hw8" / "rope.cpp").string());
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("0 masses, where num_nodes = 16"), std::string::npos) << r.out;
  const Result again = springlab("homework kit " + (dir / "hw8").string());
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.err.find("exists already"), std::string::npos) << again.err;
}

}  // namespace
}  // namespace springlab::test
