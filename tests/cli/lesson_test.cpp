// The lessons: every shipped lesson played headlessly, each claim its captions make checked on
// what happened (lesson/lesson_checks.hpp measures them against the physics: growth factors
// a step from the methods' amplification, exp(-k_drag n t / M), exact solutions, limits, orders);
// the course's order; `springlab lesson`, `render --lesson` and `view --lesson` as a user runs
// them, and a bad lesson's one message.
#include <gtest/gtest.h>

#include "cli/cli_support.hpp"
#include "lesson/lesson_checks.hpp"
#include "lesson/lesson_library.hpp"

namespace springlab::test {
namespace {

namespace fs = std::filesystem;

// The lecture's order (GAMES101, animation and simulation; assets/lessons/README.md).
const std::vector<std::string> kCourse = {"hooke",
                                          "damping-vs-drag",
                                          "euler-explodes",
                                          "damping-buys-a-limit",
                                          "midpoint-modified-euler",
                                          "adaptive-step",
                                          "implicit-stiff",
                                          "rk4-work-precision",
                                          "particle-systems",
                                          "inverse-kinematics",
                                          "what-games-use",
                                          "write-your-own-step",
                                          "homework-8"};

class ShippedLesson : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedLesson, EveryClaimOfItsCaptionsHoldsWhenPlayed) {
  const Lesson lesson = app::open_lesson(GetParam());
  for (std::size_t s = 0; s < lesson.steps.size(); ++s) {
    const LessonStep& step = lesson.steps[s];
    EXPECT_FALSE(step.claims.empty())
        << lesson.name << " step " << s + 1 << " claims nothing a test can check";
    for (const app::ClaimResult& r : app::check_step(step))
      EXPECT_TRUE(r.passed) << lesson.name << " step " << s + 1 << ": " << r.claim.describe()
                            << ": " << r.measured;
  }
}

INSTANTIATE_TEST_SUITE_P(Lessons, ShippedLesson, ::testing::ValuesIn(kCourse),
                         [](const auto& info) { return scene_test_name(info.param); });

TEST(Lessons, TheCourseFollowsTheLecture) {
  const Result r = springlab("lesson list");
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream lines(r.out);
  std::vector<std::string> names;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    int number = 0;
    std::string name;
    words >> number >> name;
    EXPECT_EQ(number, static_cast<int>(names.size()) + 1) << line;
    names.push_back(name);
  }
  EXPECT_EQ(names, kCourse);
}

TEST(Lessons, CheckPrintsEachClaimWithWhatWasMeasured) {
  const Result r = springlab("lesson check euler-explodes");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(
      r.out.find(
          "ok    euler: energy grows by x1.027778 a step: x1.027778 a step (expected x1.027778)"),
      std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("5 of 5 claims hold"), std::string::npos) << r.out;
}

TEST(Lessons, AClaimThatDoesNotHoldFailsTheCheck) {
  TempDir dir;
  // Symplectic Euler on the spring keeps its energy: claiming it grows is false.
  write_file(dir / "wrong.json", R"({"title": "Wrong", "summary": "A false claim.", "steps": [
    {"title": "SE", "scene": "spring", "method": "symplectic-euler", "duration": 2, "caption": "It grows.",
     "claims": [{"claim": "energy-grows"}]}]})");
  const Result r = springlab("lesson check " + (dir / "wrong.json").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("FAIL  energy grows"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1 of 2 claims hold"), std::string::npos) << r.out;  // (and in sight)
}

// Every kind of claim can fail: one false claim of each kind, each in a step of its own, played
// and checked, and every one reported FAIL with what it measured (the shipped lessons show each
// kind holding; this shows the check is not a formality). Each is false for a physical reason:
// the exact cosine is not followed by symplectic Euler at h w = 0.5; a damped spring's energy is
// not level; an undamped spring's under RK4 does not fall by 5 % of the scale, and implicit Euler's
// falls by 0.973 a step, not 0.9; drag changes momentum; an undamped box keeps its wobble; gravity
// speeds the centre that drag alone would slow; explicit Euler's energy grows 1.0278 a step, not
// 1.05; symplectic Euler holds; explicit Euler does not; the damped spring's limit is 0.02 s;
// RK4 never rejects a step; Euler's order is 1, not 2, and RK4 is the most accurate; the
// fountain holds about 1280 drops, not 5000; a firework bursts into 160 sparks, not 100; a
// target within reach is reached; no two poses are 5 m apart.
TEST(Lessons, EveryKindOfClaimCanFail) {
  TempDir dir;
  // (Two lessons: at most 12 steps each.)
  write_file(dir / "false1.json",
             R"({"title": "False", "summary": "False claims, one of each kind.", "steps": [
    {"title": "follows-exact", "scene": "spring", "method": "symplectic-euler", "dt": 0.05, "substeps": 1,
     "duration": 3, "caption": "c", "claims": [{"claim": "follows-exact", "within": 0.001}]},
    {"title": "energy-bounded", "scene": "spring", "method": "rk4", "kd": 2, "duration": 3, "caption": "c",
     "claims": [{"claim": "energy-bounded", "within": 0.01}]},
    {"title": "energy-decays", "scene": "spring", "method": "rk4", "substeps": 1, "duration": 3, "caption": "c",
     "claims": [{"claim": "energy-decays"}]},
    {"title": "energy-decays per step", "scene": "spring", "method": "implicit-euler", "dt": 0.016666666666666666,
     "substeps": 1, "duration": 2, "caption": "c", "claims": [{"claim": "energy-decays", "per_step": 0.9}]},
    {"title": "momentum-kept", "scene": "jelly", "set": {"gravity": [0, 0, 0], "drag": 0.5, "colliders": [],
     "jelly.velocity": [1, 0, 0]}, "method": "symplectic-euler", "duration": 2, "caption": "c",
     "claims": [{"claim": "momentum-kept", "from": 0.1}]},
    {"title": "internal-decays", "scene": "jelly", "set": {"jelly.damping": 0, "drag": 0}, "method": "symplectic-euler",
     "duration": 3, "caption": "c", "claims": [{"claim": "internal-decays", "from": 1.0, "below": 0.05}]},
    {"title": "drag-slows", "scene": "jelly", "set": {"drag": 0.008, "colliders": [], "jelly.velocity": [0.4, 0, 0]},
     "method": "symplectic-euler", "duration": 2, "caption": "c", "claims": [{"claim": "drag-slows", "from": 0.1}]},
    {"title": "energy-grows", "scene": "spring", "method": "euler", "dt": 0.016666666666666666, "substeps": 1,
     "duration": 2, "caption": "c", "claims": [{"claim": "energy-grows", "per_step": 1.05, "to": 0.75}]},
    {"title": "diverges", "scene": "spring", "method": "symplectic-euler", "dt": 0.016666666666666666, "substeps": 1,
     "duration": 3, "caption": "c", "claims": [{"claim": "diverges", "by": 3}]}]})");
  write_file(dir / "false2.json",
             R"({"title": "False too", "summary": "The other kinds.", "steps": [
    {"title": "holds", "scene": "spring", "method": "euler", "dt": 0.016666666666666666, "substeps": 1,
     "duration": 3, "caption": "c", "claims": [{"claim": "holds"}]},
    {"title": "limit", "scene": "damped-spring", "method": "euler", "dt": 0.015, "substeps": 1, "duration": 1,
     "caption": "c", "claims": [{"claim": "limit", "h": 0.03, "within": 0.01}]},
    {"title": "steps-adapt", "scene": "spring", "method": "rk4", "substeps": 1, "duration": 2, "caption": "c",
     "claims": [{"claim": "steps-adapt", "ratio": 2}]},
    {"title": "orders", "scene": "spring", "method": "rk4", "dt": 0.004166666666666667, "substeps": 1, "duration": 1,
     "caption": "c", "claims": [{"claim": "orders", "orders": {"euler": 2, "rk4": 4}}]},
    {"title": "orders best", "scene": "spring", "method": "rk4", "dt": 0.004166666666666667, "substeps": 1,
     "duration": 1, "caption": "c", "claims": [{"claim": "orders", "orders": {"euler": 1, "rk4": 4}, "best": "euler"}]},
    {"title": "particles", "scene": "fountain", "duration": 8, "caption": "c",
     "claims": [{"claim": "particles", "about": 5000, "within": 0.08, "at": 7}]},
    {"title": "bursts", "scene": "fireworks", "duration": 8, "caption": "c", "claims": [{"claim": "bursts", "count": 100}]},
    {"title": "out-of-reach", "scene": "ik-arm", "duration": 3, "caption": "c", "claims": [{"claim": "out-of-reach"}]},
    {"title": "poses-differ", "scene": "ik-arm", "compare": ["ccd", "fabrik", "dls"], "duration": 3, "caption": "c",
     "claims": [{"claim": "poses-differ", "min": 5}]},
    {"title": "solver-converges", "scene": "cloth", "ks": 20000, "method": "local-global", "dt": 0.016666666666666666,
     "substeps": 1, "duration": 1, "caption": "c", "claims": [{"claim": "solver-converges", "below": 0.5}]},
    {"title": "acts-as", "scene": "chain", "method": "xpbd", "dt": 0.03333333333333333, "substeps": 1, "duration": 20,
     "caption": "c", "claims": [{"claim": "acts-as", "above": 0.5}]},
    {"title": "linear momentum", "scene": "cloth", "ks": 20000, "set": {"cloth.pinned": [], "gravity": [0, 0, 0],
     "drag": 0}, "compare": ["xpbd", "vbd"], "dt": 0.016666666666666666, "substeps": 1, "duration": 2, "caption": "c",
     "events": [{"t": 0.2, "grab": "cloth:0"}, {"t": 0.2, "move": [-1.0, 2.4, 0.4], "over": 0.25},
                {"t": 0.45, "release": true}],
     "claims": [{"claim": "linear-momentum-kept", "lane": "vbd", "from": 0.6},
                {"claim": "linear-momentum-changes", "lane": "xpbd", "from": 0.6}]}]})");
  const Result r = springlab("lesson check " + (dir / "false1.json").string() + " " +
                             (dir / "false2.json").string());
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  // (Every step also gets the check's own "in sight", tested below: not counted here.)
  int fails = 0, oks = 0;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    if (line.find("in sight") != std::string::npos) continue;
    fails += line.find("FAIL  ") != std::string::npos;
    oks += line.find("ok  ") != std::string::npos;
  }
  EXPECT_EQ(fails, 22) << r.out;
  EXPECT_EQ(oks, 0) << r.out;
}

// Every step is checked for what a lesson never writes: each lane that holds stays in sight (at
// least half of its free particles in the scene's 16:9 frame, which every lane's view shows).
// Both ways: a cloth drifting out at 3 m/s fails, at 0.1 m/s it holds; explicit Euler's spring
// swinging out as it diverges is what the step shows, and is not flagged.
TEST(Lessons, ALaneThatHoldsOutOfSightFailsTheCheck) {
  TempDir dir;
  write_file(dir / "sight.json", R"({"title": "Sight", "summary": "In sight or not.", "steps": [
    {"title": "out", "scene": "cloth", "set": {"cloth.pinned": [], "gravity": [0, 0, 0], "drag": 0,
     "cloth.velocity": [3, 0, 0]}, "method": "xpbd", "dt": 0.016666666666666666, "substeps": 1, "duration": 3,
     "caption": "c", "claims": [{"claim": "holds"}]},
    {"title": "in", "scene": "cloth", "set": {"cloth.pinned": [], "gravity": [0, 0, 0], "drag": 0,
     "cloth.velocity": [0.1, 0, 0]}, "method": "xpbd", "dt": 0.016666666666666666, "substeps": 1, "duration": 3,
     "caption": "c", "claims": [{"claim": "holds"}]},
    {"title": "diverging", "scene": "spring", "compare": ["euler", "symplectic-euler"], "dt": 0.05,
     "substeps": 1, "duration": 3, "caption": "c", "claims": [{"claim": "diverges", "lane": "euler"}]}]})");
  const Result r = springlab("lesson check " + (dir / "sight.json").string());
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  const auto line = [&](const std::string& step) {
    const std::size_t at = r.out.find("every lane that holds in sight", r.out.find(step));
    return r.out.substr(r.out.rfind('\n', at) + 1, r.out.find('\n', at) - r.out.rfind('\n', at));
  };
  EXPECT_NE(line("step 1: out").find("FAIL  "), std::string::npos) << r.out;
  EXPECT_NE(line("step 1: out").find("xpbd: 0.0 % at least"), std::string::npos) << r.out;
  EXPECT_NE(line("step 2: in").find("ok  "), std::string::npos) << r.out;
  EXPECT_NE(line("step 3: diverging").find("ok  "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("5 of 6 claims hold"), std::string::npos) << r.out;
}

TEST(Lessons, ABadLessonGetsOneMessageNamingTheFileAndTheFieldAndExitsTwo) {
  TempDir dir;
  const fs::path file = dir / "bad.json";
  write_file(file, R"({"title": "Bad", "summary": "s", "steps": [
    {"title": "t", "scene": "spring", "kd": -1, "duration": 2, "caption": "c"}]})");
  const std::string expected = "springlab: lesson '" + file.string() + "': /steps/0/kd: must be";
  for (const std::string& command :
       {"lesson check " + file.string(),
        "render --lesson " + file.string() + " --out " + (dir / "frames").string(),
        "view --lesson " + file.string() + " --frames 1"}) {
    const Result r = springlab(command);
    EXPECT_EQ(r.status, 2) << command;
    EXPECT_EQ(r.err.rfind(expected, 0), 0u) << command << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "frames"));  // nothing half-written
}

TEST(Lessons, BadLessonOptionsExitTwo) {
  TempDir dir;
  const std::string out = " --out " + (dir / "f").string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"render --lesson hoke" + out,
       "lesson 'hoke': no such file, and no shipped lesson of that name; did you mean 'hooke'?"},
      {"render" + out, "render: give a SCENE or --lesson NAME"},
      {"render spring --lesson hooke" + out, "render: give a SCENE or --lesson NAME"},
      {"render --lesson hooke --method rk4" + out,
       "render --lesson: a lesson is recorded with its own values"},
      {"view --lesson hooke --step 3 --frames 1", "--step: lesson 'hooke' has steps 1 to 2, got 3"},
      {"lesson check nope", "lesson 'nope': no such file"},
  };
  for (const auto& [command, message] : cases) {
    const Result r = springlab(command);
    EXPECT_EQ(r.status, 2) << command;
    EXPECT_NE(r.err.find(message), std::string::npos) << command << ": " << r.err;
  }
}

// A lesson takes none of the class's values (its captions state its own), and says how to record
// each step with them instead: its scene's render command, which runs.
TEST(Lessons, RenderWithTheClassesValuesGivesEachStepsCommand) {
  TempDir dir;
  const Result r = springlab("render --lesson damping-buys-a-limit --dt 0.01 --kd 1 --out " +
                             (dir / "f").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_FALSE(std::filesystem::exists(dir / "f"));
  const std::string step = "step 1: springlab render damped-spring --method euler --dt 0.01 ";
  const std::size_t at = r.err.find(step);
  ASSERT_NE(at, std::string::npos) << r.err;
  EXPECT_NE(r.err.find("step 2: springlab render damped-spring"), std::string::npos) << r.err;
  std::string command = r.err.substr(at + 8 + std::string("springlab ").size());
  command = command.substr(0, command.find('\n'));
  EXPECT_NE(command.find("--kd 1 "), std::string::npos) << command;
  command.replace(command.find("--out step1"), std::string("--out step1").size(),
                  "--frames 2 --out " + (dir / "step1").string());
  const Result run = springlab(command);
  EXPECT_TRUE(run.status == 0 || run.status == 3) << command << ": " << run.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "step1" / "frame_00001.png")) << command;
}

TEST(Lessons, RenderPlaysEveryStepForItsDuration) {
  TempDir dir;
  // euler-explodes: one step of 6 s; hooke: two of 6 s. At 5 frames a second: 30 and 60 frames.
  for (const auto& [lesson, frames] :
       std::vector<std::pair<std::string, int>>{{"euler-explodes", 30}, {"hooke", 60}}) {
    const fs::path out = dir / lesson;
    const Result r = springlab("render --lesson " + lesson +
                               " --fps 5 --size 320x180 --software --out " + out.string());
    ASSERT_EQ(r.status, 0) << r.err;
    int count = 0;
    for (const auto& e : fs::directory_iterator(out)) count += e.path().extension() == ".png";
    EXPECT_EQ(count, frames) << lesson;
    EXPECT_NE(r.out.find("rendered " + std::to_string(frames) + " frames of lesson " + lesson),
              std::string::npos)
        << r.out;
  }
}

TEST(Lessons, RenderWritesAVideoWithTheCaptionsBurnedIn) {
  if (std::system("command -v ffprobe > /dev/null") != 0)
    GTEST_SKIP() << "ffprobe (package ffmpeg) is missing";
  TempDir dir;
  const auto video = dir / "hooke.mp4";
  const Result r =
      springlab("render --lesson hooke --duration 1 --fps 20 --size 640x360 --software --video " +
                video.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string probe =
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=codec_name,width,height,nb_read_frames -of csv=p=0 '" +
      video.string() + "' > '" + (dir / "probe").string() + "'";
  ASSERT_EQ(std::system(probe.c_str()), 0);
  EXPECT_EQ(read_file(dir / "probe"), "h264,640,360,20\n");
}

}  // namespace
}  // namespace springlab::test
