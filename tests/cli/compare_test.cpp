// springlab compare, as a student runs it: results and summary CSVs, charts in PNG and SVG for
// every shipped scene, the printed table, and clear errors for bad options.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "cli/cli_support.hpp"
#include "io/png.hpp"
#include "springlab/methods.hpp"
#include "springlab/scene.hpp"

namespace springlab::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::vector<std::string>> csv(const fs::path& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(read_file(path));
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::istringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    rows.push_back(cells);
  }
  return rows;
}

TEST(Compare, OnTheSpringWritesResultsSummaryAndCharts) {
  TempDir dir;
  const Result r =
      springlab("compare spring --software --points 5 --duration 1 --drift-duration 2 --out " +
                dir.path.string());
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* file : {"results.csv", "summary.csv", "work-precision.png", "work-precision.svg",
                           "work-precision-work.png", "work-precision-work.svg", "convergence.png",
                           "convergence.svg", "stability.png", "stability.svg", "energy-drift.png",
                           "energy-drift.svg", "solver-convergence.png", "solver-convergence.svg"})
    EXPECT_TRUE(fs::exists(dir / file)) << file;
  const auto summary = csv(dir / "summary.csv");
  ASSERT_EQ(summary.size(), methods().size() + 1);  // header and every method
  EXPECT_EQ(summary[0][0], "method");
  for (std::size_t k = 1; k < summary.size(); ++k) {
    const int table = std::stoi(summary[k][1]);
    if (summary[k][2].empty()) continue;
    EXPECT_NEAR(std::stod(summary[k][2]), table, 0.2) << summary[k][0];
  }
  const auto results = csv(dir / "results.csv");
  EXPECT_EQ(results[0].size(), 15u);
  EXPECT_EQ(results[0][14], "unstable");
  EXPECT_EQ(summary[0].size(), 11u);
  EXPECT_EQ(summary[0][5], "measured_resolution");
  EXPECT_EQ(summary[0][9], "error_floor");
  EXPECT_GT(results.size(), 40u);
  for (const char* part :
       {"reference: exact solution", "symplectic-euler", "0.2 s", "0.2828 s", "never", "always"})
    EXPECT_NE(r.out.find(part), std::string::npos) << part << "\n" << r.out;
  EXPECT_NE(read_file(dir / "convergence.svg").find("rk4 (order"), std::string::npos);
  // The stability regions at the scene's step h = 1/120 s: w = 10 rad/s, so h w = 0.0833 against
  // RK4's 2.828 (h may grow x33.9) and symplectic Euler's 2 (x24); explicit Euler has no step.
  const std::string complex = read_file(dir / "stability-region.svg");
  EXPECT_NE(complex.find("rk4: every mode inside; h may grow x33.9"), std::string::npos);
  EXPECT_NE(complex.find("euler: unstable at any step"), std::string::npos);
  const std::string oscillator = read_file(dir / "stability-region-oscillator.svg");
  EXPECT_NE(oscillator.find("symplectic-euler: every mode inside; h may grow x24"),
            std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "stability-region.png"));
  EXPECT_TRUE(fs::exists(dir / "stability-region-oscillator.png"));
  const app::Image png = app::read_png(dir / "convergence.png");
  EXPECT_EQ(png.width, 1200);
}

// A diagonally implicit tableau in compare: its order measured, and its measured stable step's
// probes, out to h w = 1000, never end the command (a step whose stage Newton could not converge
// ended it with exit 1 before: it counts as a run that did not hold).
// The shipped diagonally implicit tableaux compared to the end: their orders, and their measured
// stable step "always", found as implicit Euler's is (runs of 2000 steps up to h w = 1000, since
// the analysis proves them A-stable; runs of the full length took 14 s for SDIRK3 alone, 0.16 s
// now, implicit Euler's 0.03 s).
TEST(Compare, ADiagonallyImplicitTableauIsComparedToTheEnd) {
  TempDir dir;
  const Result r = springlab(
      "compare spring --methods sdirk3,implicit-midpoint,trapezoidal --no-charts --points 4 "
      "--out " +
      dir.path.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("trapezoidal        2.00 (2)         always                 always"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("implicit-midpoint  2.00 (2)         always                 always"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("sdirk3             2.99 (3)         always                 always"),
            std::string::npos)
      << r.out;
}

class EveryScene : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryScene, IsChartedWithoutError) {
  const std::string name = GetParam();
  const Scene scene =
      load_scene(std::string(SPRINGLAB_SOURCE_DIR) + "/assets/scenes/" + name + ".json");
  std::ostringstream range;
  range.precision(17);
  range << scene.dt / 2 << ":" << scene.dt;
  TempDir dir;
  const Result r = springlab(
      "compare " + name + " --software --points 2 --duration " + std::to_string(20 * scene.dt) +
      " --drift-duration " + std::to_string(20 * scene.dt) + " --dt-range " + range.str() +
      " --tol-range 1e-5:1e-4 --stability-budget 1e6 --out " + dir.path.string());
  if (scene.ik) {  // no integrator to chart: said so, and nothing written
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("inverse-kinematics scene"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "convergence.png"));
    return;
  }
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* chart :
       {"work-precision", "work-precision-work", "convergence", "stability", "energy-drift"}) {
    EXPECT_TRUE(fs::exists(dir / (std::string(chart) + ".png"))) << chart;
    EXPECT_TRUE(fs::exists(dir / (std::string(chart) + ".svg"))) << chart;
  }
  // The stability regions for a scene with springs; none for a particle system (no oscillating
  // modes); never a NaN or infinite coordinate in any chart.
  const bool springs = scene.model.spring_count() > 0;
  for (const char* chart : {"stability-region", "stability-region-oscillator"})
    EXPECT_EQ(fs::exists(dir / (std::string(chart) + ".svg")), springs) << chart;
  for (const auto& e : fs::directory_iterator(dir.path))
    if (e.path().extension() == ".svg") {
      const std::string svg = read_file(e.path());
      EXPECT_EQ(svg.find("nan"), std::string::npos) << e.path();
      EXPECT_EQ(svg.find("inf\""), std::string::npos) << e.path();
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, EveryScene, ::testing::ValuesIn(shipped_scenes()),
                         [](const auto& info) { return scene_test_name(info.param); });

// A new UI language is its .po file and nothing else (CONTRIBUTING.md, "A UI language"): a data
// folder whose assets/locale/ holds one more catalog, in Czech, whose letters (c with caron)
// are beyond Latin-1, is offered by --help, accepted by --lang in any of the environment's
// forms, and speaks on the charts; a language with no catalog is still refused, naming both.
TEST(Compare, ANewLanguageIsItsCatalogAlone) {
  TempDir data;
  fs::create_directories(data / "assets" / "locale");
  for (const char* folder : {"scenes", "tableaux", "lessons", "scripts"})
    fs::create_directory_symlink(fs::path(SPRINGLAB_SOURCE_DIR) / "assets" / folder,
                                 data / "assets" / folder);
  fs::create_directory_symlink(fs::path(SPRINGLAB_SOURCE_DIR) / "shaders", data / "shaders");
  fs::copy_file(fs::path(SPRINGLAB_SOURCE_DIR) / "assets/locale/zh-CN.po",
                data / "assets/locale/zh-CN.po");
  write_file(
      data / "assets/locale/cs.po",
      "msgid \"\"\nmsgstr \"\"\n\"Language: cs\\n\"\n\"X-Language-Name: \u010ce\u0161tina\\n\"\n"
      "\"Content-Type: text/plain; charset=UTF-8\\n\"\n\n"
      "#, c-format\nmsgid \"Convergence on %s: error against step (x = diverged)\"\n"
      "msgstr \"Konvergence na %s: chyba podle kroku (x = divergence)\"\n\n"
      "msgid \"step h (s)\"\nmsgstr \"krok h (s)\"\n");
  const std::string with = "SPRINGLAB_DATA='" + data.path.string() + "' ";
  const Result help = springlab_with(with, "compare --help");
  EXPECT_NE(help.out.find("en, cs, zh-CN"), std::string::npos) << help.out;
  TempDir out;
  const Result r =
      springlab_with(with,
                     "compare spring --methods euler,rk4 --points 3 --drift-duration 0 --software "
                     "--lang cs_CZ.UTF-8 --out " +
                         out.path.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string svg = read_file(out / "convergence.svg");
  EXPECT_NE(svg.find("Konvergence na spring: chyba podle kroku"), std::string::npos);
  EXPECT_NE(svg.find("krok h (s)"), std::string::npos);
  EXPECT_NE(svg.find("error (m)"), std::string::npos);  // (untranslated: the English)
  const Result refused =
      springlab_with(with, "compare spring --lang de --out " + out.path.string());
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("'de' is not a language springlab speaks (en, cs, zh-CN)"),
            std::string::npos)
      << refused.err;
}

TEST(Compare, BadOptionsExitTwo) {
  TempDir dir;
  const std::string out = " --out " + dir.path.string();
  const std::pair<std::string, std::string> cases[] = {
      {"compare spring", "--out is required"},
      {"compare spring --points 1" + out, "--points: must be in [2, 64]"},
      {"compare spring --dt-range 0:0.1" + out, "--dt-range: must be LO:HI with 0 < LO < HI"},
      {"compare spring --dt-range 0.1:0.01" + out, "--dt-range"},
      {"compare spring --dt-range fast" + out, "--dt-range"},
      {"compare spring --tol-range 1e-3" + out, "--tol-range"},
      {"compare spring --methods euler,rk5" + out, "--methods: unknown method 'rk5'"},
      {"compare spring --repeats 0" + out, "--repeats"},
      {"compare spring --duration 0.001 --dt-range 0.001:0.01" + out,
       "--duration: must be at least the largest step"},
      {"compare spring --out /proc/springlab/charts", "--out: cannot create the folder"},
  };
  for (const auto& [args, expected] : cases) {
    const Result r = springlab(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << args << "\n" << r.err;
  }
}

}  // namespace
}  // namespace springlab::test
