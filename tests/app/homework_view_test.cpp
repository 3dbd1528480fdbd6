// springlab view --homework rope.cpp: the student's two steps as lanes beside springlab's rows. A
// lane of one's own is the row it was found to be (the same rope to rounding); its crash stops it
// alone; a saved file is built again and its lanes start over, and a file that no longer
// compiles leaves the last good build running with the compiler's error shown.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "cli/cli_support.hpp"
#include "homework/homework_watch.hpp"
#include "options/scene_options.hpp"
#include "session/session.hpp"

namespace springlab::test {
namespace {

namespace fs = std::filesystem;
using app::HomeworkWatch;
using app::Session;

const fs::path kRopes = fs::path(SPRINGLAB_SOURCE_DIR) / "tests" / "homework" / "ropes";

std::unique_ptr<Session> rope_session(const std::vector<std::string>& sets) {
  app::SimOptions options;
  options.dt = 1.0 / 8192;  // exact in float, as the exercise's step takes it
  options.substeps = "1";
  options.kd = 0.0;  // the exercise's springs have no damping of their own
  options.sets = sets;
  options.sets.push_back(
      "rope.mass=2");  // 0.125 kg a node: exact in float, as the exercise's mass is
  app::Prepared p = app::prepare("rope", options);
  return std::make_unique<Session>(std::move(p.scene), p.settings, 60.0);
}

// The student's semi-implicit Euler with its drag of 0.01 N s/m beside springlab's symplectic
// Euler, which runs with what the checker fitted (that drag, no spring damping) instead of the
// scene's own drag of 0.03: the two lanes stay together to rounding, and the student's code ran for
// it (the rope fell and swung a metre). The Verlet row takes the student's d.
TEST(HomeworkView, ALaneOfOnesOwnFollowsItsRowRunWithTheFittedDamping) {
  HomeworkWatch watch(kRopes / "correct.cpp");
  auto session = rope_session({});
  ASSERT_EQ(session->scene().model.drag, 0.03);  // the scene's, which the rows do not take
  watch.poll(*session);
  ASSERT_EQ(session->lanes().size(), 4u);
  const app::Lane& own = session->lanes()[0];
  const app::Lane& row = session->lanes()[2];
  const app::Lane& verlet_row = session->lanes()[3];
  EXPECT_EQ(app::lane_label(own), "Your simulateEuler");
  EXPECT_EQ(app::lane_label(session->lanes()[1]), "Your simulateVerlet");
  EXPECT_EQ(own.sim.settings().method, Method::SymplecticEuler);  // the row it was found to be
  EXPECT_EQ(row.sim.settings().method, Method::SymplecticEuler);
  EXPECT_NEAR(row.sim.model().drag, 0.01, 1e-9);
  EXPECT_EQ(row.sim.model().kd(0), 0.0);
  EXPECT_NEAR(verlet_row.sim.model().verlet_damping, 5e-5, 1e-9);
  EXPECT_EQ(verlet_row.sim.model().drag, 0.0);
  for (int frame = 0; frame < 60; ++frame) session->advance_frame();  // 1 s: 8192 steps
  ASSERT_FALSE(own.sim.trouble()) << own.sim.trouble()->message();
  EXPECT_NEAR(own.sim.state().t, 1.0, 1e-9);
  const double apart = (own.sim.state().x - row.sim.state().x).rowwise().norm().maxCoeff();
  EXPECT_LT(apart, 1e-9);
  const double moved = (own.sim.state().x - session->scene().state.x).rowwise().norm().maxCoeff();
  EXPECT_GT(moved, 1.0);  // the student's code stepped the rope: it fell and swung
  // The panel's account: both steps named with their damping, and the parameters the rows took.
  const std::vector<std::string>& lines = watch.status().lines;
  ASSERT_GE(lines.size(), 5u);
  EXPECT_NE(
      lines[1].find("simulateEuler: Symplectic Euler, a global drag f = -c v, c = 0.01 N s/m"),
      std::string::npos)
      << lines[1];
  EXPECT_NE(
      lines[2].find("beside it springlab's symplectic-euler with drag 0.01 N s/m, k_d 0 N s/m"),
      std::string::npos)
      << lines[2];
  EXPECT_NE(lines[3].find("simulateVerlet: Verlet, damping factor d = 5e-05"), std::string::npos)
      << lines[3];
  EXPECT_NE(lines[4].find("beside it springlab's verlet with drag 0 N s/m, k_d 0 N s/m, d = 5e-05"),
            std::string::npos)
      << lines[4];
}

// A step that is wrong visibly leaves the row it stands beside: forces never cleared.
TEST(HomeworkView, AWrongLaneLeavesItsRow) {
  HomeworkWatch watch(kRopes / "forces_kept.cpp");
  auto session = rope_session({});
  watch.poll(*session);
  ASSERT_EQ(session->lanes().size(), 4u);
  for (int frame = 0; frame < 6; ++frame) session->advance_frame();  // 0.1 s
  const app::Lane &own = session->lanes()[0], &row = session->lanes()[2];
  const double apart = own.sim.trouble()
                           ? INFINITY
                           : (own.sim.state().x - row.sim.state().x).rowwise().norm().maxCoeff();
  EXPECT_GT(apart, 1e-2);
}

// A crash in simulateVerlet stops that lane, with what happened and at which step; the others go
// on to the end. (Under xvfb, as `view --frames` runs: exit 3, a lane diverged.)
TEST(HomeworkView, ACrashStopsItsOwnLaneAndTheAppGoesOn) {
  const Result r = springlab_under_xvfb("view rope --homework " + (kRopes / "crash.cpp").string() +
                                        " --frames 20");
  EXPECT_EQ(r.status, 3) << r.out << r.err;
  EXPECT_NE(
      r.out.find(
          "lane       Your simulateVerlet at t = 0 s (diverged: simulateVerlet (step 1 of 1, h = "),
      std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("was killed by signal 11 (Segmentation fault))"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("lane       Your simulateEuler at t = 0.3333 s\n"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("lane       verlet at t = 0.3333 s\n"), std::string::npos) << r.out;
}

// Lesson 13 with the student's code: each of its steps shows the student's lanes beside
// springlab's (step 4 is the spring: a rope of two masses to the student's constructor).
TEST(HomeworkView, TheLessonShowsTheStudentsLanes) {
  const Result r = springlab_under_xvfb("view --lesson homework-8 --step 4 --homework " +
                                        (kRopes / "correct.cpp").string() + " --frames 30");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("lane       Your simulateEuler at t = 0.5 s\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("lane       Your simulateVerlet at t = 0.5 s\n"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("lane       verlet at t = 0.5 s\n"), std::string::npos) << r.out;
}

TEST(HomeworkView, AFileThatDoesNotCompileIsRefusedBeforeAnyWindow) {
  const Result r = springlab("view --homework " +
                             (kRopes / "does_not_compile.cpp").string());  // no display needed
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("does_not_compile.cpp does not compile: "), std::string::npos) << r.err;
  const Result both =
      springlab("view --homework " + (kRopes / "correct.cpp").string() + " --compare euler,rk4");
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(
      both.err.find(
          "--homework: shows your rope's lanes beside springlab's; it does not go with --compare"),
      std::string::npos)
      << both.err;
}

void write(const fs::path& file, const std::string& text) {
  // A save in the editor's way: a new file in its place, with a later time.
  const fs::path temp = file.string() + ".saving";
  std::ofstream(temp) << text;
  fs::rename(temp, file);
}

// Waits (frames go on) until the watch has seen the saved file, built it and taken it in.
void settle(HomeworkWatch& watch, Session& session) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  bool seen = false;
  while (std::chrono::steady_clock::now() < deadline) {
    watch.poll(session);
    seen = seen || watch.status().building;
    if (seen && !watch.status().building) break;
    session.advance_frame();
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_TRUE(seen) << "the saved file was not seen";
}

TEST(HomeworkView, ASavedFileIsBuiltAgainAndABrokenOneLeavesTheLastGoodBuild) {
  TempDir dir;
  fs::copy_file(kRopes / "rope_with.hpp", dir / "rope_with.hpp");
  const fs::path file = dir / "rope.cpp";
  write(file, "#include \"rope_with.hpp\"\n");
  HomeworkWatch watch(file);
  auto session = rope_session({});
  watch.poll(*session);
  EXPECT_EQ(session->lanes()[0].sim.settings().method, Method::SymplecticEuler);

  // Saved as explicit Euler: built on the worker, checked, and the lane is now explicit Euler's.
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // a later modification time
  write(file, "#define EXPLICIT\n#include \"rope_with.hpp\"\n");
  settle(watch, *session);
  EXPECT_EQ(session->lanes()[0].sim.settings().method, Method::Euler);
  EXPECT_NE(watch.status().lines[1].find("simulateEuler: Explicit Euler"), std::string::npos)
      << watch.status().lines[1];
  EXPECT_TRUE(watch.status().error.empty());

  // Saved broken: the error is shown, the explicit lanes go on.
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  write(file, "#include \"rope_with.hpp\"\nvoid broken() { undeclared(); }\n");
  settle(watch, *session);
  EXPECT_NE(watch.status().error.find("rope.cpp does not compile: "), std::string::npos)
      << watch.status().error;
  EXPECT_NE(watch.status().error.find("undeclared"), std::string::npos) << watch.status().error;
  EXPECT_EQ(session->lanes()[0].sim.settings().method, Method::Euler);
  const double before = session->lanes()[0].sim.state().t;
  for (int frame = 0; frame < 5; ++frame) session->advance_frame();
  EXPECT_GT(session->lanes()[0].sim.state().t, before);
  EXPECT_FALSE(session->lanes()[0].sim.trouble());
}

}  // namespace
}  // namespace springlab::test
