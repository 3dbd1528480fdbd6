// Seen by everyone (issue 44): the methods' colours under simulated colour blindness, their marks,
// and the text's contrast measured on the rendered golden frames.
//
// Colour science, from its published sources: sRGB's transfer curve and relative luminance
// (IEC 61966-2-1, as WCAG 2.1 uses them), CIELAB under D65, CIEDE2000 (checked against Sharma,
// Wu and Dalal's published test pairs, 2005), and protanopia, deuteranopia and tritanopia as
// Machado, Oliveira and Fernandes (2009) simulate them at full severity, in linear RGB.
#include "draw/palette.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "draw/marks.hpp"
#include "io/png.hpp"
#include "ui/theme.hpp"
#include "util/data_dir.hpp"

namespace springlab::test {
namespace {

namespace fs = std::filesystem;
using Rgb = std::array<double, 3>;
using Mat = std::array<Rgb, 3>;

double linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
// As drawn: 8 bits a channel.
Rgb rgb(const draw::Rgba& c) {
  const auto byte = [](float x) { return std::round(std::clamp(x, 0.0f, 1.0f) * 255.0) / 255.0; };
  return {byte(c.r), byte(c.g), byte(c.b)};
}
Rgb lin(const Rgb& c) {
  return {linear(c[0]), linear(c[1]), linear(c[2])};
}
double luminance_of_linear(const Rgb& l) {
  return 0.2126 * l[0] + 0.7152 * l[1] + 0.0722 * l[2];
}
// WCAG 2.1's contrast ratio of two sRGB colours.
double contrast(const Rgb& a, const Rgb& b) {
  const double la = luminance_of_linear(lin(a)), lb = luminance_of_linear(lin(b));
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

Rgb times(const Mat& m, const Rgb& v) {
  Rgb out{};
  for (int i = 0; i < 3; ++i)
    out[i] = std::clamp(m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2], 0.0, 1.0);
  return out;
}

// Linear RGB to CIELAB (D65 white).
Rgb lab(const Rgb& l) {
  const double X = (0.4124564 * l[0] + 0.3575761 * l[1] + 0.1804375 * l[2]) / 0.95047;
  const double Y = 0.2126729 * l[0] + 0.7151522 * l[1] + 0.0721750 * l[2];
  const double Z = (0.0193339 * l[0] + 0.1191920 * l[1] + 0.9503041 * l[2]) / 1.08883;
  const auto f = [](double t) {
    return t > 216.0 / 24389.0 ? std::cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0;
  };
  return {116.0 * f(Y) - 16.0, 500.0 * (f(X) - f(Y)), 200.0 * (f(Y) - f(Z))};
}

double degrees(double r) {
  return r * 180.0 / std::numbers::pi;
}
double radians(double d) {
  return d * std::numbers::pi / 180.0;
}

// CIEDE2000 (Sharma, Wu and Dalal 2005, equations 1 to 25).
double de2000(const Rgb& lab1, const Rgb& lab2) {
  const auto [L1, a1, b1] = lab1;
  const auto [L2, a2, b2] = lab2;
  const double Cb = 0.5 * (std::hypot(a1, b1) + std::hypot(a2, b2));
  const double G = 0.5 * (1.0 - std::sqrt(std::pow(Cb, 7) / (std::pow(Cb, 7) + std::pow(25.0, 7))));
  const double a1p = (1 + G) * a1, a2p = (1 + G) * a2;
  const double C1p = std::hypot(a1p, b1), C2p = std::hypot(a2p, b2);
  const auto hue = [](double b, double a) {
    const double h = degrees(std::atan2(b, a));
    return (a == 0 && b == 0) ? 0.0 : h < 0 ? h + 360.0 : h;
  };
  const double h1p = hue(b1, a1p), h2p = hue(b2, a2p);
  double dh = 0.0;
  if (C1p * C2p != 0.0) {
    dh = h2p - h1p;
    if (dh > 180)
      dh -= 360;
    else if (dh < -180)
      dh += 360;
  }
  const double dLp = L2 - L1, dCp = C2p - C1p,
               dHp = 2.0 * std::sqrt(C1p * C2p) * std::sin(radians(dh / 2));
  const double Lbp = 0.5 * (L1 + L2), Cbp = 0.5 * (C1p + C2p);
  double hbp = h1p + h2p;
  if (C1p * C2p != 0.0)
    hbp = std::abs(h1p - h2p) <= 180
              ? 0.5 * (h1p + h2p)
              : (h1p + h2p < 360 ? 0.5 * (h1p + h2p + 360) : 0.5 * (h1p + h2p - 360));
  const double T = 1 - 0.17 * std::cos(radians(hbp - 30)) + 0.24 * std::cos(radians(2 * hbp)) +
                   0.32 * std::cos(radians(3 * hbp + 6)) - 0.20 * std::cos(radians(4 * hbp - 63));
  const double dtheta = 30 * std::exp(-std::pow((hbp - 275) / 25, 2));
  const double Rc = 2 * std::sqrt(std::pow(Cbp, 7) / (std::pow(Cbp, 7) + std::pow(25.0, 7)));
  const double Sl = 1 + 0.015 * std::pow(Lbp - 50, 2) / std::sqrt(20 + std::pow(Lbp - 50, 2));
  const double Sc = 1 + 0.045 * Cbp, Sh = 1 + 0.015 * Cbp * T,
               Rt = -std::sin(radians(2 * dtheta)) * Rc;
  return std::sqrt(std::pow(dLp / Sl, 2) + std::pow(dCp / Sc, 2) + std::pow(dHp / Sh, 2) +
                   Rt * (dCp / Sc) * (dHp / Sh));
}

// Machado, Oliveira and Fernandes (2009), severity 1.
struct Vision {
  const char* name;
  Mat m;
};
const Vision kVisions[] = {
    {"normal vision", {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}},
    {"protanopia",
     {{{0.152286, 1.052583, -0.204868},
       {0.114503, 0.786281, 0.099216},
       {-0.003882, -0.048116, 1.051998}}}},
    {"deuteranopia",
     {{{0.367322, 0.860646, -0.227968},
       {0.280085, 0.672501, 0.047413},
       {-0.011820, 0.042940, 0.968881}}}},
    {"tritanopia",
     {{{1.255528, -0.076749, -0.178779},
       {-0.078411, 0.930809, 0.147602},
       {0.004733, 0.691367, 0.303900}}}},
};

double apart(const Vision& v, Method a, Method b) {
  return de2000(lab(times(v.m, lin(rgb(draw::method_color(a))))),
                lab(times(v.m, lin(rgb(draw::method_color(b))))));
}

std::vector<Method> built_in() {  // every compiled-in row, however many the table has
  std::vector<Method> out;
  for (const MethodInfo& m : built_in_methods()) out.push_back(m.id);
  return out;
}

TEST(Palette, CieDe2000MatchesSharmasPublishedPairs) {
  // Sharma, Wu and Dalal (2005), table 1: pairs 1, 7, 17 and 25.
  EXPECT_NEAR(de2000({50, 2.6772, -79.7751}, {50, 0, -82.7485}), 2.0425, 1e-4);
  EXPECT_NEAR(de2000({50, 0, 0}, {50, -1, 2}), 2.3669, 1e-4);
  EXPECT_NEAR(de2000({50, 2.5, 0}, {73, 25, -18}), 27.1492, 1e-4);
  EXPECT_NEAR(de2000({60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}), 1.2644, 1e-4);
  // And WCAG's ratio at its ends: white on black 21:1, a colour on itself 1:1.
  EXPECT_NEAR(contrast({1, 1, 1}, {0, 0, 0}), 21.0, 1e-12);
  EXPECT_NEAR(contrast({0.3, 0.6, 0.9}, {0.3, 0.6, 0.9}), 1.0, 1e-12);
}

// The five rows every shipped scene and most lessons compare (explicit and symplectic Euler,
// RK4, Verlet, implicit Euler) stay apart by at least 7.5 CIEDE2000 (a just-noticeable difference
// is about 1 to 2) under each simulated colour blindness, and 30 in normal vision (measured
// worst: symplectic against implicit Euler, 7.8 under protanopia).
TEST(Palette, TheLecturesMethodsStayApartUnderColourBlindness) {
  const Method five[] = {Method::Euler, Method::SymplecticEuler, Method::RK4, Method::Verlet,
                         Method::ImplicitEuler};
  for (const Vision& v : kVisions)
    for (std::size_t i = 0; i < std::size(five); ++i)
      for (std::size_t j = i + 1; j < std::size(five); ++j)
        EXPECT_GE(apart(v, five[i], five[j]), v.m[0][0] == 1 ? 30.0 : 7.5)
            << method_info(five[i]).name << " against " << method_info(five[j]).name << " under "
            << v.name;
}

// Every pair of lanes a lesson shows together (rows made from its tableaux too, made as the
// lesson makes them) stays apart by 7.5 under each; any two of the
// twelve built-in rows by at least 4 (twelve hues cannot all stay far apart for a dichromat:
// RK4 against XPBD under protanopia, 4.2), and every row has a mark of its own, so that no two
// lanes rest on colour alone.
TEST(Palette, LanesShownTogetherStayApartAndEachRowHasItsOwnMark) {
  const std::vector<Method> rows = built_in();
  std::set<draw::Mark> marks;
  for (Method m : rows) marks.insert(draw::method_mark(m));
  EXPECT_EQ(marks.size(), rows.size());
  EXPECT_EQ(marks.count(draw::Mark::None), 0u);
  for (const Vision& v : kVisions)
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (std::size_t j = i + 1; j < rows.size(); ++j)
        EXPECT_GE(apart(v, rows[i], rows[j]), 4.0)
            << method_info(rows[i]).name << " against " << method_info(rows[j]).name << " under "
            << v.name;

  int sets = 0;
  std::vector<fs::path>
      lessons;  // in the course's order (the tableaux' rows made as it makes them)
  for (const auto& file :
       fs::directory_iterator(fs::path(SPRINGLAB_SOURCE_DIR) / "assets" / "lessons"))
    if (file.path().extension() == ".json") lessons.push_back(file.path());
  std::sort(lessons.begin(), lessons.end());
  for (const fs::path& file : lessons) {
    const nlohmann::json lesson = nlohmann::json::parse(std::ifstream(file));
    for (const auto& step : lesson.at("steps")) {
      if (!step.contains("compare")) continue;
      std::vector<Method> lanes;
      // (The IK lesson's solvers are no methods: they take the first three lecture hues.)
      for (const auto& name : step["compare"])
        if (const auto m = app::lookup_method(name.get<std::string>())) lanes.push_back(*m);
      ++sets;
      for (const Vision& v : kVisions)
        for (std::size_t i = 0; i < lanes.size(); ++i)
          for (std::size_t j = i + 1; j < lanes.size(); ++j)
            EXPECT_GE(apart(v, lanes[i], lanes[j]), 7.5)
                << file.filename() << ": " << method_info(lanes[i]).name << " against "
                << method_info(lanes[j]).name << " under " << v.name;
    }
  }
  EXPECT_GE(sets, 5);
}

// Text at least 4.5:1 (WCAG 2.1, 1.4.3) on every golden frame, English and Chinese, desktop and
// browser: the panels, the charts, the lessons' captions. Measured on the pixels: a frame's
// surfaces are the colours that fill its flat areas (at least 1500 pixels, each amid eight of
// its own colour: the panels, buttons, fields, the charts' and the band's backgrounds); each
// colour the app writes text in (the theme's, the verdicts', the methods' for their names)
// is found where it is drawn whole (a glyph's core), beside a surface (within 2 pixels); the
// ratio of the two is its contrast there.
ImVec4 style_of(ImGuiCol c) {
  return ImGui::GetStyle().Colors[c];
}

TEST(Contrast, TextIsAtLeastFourAndAHalfToOneOnEveryGoldenFrame) {
  ImGui::CreateContext();
  ui::apply_theme(1.0f);
  const ImVec4* style = ImGui::GetStyle().Colors;
  std::vector<std::pair<std::string, draw::Rgba>> text = {
      {"text", {style[ImGuiCol_Text].x, style[ImGuiCol_Text].y, style[ImGuiCol_Text].z, 1}},
      {"quiet text",
       {style[ImGuiCol_TextDisabled].x, style[ImGuiCol_TextDisabled].y,
        style[ImGuiCol_TextDisabled].z, 1}},
      {"safe", ui::kSafeText},
      {"near", ui::kNearText},
      {"beyond", ui::kBeyondText},
      {"neutral", ui::kNeutralText}};
  ImGui::DestroyContext();
  for (Method m : built_in()) text.push_back({method_info(m).name, draw::method_color(m)});

  // Each text colour as drawn, and within one level a channel of it (the rasteriser's rounding).
  std::unordered_map<std::uint32_t, std::size_t> text_of;
  for (std::size_t k = 0; k < text.size(); ++k) {
    const Rgb t = rgb(text[k].second);
    for (int dr = -1; dr <= 1; ++dr)
      for (int dg = -1; dg <= 1; ++dg)
        for (int db = -1; db <= 1; ++db) {
          const auto level = [](double c, int d) {
            return static_cast<std::uint32_t>(std::clamp(std::lround(c * 255) + d, 0L, 255L));
          };
          text_of.emplace(level(t[0], dr) << 16 | level(t[1], dg) << 8 | level(t[2], db), k);
        }
  }
  struct Worst {
    double ratio = 1e9;
    std::string where;
  };
  std::map<std::string, Worst> worst;
  int frames = 0;
  // The theme's opaque fills, surfaces wherever they are drawn (a slider's grab is too small to
  // be a flat area, and its value is written across it).
  std::vector<std::uint32_t> fills;
  ImGui::CreateContext();
  ui::apply_theme(1.0f);
  for (ImGuiCol c :
       {ImGuiCol_FrameBg, ImGuiCol_Button, ImGuiCol_SliderGrab, ImGuiCol_PlotHistogram}) {
    const Rgb f = rgb({style_of(c).x, style_of(c).y, style_of(c).z, 1});
    fills.push_back(static_cast<std::uint32_t>(std::lround(f[0] * 255)) << 16 |
                    static_cast<std::uint32_t>(std::lround(f[1] * 255)) << 8 |
                    static_cast<std::uint32_t>(std::lround(f[2] * 255)));
  }
  ImGui::DestroyContext();
  for (const fs::path& dir : {fs::path(SPRINGLAB_SOURCE_DIR) / "tests/golden",
                              fs::path(SPRINGLAB_SOURCE_DIR) / "tests/web/golden"})
    for (const auto& file : fs::directory_iterator(dir)) {
      if (file.path().extension() != ".png") continue;
      const app::Image im = app::read_png(file.path());
      ++frames;
      const int W = im.width, H = im.height;
      const auto at = [&](int x, int y) {
        const std::uint8_t* p = im.rgba.data() + (static_cast<std::size_t>(y) * W + x) * 4;
        return static_cast<std::uint32_t>(p[0] << 16 | p[1] << 8 | p[2]);
      };
      // The surfaces: flat areas' colours.
      std::map<std::uint32_t, int> flat;
      for (int y = 1; y + 1 < H; ++y)
        for (int x = 1; x + 1 < W; ++x) {
          const std::uint32_t c = at(x, y);
          bool same = true;
          for (int dy = -1; dy <= 1 && same; ++dy)
            for (int dx = -1; dx <= 1 && same; ++dx) same = at(x + dx, y + dy) == c;
          if (same) ++flat[c];
        }
      std::set<std::uint32_t> surfaces(fills.begin(), fills.end());
      for (const auto& [c, n] : flat)
        if (n >= 1500) surfaces.insert(c);
      const auto unpack = [](std::uint32_t c) {
        return Rgb{(c >> 16 & 255) / 255.0, (c >> 8 & 255) / 255.0, (c & 255) / 255.0};
      };
      for (int y = 2; y + 2 < H; ++y)
        for (int x = 2; x + 2 < W; ++x) {
          const auto found = text_of.find(at(x, y));
          if (found == text_of.end()) continue;
          const auto& [name, colour] = text[found->second];
          for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) {
              const std::uint32_t s = at(x + dx, y + dy);
              if (!surfaces.count(s) || text_of.count(s)) continue;
              const double r = contrast(rgb(colour), unpack(s));
              Worst& w = worst[name];
              if (r < w.ratio) {
                char where[160];
                std::snprintf(where, sizeof where, "%s at (%d, %d) on #%06x",
                              file.path().filename().c_str(), x, y, s);
                w = {r, where};
              }
            }
        }
    }
  EXPECT_GE(frames, 60);
  for (const auto& [name, w] : worst) EXPECT_GE(w.ratio, 4.5) << name << ": " << w.where;
  // Every colour text is written in was found on a surface in some golden frame, so checked: a
  // colour never found would pass unchecked.
  for (const auto& [name, colour] : text)
    EXPECT_TRUE(worst.count(name)) << name << " was never found as text on a surface";
}

}  // namespace
}  // namespace springlab::test
