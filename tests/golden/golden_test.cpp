// Golden images: each case of cases.txt is rendered headlessly on the software rasteriser and
// compared with its reference with a tolerance: a pixel differs when any channel is off by more
// than kChannel, and a case fails when more than kFraction of its pixels differ. A failure
// writes the actual image and a diff image (differing pixels in red over a faded copy) beside
// the test output and says where. SPRINGLAB_UPDATE_GOLDENS=1 (scripts/update-goldens.sh)
// rewrites the references instead; nothing else ever does.
//
// Also: the same frame renders to identical bytes twice in one process, in two processes, and
// whatever the number of rasteriser or simulation threads.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "cli/cli_support.hpp"
#include "draw/scene_frame.hpp"
#include "gfx/offscreen.hpp"
#include "io/png.hpp"
#include "session/session.hpp"

namespace springlab::test {
namespace {

namespace fs = std::filesystem;

constexpr int kChannel = 24;         // of 255
constexpr double kFraction = 0.005;  // of the pixels

struct Case {
  std::string name, args;
  int frame = 0;
};

// CTest names each case by this, not by the struct's bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::vector<Case> load_cases() {
  std::vector<Case> cases;
  std::ifstream in(std::string(SPRINGLAB_SOURCE_DIR) + "/tests/golden/cases.txt");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    Case c;
    s >> c.name;
    std::getline(s, c.args);
    const auto select = c.args.find("--select ");
    c.frame = select == std::string::npos ? 0 : std::stoi(c.args.substr(select + 9));
    cases.push_back(c);
  }
  return cases;
}

fs::path golden_dir() { return fs::path(SPRINGLAB_SOURCE_DIR) / "tests" / "golden"; }
fs::path failure_dir() { return fs::path(SPRINGLAB_BINARY_DIR) / "golden-failures"; }

std::string frame_file(int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", frame);
  return name;
}

// Renders a case into `dir`; returns the frame's path.
fs::path render(const Case& c, const fs::path& dir) {
  const Result r = springlab("render " + c.args + " --software --out '" + dir.string() + "'", SPRINGLAB_SOURCE_DIR);
  EXPECT_TRUE(r.status == 0 || r.status == 3) << c.name << ": " << r.err;
  return dir / frame_file(c.frame);
}

struct Difference {
  std::size_t differing = 0, total = 0;
  app::Image diff;
};

Difference compare(const app::Image& expected, const app::Image& actual) {
  Difference d;
  d.total = static_cast<std::size_t>(expected.width) * expected.height;
  d.diff = expected;
  for (std::size_t p = 0; p < d.total; ++p) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(expected.rgba[4 * p + c]) - int(actual.rgba[4 * p + c])));
    std::uint8_t* out = d.diff.rgba.data() + 4 * p;
    if (worst > kChannel) {
      ++d.differing;
      out[0] = 255, out[1] = 0, out[2] = 0;
    } else {
      for (int c = 0; c < 3; ++c) out[c] = static_cast<std::uint8_t>(64 + out[c] / 4);
    }
    out[3] = 255;
  }
  return d;
}

class Golden : public ::testing::TestWithParam<Case> {};

TEST_P(Golden, MatchesItsReference) {
  const Case& c = GetParam();
  TempDir dir;
  const fs::path actual_path = render(c, dir.path);
  ASSERT_TRUE(fs::exists(actual_path)) << c.name << ": no frame written";
  const fs::path reference = golden_dir() / (c.name + ".png");
  if (std::getenv("SPRINGLAB_UPDATE_GOLDENS")) {
    fs::copy_file(actual_path, reference, fs::copy_options::overwrite_existing);
    std::printf("updated %s\n", reference.c_str());
    return;
  }
  ASSERT_TRUE(fs::exists(reference)) << reference << " is missing: run scripts/update-goldens.sh";
  const app::Image expected = app::read_png(reference);
  const app::Image actual = app::read_png(actual_path);
  ASSERT_EQ(actual.width, expected.width);
  ASSERT_EQ(actual.height, expected.height);
  const Difference d = compare(expected, actual);
  const double fraction = static_cast<double>(d.differing) / d.total;
  if (fraction > kFraction) {
    fs::create_directories(failure_dir());
    const fs::path out_actual = failure_dir() / (c.name + "-actual.png");
    const fs::path out_diff = failure_dir() / (c.name + "-diff.png");
    app::write_png(out_actual, actual, 6);
    app::write_png(out_diff, d.diff, 6);
    ADD_FAILURE() << c.name << ": " << d.differing << " of " << d.total << " pixels differ by more than " << kChannel
                  << " (" << 100.0 * fraction << "% > " << 100.0 * kFraction << "%).\n  reference: " << reference
                  << "\n  actual:    " << out_actual << "\n  diff:      " << out_diff
                  << "\n  If the change is intended: scripts/update-goldens.sh";
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, Golden, ::testing::ValuesIn(load_cases()), [](const auto& info) {
  std::string name = info.param.name;
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
});

// The deterministic charts of `compare spring` (not work-precision against wall time).
TEST(GoldenCharts, OfTheSpring) {
  TempDir dir;
  const Result r = springlab("compare spring --software --points 6 --duration 1 --drift-duration 5 "
                             "--tol-range 1e-9:1e-5 --out '" + dir.path.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* chart : {"work-precision-work", "convergence", "stability", "energy-drift"}) {
    const fs::path actual_path = dir / (std::string(chart) + ".png");
    const fs::path reference = golden_dir() / ("charts-spring-" + std::string(chart) + ".png");
    if (std::getenv("SPRINGLAB_UPDATE_GOLDENS")) {
      fs::copy_file(actual_path, reference, fs::copy_options::overwrite_existing);
      std::printf("updated %s\n", reference.c_str());
      continue;
    }
    ASSERT_TRUE(fs::exists(reference)) << reference << " is missing: run scripts/update-goldens.sh";
    const app::Image expected = app::read_png(reference), actual = app::read_png(actual_path);
    ASSERT_EQ(actual.width, expected.width);
    const Difference d = compare(expected, actual);
    const double fraction = static_cast<double>(d.differing) / d.total;
    if (fraction > kFraction) {
      fs::create_directories(failure_dir());
      app::write_png(failure_dir() / ("charts-spring-" + std::string(chart) + "-actual.png"), actual, 6);
      app::write_png(failure_dir() / ("charts-spring-" + std::string(chart) + "-diff.png"), d.diff, 6);
      ADD_FAILURE() << chart << ": " << 100.0 * fraction << "% of pixels differ; see " << failure_dir();
    }
  }
}

std::string bytes(const fs::path& p) { return read_file(p); }

TEST(Deterministic, SameFrameInTwoProcessesIsTheSameBytes) {
  const Case c{"jelly", "jelly --frames 31 --select 30 --size 480x270 --ui --ui-scale 0.75", 30};
  TempDir a, b;
  const auto pa = render(c, a.path), pb = render(c, b.path);
  ASSERT_FALSE(bytes(pa).empty());
  EXPECT_EQ(bytes(pa), bytes(pb));
}

TEST(Deterministic, RasteriserAndSimulationThreadsChangeNoPixel) {
  // llvmpipe's threads, and the simulation's (a cloth big enough to run in parallel).
  // (A 48 x 48 cloth has twice the 24 x 24 one's highest frequency: two sub-steps keep it stable.)
  const std::string args = "render cloth --set cloth.width=48 --set cloth.height=48 --substeps 2 --frames 21 --select 20 --size 480x270 --software";
  TempDir a, b, c;
  ASSERT_EQ(springlab(args + " --threads 1 --out '" + a.path.string() + "'").status, 0);
  ASSERT_EQ(springlab(args + " --threads 2 --out '" + b.path.string() + "'").status, 0);
  ASSERT_EQ(std::system(("LP_NUM_THREADS=1 '" SPRINGLAB_EXECUTABLE "' " + args + " --out '" + c.path.string() +
                         "' > /dev/null 2>&1").c_str()), 0);
  const auto frame = frame_file(20);
  EXPECT_EQ(bytes(a.path / frame), bytes(b.path / frame));
  EXPECT_EQ(bytes(a.path / frame), bytes(c.path / frame));
}

TEST(Deterministic, SameFrameTwiceInOneProcess) {
  Scene scene = load_scene(std::string(SPRINGLAB_SOURCE_DIR) + "/assets/scenes/cloth-sphere.json");
  SimulationSettings settings;
  settings.method = scene.methods.front();
  settings.dt = scene.dt;
  app::Session session(scene, settings);
  for (int k = 0; k < 30; ++k) session.advance_frame();
  gfx::Offscreen offscreen(true, 320, 180, 0.0f);
  const auto options = draw::ViewOptions::for_scene(session.scene());
  const draw::Frame frame = draw::build_frame(session, options, {0, 0, 320, 180});
  app::Image first, second;
  offscreen.render(frame, {}, first);
  offscreen.render(frame, {}, second);
  EXPECT_EQ(first.rgba, second.rgba);
  // And the picture is not blank: the cloth, the sphere and the ground are there.
  std::set<std::uint32_t> colours;
  for (std::size_t p = 0; p < first.rgba.size(); p += 4)
    colours.insert(first.rgba[p] << 16 | first.rgba[p + 1] << 8 | first.rgba[p + 2]);
  EXPECT_GT(colours.size(), 200u);
}

}  // namespace
}  // namespace springlab::test
