// The window, run as a user (or a course's CI) runs it: under xvfb-run, springlab view SCENE
// --frames N --screenshot FILE on every shipped scene; a script that drags a particle and
// switches method; no display; bad options.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <set>

#include "cli/cli_support.hpp"
#include "io/png.hpp"
#include "util/language.hpp"

namespace springlab::test {
namespace {

namespace fs = std::filesystem;

Result view(const std::string& args, const fs::path& cwd = ".") {
  return springlab_under_xvfb("view " + args, cwd);
}

// Distinct colours, and bright (text) pixels, in a rectangle of an image.
struct Content {
  std::size_t colours = 0, bright = 0;
};
Content content(const app::Image& im, int x0, int y0, int x1, int y1) {
  std::set<std::uint32_t> colours;
  Content c;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::uint8_t* p = im.rgba.data() + (static_cast<std::size_t>(y) * im.width + x) * 4;
      colours.insert(p[0] << 16 | p[1] << 8 | p[2]);
      if (p[0] > 200 && p[1] > 200 && p[2] > 200) ++c.bright;
    }
  c.colours = colours.size();
  return c;
}

class EveryScene : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryScene, OpensAndShowsTheSceneAndThePanels) {
  TempDir dir;
  const fs::path shot = dir / "shot.png";
  const Result r = view(GetParam() + " --frames 20 --screenshot " + shot.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("frames     20 in"), std::string::npos) << r.out;
  const app::Image im = app::read_png(shot);
  ASSERT_EQ(im.width, 1280);
  ASSERT_EQ(im.height, 720);
  // The controls on the left: text.
  EXPECT_GT(content(im, 0, 0, 360, 720).bright, 500u);
  // The charts at the bottom: lines and labels in several colours.
  EXPECT_GT(content(im, 380, 470, 1280, 720).colours, 20u);
  // The scene itself: not an empty background.
  EXPECT_GT(content(im, 380, 0, 1280, 450).colours, 10u);
}

INSTANTIATE_TEST_SUITE_P(Scenes, EveryScene, ::testing::ValuesIn(shipped_scenes()),
                         [](const auto& info) { return scene_test_name(info.param); });

TEST(View, AScriptDragsAParticleAndSwitchesTheMethod) {
  TempDir dir;
  const std::string script =
      std::string(SPRINGLAB_SOURCE_DIR) + "/assets/scripts/rope-drag-euler-to-rk4.json";
  const Result r =
      view("rope --frames 270 --script " + script + " --screenshot " + (dir / "a.png").string());
  ASSERT_EQ(r.status, 0) << r.err;
  // Grabbed where it was at t = 0.4 s, let go at the path's last waypoint.
  const std::regex dragged(
      R"(dragged    particle 15 from \(.*\) to \(3.4, -0.4, 0\): ([0-9.e+-]+) m)");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, dragged)) << r.out;
  EXPECT_GT(std::stod(m[1]), 0.3);
  EXPECT_NE(r.out.find("lane       rk4 at t = 4.5 s"), std::string::npos)
      << r.out;  // switched at 4 s

  // And the picture differs from the same frames without the script.
  const Result plain = view("rope --frames 270 --screenshot " + (dir / "b.png").string());
  ASSERT_EQ(plain.status, 0) << plain.err;
  const app::Image a = app::read_png(dir / "a.png"), b = app::read_png(dir / "b.png");
  std::size_t differ = 0;
  for (std::size_t k = 0; k < a.rgba.size(); ++k) differ += a.rgba[k] != b.rgba[k];
  EXPECT_GT(differ, 1000u);
}

TEST(View, CompareModeStartsFromTheCommandLine) {
  const Result r = view("spring --frames 30 --compare euler,verlet,rk4");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* lane : {"lane       euler", "lane       verlet", "lane       rk4"})
    EXPECT_NE(r.out.find(lane), std::string::npos) << r.out;
}

// An IK scene's lanes are its solvers (its kind's rows), by the command line and by a link's
// names alike.
TEST(View, CompareModeOfAnIkSceneNamesItsSolvers) {
  const Result r = view("ik-arm --frames 30 --compare ccd,dls");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* lane : {"lane       ccd", "lane       dls"})
    EXPECT_NE(r.out.find(lane), std::string::npos) << r.out;
}

TEST(View, WithoutADisplaySaysWhatToDo) {
  const Result r = springlab_with("env -u DISPLAY -u WAYLAND_DISPLAY ", "view spring --frames 1");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("needs a display"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("springlab render"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(View, BadOptionsExitTwo) {
  for (const auto& [args, expected] : std::vector<std::pair<std::string, std::string>>{
           {"view spring --screenshot x.png", "--screenshot: needs --frames N"},
           {"view spring --frames 0", "--frames"},
           {"view spring --size 10x10 --frames 1", "--size"},
           {"view spring --compare euler --frames 1", "--compare: give 2 to 4 methods"},
           {"view ik-arm --compare ccd,rk4 --frames 1",
            "--compare: unknown solver 'rk4' (this is an inverse-kinematics scene"},
           {"view nope --frames 1", "scene 'nope'"},
           {"view spring --ui-scale 9 --frames 1", "--ui-scale"},
           {"view spring --lang fr --frames 1",
            "--lang: 'fr' is not a language springlab speaks (en, zh-CN)"},
           {"view spring --keys F6,Bogus --frames 1", "--keys: unknown key 'Bogus'"}}) {
    const Result r = springlab(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << args << "\n" << r.err;
  }
}

// The window speaks the environment's language as gettext reads it (LANGUAGE, LC_ALL,
// LC_MESSAGES, LANG), or --lang's; a locale springlab has no translation for is English.
TEST(View, SpeaksTheLanguageOfTheEnvironmentOrOfLang) {
  for (const auto& [env, args, expected] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
           {"LANG=zh_CN.UTF-8 LC_ALL= LC_MESSAGES= LANGUAGE=", "", "zh-CN"},
           {"LANG=en_GB.UTF-8 LC_ALL= LC_MESSAGES=zh_CN.UTF-8 LANGUAGE=", "", "zh-CN"},
           {"LANG=zh_CN.UTF-8 LC_ALL=fr_FR.UTF-8 LC_MESSAGES= LANGUAGE=", "", "en"},
           {"LANG=zh_CN.UTF-8 LC_ALL= LC_MESSAGES= LANGUAGE=", "--lang en", "en"},
           {"LANG=C LC_ALL= LC_MESSAGES= LANGUAGE=", "--lang zh-CN", "zh-CN"}}) {
    const Result r =
        springlab_under_xvfb("view spring --frames 2 " + args, ".", "env " + env + " ");
    ASSERT_EQ(r.status, 0) << env << " " << args << "\n" << r.err;
    EXPECT_NE(r.out.find("language   " + expected + "\n"), std::string::npos)
        << env << " " << args << "\n"
        << r.out;
  }
}

// The environment's language without a window (every case gettext's reading decides): LANGUAGE's
// list before the locale, its first language springlab speaks, ignored under the C locale.
TEST(View, TheEnvironmentsLanguageAsGettextReadsIt) {
  const auto with = [](const char* language, const char* lang) {
    for (const char* name : {"LC_ALL", "LC_MESSAGES"}) unsetenv(name);
    setenv("LANGUAGE", language, 1);
    setenv("LANG", lang, 1);
    return app::environment_language();
  };
  EXPECT_EQ(with("zh_CN:en", "en_US.UTF-8"), "zh-CN");
  EXPECT_EQ(with("en:zh_CN", "zh_CN.UTF-8"), "en");
  EXPECT_EQ(with("fr:zh_CN:en", "en_US.UTF-8"), "zh-CN");  // (no French: the next it speaks)
  EXPECT_EQ(with("fr:de", "zh_CN.UTF-8"), "en");           // (none it speaks: untranslated)
  EXPECT_EQ(with("zh_CN:en", "C"), "en");                  // (the C locale ignores LANGUAGE)
  EXPECT_EQ(with("", "zh_TW.UTF-8"), "zh-CN");
  EXPECT_EQ(with("", "en_GB.UTF-8"), "en");
  unsetenv("LANGUAGE");
  unsetenv("LANG");
}

// A lesson in the window: its band across the top (the caption's text), the scene and the panels
// below it, from the step asked for.
TEST(View, TeachesALessonWithItsCaptionAboveTheScene) {
  TempDir dir;
  const fs::path shot = dir / "shot.png";
  const Result r =
      view("--lesson damping-buys-a-limit --step 2 --frames 20 --screenshot " + shot.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const app::Image im = app::read_png(shot);
  ASSERT_EQ(im.width, 1280);
  EXPECT_GT(content(im, 0, 30, 1280, 100).bright, 2000u);    // the caption, large
  EXPECT_GT(content(im, 380, 160, 1280, 450).colours, 10u);  // the scene, under the band
  EXPECT_GT(content(im, 0, 170, 360, 720).bright, 500u);     // the controls
}

// The panels by keyboard alone (ui/keyboard_focus.hpp), keys pressed as a person presses them
// (--keys: one every other frame from the third). 40 frames are 0.667 s; a pause at the k-th key
// stops the clock at frame 2k (t = k / 30 s). The key paths follow the rope's panel (scene,
// lesson, method, then Pause; the last header "View and files" after "A particle by keys"): a
// change there moves them.
TEST(View, ThePanelsAreRunByKeyboardAlone) {
  const auto lane = [](const std::string& keys) {
    const Result r = view("rope --frames 40 --keys " + keys);
    EXPECT_EQ(r.status, 0) << keys << "\n" << r.err;
    const std::size_t at = r.out.find("lane       ");
    return at == std::string::npos ? r.out : r.out.substr(at, r.out.find('\n', at) - at);
  };
  // Space: the scene's (pause) until F6 gives the keys to the panels, where it presses the
  // control in focus (here the scene's list, opened); Esc, F6 past the last panel (the controls,
  // then the charts), or Shift+F6 back past the first, give them back; Ctrl+Tab takes them too.
  EXPECT_EQ(lane("Space"), "lane       euler at t = 0.03333 s");
  EXPECT_EQ(lane("F6,Space"), "lane       euler at t = 0.6667 s");
  EXPECT_EQ(lane("F6,Escape,Space"), "lane       euler at t = 0.1 s");
  EXPECT_EQ(lane("F6,F6,F6,Space"), "lane       euler at t = 0.1333 s");
  EXPECT_EQ(lane("F6,F6,Shift+F6,Shift+F6,Space"), "lane       euler at t = 0.1667 s");
  EXPECT_EQ(lane("Ctrl+Tab,Space"), "lane       euler at t = 0.6667 s");
  // The controls, operated: Pause (the arrows move between controls), the method's list (Space
  // opens it, Down and Space choose the row after explicit Euler's).
  EXPECT_EQ(lane("F6,Down,Down,Down,Space"), "lane       euler at t = 0.1667 s");
  EXPECT_EQ(lane("F6,Down,Down,Space,Down,Space"), "lane       symplectic-euler at t = 0.6667 s");

  // A particle held and moved by keys: "A particle by keys" opened (End, Up, Space), particle 15
  // typed (Enter, 1, 5, Enter), held, moved right three times (a twentieth of the rope's 4 m
  // extent each: 0.6 m in all), let go.
  const Result r = view(
      "rope --frames 60 --keys F6,End,Up,Space,Down,Enter,1,5,Enter,Down,Space,Right,Right,Right,"
      "Space,Space,Space,Left,Left,Left,Space");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(
      r.out.find("dragged    particle 15 from (3.826, -0.6358, 0) to (4.426, -0.6358, 0): 0.6 m"),
      std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace springlab::test
