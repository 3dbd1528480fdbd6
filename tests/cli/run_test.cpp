// springlab run and list, as docs/command-line.md specifies them: the CSV trace, the summary, the
// exit statuses, one clear message for each bad input, nothing half-written.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "cli/cli_support.hpp"
#include "springlab/energy_audit.hpp"
#include "springlab/methods.hpp"

namespace springlab::test {
namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream s(text);
  for (std::string line; std::getline(s, line);) out.push_back(line);
  return out;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream s(line);
  for (std::string cell; std::getline(s, cell, ',');) out.push_back(cell);
  return out;
}

TEST(List, ShowsEveryScenesAndMethodOneALine) {
  const Result r = springlab("list");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* scene :
       {"spring", "damped-spring", "rope", "chain", "cloth", "cloth-sphere", "jelly", "stiff"})
    EXPECT_NE(r.out.find("scene   " + std::string(scene) + " "), std::string::npos) << scene;
  for (const MethodInfo& m : methods())  // (the built-in rows: this process has added none)
    EXPECT_NE(r.out.find("method  " + std::string(m.name) + " "), std::string::npos) << m.name;
}

TEST(Run, WritesTheCsvTraceOfDesignMd) {
  TempDir dir;
  const Result r =
      springlab("run spring --method rk4 --dt 0.01 --steps 10 --csv " + (dir / "t.csv").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = lines(read_file(dir / "t.csv"));
  ASSERT_EQ(rows.size(), 12u);  // header, t = 0, 10 steps
  EXPECT_EQ(rows[0], "t,kinetic,potential,total,x0,y0,z0,vx0,vy0,vz0,x1,y1,z1,vx1,vy1,vz1");
  const auto first = split(rows[1]);
  ASSERT_EQ(first.size(), 16u);
  EXPECT_EQ(first[0], "0");
  EXPECT_EQ(first[10], "1.5");
  EXPECT_EQ(first[3], "12.5");
  // Row k is at t = k dt and close to the exact 1 + 0.5 cos(10 t) (RK4 at h = 0.01).
  for (int k = 1; k <= 10; ++k) {
    const auto row = split(rows[k + 1]);
    const double t = std::stod(row[0]);
    EXPECT_NEAR(t, 0.01 * k, 1e-15);
    // RK4's global error after t: about t w (h w)^4 / 120 times the amplitude: 4e-7 here.
    EXPECT_NEAR(std::stod(row[10]), 1 + 0.5 * std::cos(10 * t), 1e-6);
    EXPECT_NEAR(std::stod(row[3]), 12.5, 1e-5);
  }
  for (const char* part : {"scene      spring", "method     rk4", "steps      10 of 10", "energy",
                           "w_max = 10 rad/s", "stable up to h = 0.2828"})
    EXPECT_NE(r.out.find(part), std::string::npos) << part << "\n" << r.out;
}

TEST(Run, EveryKthRowAndTheLast) {
  TempDir dir;
  ASSERT_EQ(springlab("run spring --dt 0.01 --steps 12 --every 5 --csv " + (dir / "t.csv").string())
                .status,
            0);
  const auto rows = lines(read_file(dir / "t.csv"));
  ASSERT_EQ(rows.size(), 5u);  // header, steps 0, 5, 10, and the last (12)
  EXPECT_NEAR(std::stod(split(rows[2])[0]), 0.05, 1e-15);
  EXPECT_NEAR(std::stod(split(rows[4])[0]), 0.12, 1e-15);
}

TEST(Run, OptionsChangeTheRun) {
  const Result r = springlab(
      "run spring --method euler --dt 0.001 --substeps 4 --duration 0.5 --ks 400 --kd 1 --set "
      "particles.1.mass=4");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("steps      500 of 500"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("h = 0.00025 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("w_max = 10 rad/s"), std::string::npos) << r.out;  // sqrt(400 / 4)
}

TEST(Run, IntegerOptionsTakeAnyWholeNumber) {
  const Result r = springlab("run spring --steps 1e3 --substeps 2.0 --threads 1");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("steps      1000 of 1000"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2 substeps"), std::string::npos) << r.out;
}

TEST(Run, DivergenceExitsThreeAndSaysWhereAndWhy) {
  TempDir dir;
  // The linear spring (rest length 0) under symplectic Euler at h w = 3: past its limit 2, the
  // energy grows about fortyfold a step and passes 1e6 times the scene's scale within a second.
  const Result r = springlab(
      "run spring --set springs.0.rest_length=0 --set particles.1.position=[0.5,0,0] "
      "--method symplectic-euler --dt 0.3 --substeps 1 --duration 100 --csv " +
      (dir / "t.csv").string());
  EXPECT_EQ(r.status, 3);
  for (const char* part : {"diverged during step", "t = ", "symplectic-euler", "h = 0.3 s",
                           "stable up to h = 0.2 s", "1e6 times", "10 rad/s"})
    EXPECT_NE(r.err.find(part), std::string::npos) << part << "\n" << r.err;
  // A warning before the run (the step is past the limit), then the divergence.
  const auto said = lines(r.err);
  ASSERT_EQ(said.size(), 2u) << r.err;
  EXPECT_NE(
      said[0].find("warning: spring: h = 0.3 s is past symplectic-euler's stability limit (0.2 s"),
      std::string::npos)
      << said[0];
  EXPECT_NE(said[1].find("diverged during step"), std::string::npos) << said[1];
  // The trace up to the divergence is complete and kept.
  const auto rows = lines(read_file(dir / "t.csv"));
  EXPECT_GT(rows.size(), 2u);
  for (const auto& row : rows) EXPECT_EQ(row.find("nan"), std::string::npos);
}

// The energy audit: explicit Euler on the undamped spring gains energy at every step and never
// stops; long before the energy reaches 1e6 times the scene's scale, the run is reported as
// numerically unstable, with where it started.
TEST(Run, AnInstabilityCaughtByTheAuditExitsThreeToo) {
  TempDir dir;
  const Result r = springlab("run spring --method euler --dt 0.01 --duration 100 --csv " +
                             (dir / "t.csv").string());
  EXPECT_EQ(r.status, 3);
  for (const char* part :
       {"went numerically unstable during step", "rose by", "from its low at t = ", "euler",
        "h = 0.01 s", "unstable at any step", "symplectic-euler"})
    EXPECT_NE(r.err.find(part), std::string::npos) << part << "\n" << r.err;
  // The warning (no step is small enough for explicit Euler without damping), then the report.
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 2) << r.err;
  const auto rows = lines(read_file(dir / "t.csv"));
  // Stopped within a second (three of the audit's windows once the rise passes its floor, on the
  // first step), not at 1e6 times the scale (step 1728).
  EXPECT_GT(rows.size(), 3 * EnergyAudit::kWindow / 0.01);
  EXPECT_LT(rows.size(), 1.0 / 0.01 + 2);
}

struct BadInput {
  std::string args;
  std::string file;  // written to bad.json when not empty
  std::vector<std::string> expected;
};

TEST(Run, BadInputExitsTwoWithOneMessageNamingWhatIsWrong) {
  TempDir dir;
  const std::string two =
      R"("particles": [{"position": [0,0,0], "pinned": true}, {"position": [1,0,0]}])";
  const std::string rope =
      R"({"generators": [{"type": "rope", "start": [0,0,0], "end": [1,0,0], "stiffness": 1, )";
  // Each message names the file (or the option), the field as a JSON path, and what is allowed.
  const BadInput cases[] = {
      // Scenes that are not there.
      {"run nope", "", {"scene 'nope': no such file", "shipped: ", "spring"}},
      {"run sprng", "", {"did you mean 'spring'?"}},
      // Malformed JSON.
      {"run bad.json", "{\"particles\": [", {"scene 'bad.json': not valid JSON", "line 1"}},
      // Wrong types.
      {"run bad.json",
       R"({"particles": [{"position": "here"}]})",
       {"bad.json", "/particles/0/position", "array of 3 numbers"}},
      {"run bad.json",
       R"({"particles": [{"position": [0,0,0], "pinned": 1}]})",
       {"bad.json", "/particles/0/pinned", "true or false", "got 1"}},
      {"run bad.json",
       "{" + two + R"(, "springs": {"a": 0}})",
       {"bad.json", "/springs", "array of objects", "got an object"}},
      // Unknown fields: the closest known one is suggested.
      {"run bad.json",
       "{" + two + R"(, "gravty": [0,-9.8,0]})",
       {"bad.json", "/gravty: unknown field", "did you mean \"gravity\"?", "known fields here: "}},
      {"run bad.json",
       "{" + two + R"(, "springs": [{"a": 0, "b": 1, "ks": 1, "restlength": 1}]})",
       {"bad.json", "/springs/0/restlength: unknown field", "did you mean \"rest_length\"?"}},
      // Missing required fields.
      {"run bad.json",
       "{" + two + R"(, "springs": [{"a": 0, "b": 1}]})",
       {"bad.json", "/springs/0/ks: is required", "[0, 1e+12]"}},
      {"run bad.json",
       R"({"particles": [{"mass": 1}]})",
       {"bad.json", "/particles/0/position: is required", "[x, y, z]"}},
      {"run bad.json", "{}", {"bad.json", "declares no particles"}},
      // Negative or zero mass.
      {"run bad.json",
       R"({"particles": [{"position": [0,0,0], "mass": -2}]})",
       {"bad.json", "/particles/0/mass", "[1e-09, 1e+09]", "got -2"}},
      {"run bad.json",
       R"({"particles": [{"position": [0,0,0], "mass": 0}]})",
       {"bad.json", "/particles/0/mass", "[1e-09, 1e+09]", "got 0"}},
      {"run bad.json",
       rope + R"("nodes": 4, "mass": 0}]})",
       {"bad.json", "/generators/0/mass", "[1e-09, 1e+09]", "got 0"}},
      // NaN or infinite values (JSON has neither: a NaN is not JSON, an infinity overflows).
      {"run bad.json",
       R"({"particles": [{"position": [0,0,0], "mass": "NaN"}]})",
       {"bad.json", "/particles/0/mass", "must be a number", "[1e-09, 1e+09]"}},
      {"run bad.json",
       R"({"particles": [{"position": [NaN,0,0]}]})",
       {"bad.json", "not valid JSON"}},
      {"run bad.json",
       R"({"particles": [{"position": [0,0,1e999]}]})",
       {"bad.json", "not valid JSON", "number overflow", "1e999"}},
      {"run bad.json",
       R"({"particles": [{"position": [0,0,1e300]}]})",
       {"bad.json", "/particles/0/position/2", "[-1e+09, 1e+09]", "got 1e+300"}},
      // Springs to particles that do not exist, from a particle to itself, with coincident ends,
      // with negative rest lengths.
      {"run bad.json",
       "{" + two + R"(, "springs": [{"a": 0, "b": 2, "ks": 1}]})",
       {"bad.json", "/springs/0/b", "[0, 1]", "got 2"}},
      {"run bad.json",
       "{" + two + R"(, "springs": [{"a": -1, "b": 1, "ks": 1}]})",
       {"bad.json", "/springs/0/a", "[0, 1]", "got -1"}},
      {"run bad.json",
       "{" + two + R"(, "springs": [{"a": 0, "b": "rope:3", "ks": 1}]})",
       {"bad.json", "/springs/0/b", "generator named in this scene", "rope:3"}},
      {"run bad.json",
       "{" + two + R"(, "springs": [{"a": 1, "b": 1, "ks": 1}]})",
       {"bad.json", "/springs/0/b", "same particle as \"a\""}},
      {"run bad.json",
       R"({"particles": [{"position": [0,0,0]}, {"position": [0,0,0]}], "springs": [{"a": 0, "b": 1, "ks": 5, "rest_length": 1}]})",
       {"bad.json", "/springs/0", "ends start at the same point", "rest_length 0"}},
      {"run bad.json",
       "{" + two + R"(, "springs": [{"a": 0, "b": 1, "ks": 1, "rest_length": -2}]})",
       {"bad.json", "/springs/0/rest_length", "[0, 1e+09]", "got -2"}},
      // Generators of zero or absurd size: refused before anything is allocated, with the limit.
      {"run bad.json",
       rope + R"("nodes": 1e9}]})",
       {"bad.json", "/generators/0/nodes", "[2, 4194304]", "got 1e+09"}},
      {"run bad.json",
       rope + R"("nodes": 0}]})",
       {"bad.json", "/generators/0/nodes", "[2, 4194304]", "got 0"}},
      {"run bad.json",
       R"({"generators": [{"type": "cloth", "width": 0, "stretch": 1}]})",
       {"bad.json", "/generators/0/width", "[2, 2048]", "got 0"}},
      {"run bad.json",
       R"({"generators": [{"type": "cloth", "size": [0, 1], "stretch": 1}]})",
       {"bad.json", "/generators/0/size/0", "(0, 1e+06]", "got 0"}},
      {"run bad.json",
       R"({"generators": [{"type": "box", "nodes": [2, 2, 1e6], "stiffness": 1}]})",
       {"bad.json", "/generators/0/nodes/2", "[2, 128]", "got 1e+06"}},
      {"run bad.json",
       "{" + two +
           R"(, "generators": [{"type": "cloth", "width": 2048, "height": 2048, "stretch": 1}]})",
       {"bad.json", "/generators/0", "4194306 particles", "the limit is 4194304"}},
      // Colliders with zero-length normals.
      {"run bad.json",
       "{" + two + R"(, "colliders": [{"type": "plane", "normal": [0,0,0]}]})",
       {"bad.json", "/colliders/0/normal", "must not be zero"}},
      {"run bad.json",
       "{" + two + R"(, "colliders": [{"type": "sphere", "center": [0,0,0], "radius": -1}]})",
       {"bad.json", "/colliders/0/radius", "(0, 1e+06]", "got -1"}},
      // Unknown methods.
      {"run bad.json",
       "{" + two + R"(, "methods": ["rk5"]})",
       {"bad.json", "/methods/0", "unknown method \"rk5\"", "did you mean \"rk4\"?",
        "methods: euler, "}},
      // Non-positive or absurd steps.
      {"run bad.json", "{" + two + R"(, "dt": 0})", {"bad.json", "/dt", "(0, 1]", "got 0"}},
      {"run bad.json", "{" + two + R"(, "dt": -1})", {"bad.json", "/dt", "(0, 1]", "got -1"}},
      {"run bad.json", "{" + two + R"(, "dt": 5})", {"bad.json", "/dt", "(0, 1]", "got 5"}},
      {"run bad.json",
       "{" + two + R"(, "dt": 1e-300})",
       {"bad.json", "dt = 1e-300 s", "1e+301 steps", "the limit is 1e+12"}},
      {"run bad.json",
       "{" + two + R"(, "substeps": 0})",
       {"bad.json", "/substeps", "[1, 100000]", "got 0"}},
      {"run bad.json",
       "{" + two + R"(, "substeps": 1e9})",
       {"bad.json", "/substeps", "[1, 100000]", "got 1e+09"}},
      // Command-line options: the same checks, in the same style.
      {"run spring --dt 0", "", {"--dt", "(0, 1] s", "got 0"}},
      {"run spring --dt -0.5", "", {"--dt", "(0, 1] s", "got -0.5"}},
      {"run spring --dt 5", "", {"--dt", "(0, 1] s", "got 5"}},
      {"run spring --dt nan", "", {"--dt", "(0, 1] s", "got nan"}},
      {"run spring --dt inf", "", {"--dt", "(0, 1] s", "got inf"}},
      {"run spring --dt abc", "", {"--dt"}},
      {"run spring --dt 1e-300",
       "",
       {"spring.json", "dt = 1e-300 s", "1e+301 steps", "the limit is 1e+12", "--dt"}},
      {"run spring --steps 0", "", {"--steps", "[1, 1e+12]", "got 0"}},
      {"run spring --steps -5", "", {"--steps", "[1, 1e+12]", "got -5"}},
      {"run spring --steps 1e13", "", {"--steps", "[1, 1e+12]", "got 1e+13"}},
      {"run spring --steps 2.5", "", {"--steps", "[1, 1e+12]", "got 2.5"}},
      {"run spring --substeps 0", "", {"--substeps", "[1, 100000]", "got 0"}},
      {"run spring --substeps 1e9", "", {"--substeps", "[1, 100000]", "got 1e+09"}},
      {"run spring --substeps many", "", {"--substeps", "[1, 100000]", "got 'many'"}},
      {"run spring --duration 0", "", {"--duration", "(0, 1e+07] s", "got 0"}},
      {"run spring --ks -1", "", {"--ks", "[0, 1e+12] N/m", "got -1"}},
      {"run spring --ks inf", "", {"--ks", "[0, 1e+12] N/m", "got inf"}},
      {"run spring --kd nan", "", {"--kd", "[0, 1e+12] N s/m", "got nan"}},
      {"run spring --threads -1", "", {"--threads", "[0, 1024]", "got -1"}},
      {"run cloth --method local-global --iterations 0",
       "",
       {"--iterations", "[1, 10000]", "got 0"}},
      {"run cloth --method vbd --iterations 2.5", "", {"--iterations", "[1, 10000]", "got 2.5"}},
      {"run cloth --method xpbd --iterations 1e5",
       "",
       {"--iterations", "[1, 10000]", "got 100000"}},
      {"run cloth --method local-global --rho 1", "", {"--rho", "[0, 1)", "got 1"}},
      {"run cloth --method local-global --rho -0.1", "", {"--rho", "[0, 1)", "got -0.1"}},
      {"run cloth --method local-global --rho nan", "", {"--rho", "[0, 1)", "got nan"}},
      {"run spring --method rk5", "", {"--method", "unknown method 'rk5'", "did you mean 'rk4'?"}},
      {"run spring --set nothing=3", "", {"spring.json", "/nothing: unknown field"}},
      {"run spring --set particles.1.mas=2",
       "",
       {"spring.json", "/particles/1/mas: unknown field", "did you mean \"mass\"?"}},
      {"run spring --set particles.1.mass=0",
       "",
       {"spring.json", "/particles/1/mass", "[1e-09, 1e+09]", "got 0"}},
      {"run spring --set springs.0.b=7", "", {"spring.json", "/springs/0/b", "[0, 1]", "got 7"}},
      {"run rope --set rope.nodes=1e9",
       "",
       {"rope.json", "/generators/0/nodes", "[2, 4194304]", "got 1e+09"}},
      {"run spring --set width", "", {"--set width", "KEY=VALUE"}},
      {"run spring --every 0", "", {"--every", "[1, 1e+12]", "got 0"}},
      {"run spring --frobnicate", "", {"frobnicate"}},
      {"run", "", {"scene"}},
      {"explode", "", {"explode"}},
  };
  for (const BadInput& c : cases) {
    if (!c.file.empty()) write_file(dir / "bad.json", c.file);
    const Result r = springlab(c.args, dir.path);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << ": one line\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << c.args << "\n" << r.out;
    for (const std::string& part : c.expected)
      EXPECT_NE(r.err.find(part), std::string::npos) << c.args << ": expected '" << part << "' in\n"
                                                     << r.err;
  }
}

TEST(Run, UnwritableOutputFailsAtOnceAndLeavesNothing) {
  TempDir dir;
  const Result r = springlab("run spring --csv " + (dir / "missing" / "t.csv").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("cannot write in folder"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir.path));
}

TEST(Run, InterruptedRunLeavesNoHalfWrittenTrace) {
  TempDir dir;
  const std::string csv = (dir / "t.csv").string();
  for (int signal : {SIGINT, SIGTERM}) {
    const char* argv[] = {SPRINGLAB_EXECUTABLE, "run",  "cloth", "--duration", "1000", "--csv",
                          csv.c_str(),          nullptr};
    pid_t pid = 0;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    ASSERT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, const_cast<char**>(argv), environ), 0);
    posix_spawn_file_actions_destroy(&actions);
    // Wait until the run is writing its temporary file, then interrupt it.
    for (int k = 0; k < 200 && std::filesystem::is_empty(dir.path); ++k)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    ASSERT_FALSE(std::filesystem::is_empty(dir.path)) << "the run never started writing";
    ::kill(pid, signal);
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status));
    EXPECT_TRUE(std::filesystem::is_empty(dir.path))
        << "left: " << std::filesystem::directory_iterator(dir.path)->path();
  }
}

}  // namespace
}  // namespace springlab::test
