// Every control fits its panel on a phone: drawn headlessly with Dear ImGui at 390 and 540 pixels
// wide (a phone upright; a small tablet upright), in English and in Chinese, every vertex that a
// panel's widgets draw lies inside that panel and inside the screen, across. A window's rectangle
// on screen is not enough: a control cut off inside its window (the strip's combo once was) drew
// past its window's edge, which this sees. (Vertically a panel scrolls; the charts, which clip
// their own lines, are left out.)
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <string>

#include "session/session.hpp"
#include "support.hpp"
#include "ui/panels.hpp"
#include "ui/theme.hpp"
#include "util/language.hpp"

namespace springlab::test {
namespace {

struct Overflow {
  std::string window;
  float x = 0.0f, left = 0.0f, right = 0.0f;
};

// Draws the panels of `session` for a width x height screen, scrolled page by page through every
// scrolling panel (Dear ImGui draws only what is in view), and returns the first vertex drawn past
// its window's left or right edge or the screen's, if any.
std::optional<Overflow> first_overflow(app::Session& session, ui::UiState& ui, int width,
                                       int height) {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  io.DeltaTime = 1.0f / 60.0f;
  const auto frame = [&] {
    ImGui::NewFrame();
    ui::draw_panels(session, ui, ui::FrameStats{}, width, height);
    ImGui::Render();
  };
  for (int k = 0; k < 3; ++k) frame();  // (windows settle their sizes over frames)
  bool more = true;
  for (int page = 0; more && page < 40; ++page) {
    for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows) {
      if (!w->WasActive || w->Hidden || std::string(w->Name) == "Charts" ||
          std::string(w->Name).rfind("Debug##", 0) == 0)
        continue;
      const float left = std::max(w->Pos.x, 0.0f) - 1.0f,
                  right = std::min(w->Pos.x + w->Size.x, float(width)) + 1.0f;
      for (const ImDrawVert& v : w->DrawList->VtxBuffer)
        if (v.pos.x < left || v.pos.x > right) return Overflow{w->Name, v.pos.x, left, right};
    }
    more = false;
    for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
      if (w->WasActive && !w->Hidden && w->ScrollMax.y > 0.0f && w->Scroll.y < w->ScrollMax.y) {
        ImGui::SetScrollY(w, w->Scroll.y + 0.75f * w->Size.y);
        more = true;
      }
    if (more) frame(), frame();
  }
  return std::nullopt;
}

class NarrowScreens : public ::testing::TestWithParam<std::string> {};

TEST_P(NarrowScreens, EveryControlFitsItsPanel) {
  app::use_language(GetParam());
  ImGui::CreateContext();
  ui::apply_theme(1.0f);
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  // One lane (the strip shows the method's combo), then the busiest panel: four lanes (the
  // longest names), each with its gauge and verdict.
  Scene scene = shipped("cloth");
  const SimulationSettings settings = settings_for(scene);
  app::Session session(std::move(scene), settings, 60.0);
  for (const bool compare : {false, true}) {
    if (compare)
      session.set_compare_rows(test::method_rows(
          {Method::ImplicitEuler, Method::XPBD, Method::LocalGlobal, Method::VBD}));
    for (int k = 0; k < 3; ++k) session.advance_frame();
    for (const auto& [width, height] : {std::pair{390, 844}, std::pair{540, 960}}) {
      for (const bool open : {false, true}) {
        ui::UiState ui;
        ui.scene_name = "cloth";
        ui.sheet_open = open;  // the sheet's one row, then all of it
        ui.ranges = ui::Ranges::of(session);
        const auto overflow = first_overflow(session, ui, width, height);
        EXPECT_FALSE(overflow) << GetParam() << " at " << width << " x " << height
                               << (open ? ", sheet open" : "") << ": window '" << overflow->window
                               << "' draws at x = " << overflow->x << ", outside ["
                               << overflow->left << ", " << overflow->right << "]"
                               << (compare ? " (four lanes)" : "");
      }
    }
  }
  ImGui::DestroyContext();
  app::use_language("en");
}

INSTANTIATE_TEST_SUITE_P(Languages, NarrowScreens, ::testing::Values("en", "zh-CN"),
                         [](const auto& info) {
                           return info.param == "en" ? std::string("English")
                                                     : std::string("Chinese");
                         });

}  // namespace
}  // namespace springlab::test
