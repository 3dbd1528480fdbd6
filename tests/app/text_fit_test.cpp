// The text-fit check (ui/text_fit.hpp) on frames drawn here with Dear ImGui, no GL: it reads the
// text back from the draw lists, finds text over text, text cut by its widget (on the GPU by its
// clip, or on the CPU glyph by glyph) and text shortened,
// and says nothing of text that fits, of a row half in view in a window that scrolls, and of text
// hidden under a window drawn over it. Every golden frame is checked with it by
// TextFit.EveryGoldenFrameInBothLanguages (tests/golden/golden_test.cpp).
#include "ui/text_fit.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include <functional>
#include <string>
#include <vector>

#include "chart/text_wrap.hpp"
#include "ui/theme.hpp"

namespace springlab::test {
namespace {

// One frame of `draw` at 800 x 600: what the check says of it, and the text it read.
struct Checked {
  std::vector<std::string> faults;
  std::vector<std::string> texts;
};

Checked check(const std::function<void()>& draw) {
  ImGui::CreateContext();
  ui::apply_theme(1.0f);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  io.DisplaySize = ImVec2(800, 600);
  io.DeltaTime = 1.0f / 60.0f;
  Checked out;
  for (int pass = 0; pass < 2; ++pass) {  // (a window is measured on its first frame)
    ImGui::NewFrame();
    draw();
    ImGui::Render();
  }
  const std::vector<ui::TextRun> runs = ui::text_runs(*ImGui::GetDrawData(), *io.Fonts);
  for (const ui::TextRun& r : runs) out.texts.push_back(r.text);
  out.faults = ui::text_faults(runs, ui::windows_of(*ImGui::GetDrawData()));
  ImGui::DestroyContext();
  return out;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

bool has(const std::vector<std::string>& lines, const std::string& part) {
  for (const std::string& l : lines)
    if (l.find(part) != std::string::npos) return true;
  return false;
}

TEST(TextFit, ReadsTheTextBackFromTheDrawLists) {
  const Checked c = check([] {
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    dl->AddText(ImVec2(100, 100), IM_COL32_WHITE, "k_s (N/m)");
    dl->AddText(ImVec2(100, 200), IM_COL32_WHITE, "t = 1.500 s");
  });
  EXPECT_TRUE(has(c.texts, "k_s (N/m)")) << joined(c.texts);
  EXPECT_TRUE(has(c.texts, "t = 1.500 s")) << joined(c.texts);
  EXPECT_TRUE(c.faults.empty()) << joined(c.faults);
}

// The planted overlap: one label written over another, a little lower and to the right.
TEST(TextFit, FindsTextWrittenOverText) {
  const Checked c = check([] {
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    dl->AddText(ImVec2(100, 100), IM_COL32_WHITE, "symplectic-euler");
    dl->AddText(ImVec2(130, 106), IM_COL32_WHITE, "midpoint");
  });
  ASSERT_EQ(c.faults.size(), 1u) << joined(c.faults);
  EXPECT_TRUE(has(c.faults, "'symplectic-euler' overlaps 'midpoint'")) << joined(c.faults);
  // Side by side, a space apart, and one line under the other: nothing.
  const Checked apart = check([] {
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    dl->AddText(ImVec2(100, 100), IM_COL32_WHITE, "symplectic-euler");
    const float w = ImGui::CalcTextSize("symplectic-euler ").x;
    dl->AddText(ImVec2(100 + w, 100), IM_COL32_WHITE, "midpoint");
    dl->AddText(ImVec2(100, 100 + ImGui::GetTextLineHeight()), IM_COL32_WHITE, "rk4");
  });
  EXPECT_TRUE(apart.faults.empty()) << joined(apart.faults);
}

TEST(TextFit, FindsTextCutByItsWidget) {
  const Checked c = check([] {
    ImGui::SetNextWindowPos(ImVec2(10, 10));
    ImGui::SetNextWindowSize(ImVec2(150, 100));
    ImGui::Begin("narrow", nullptr, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
    ImGui::TextUnformatted("4  Damping buys Euler a limit");
    ImGui::End();
  });
  EXPECT_TRUE(has(c.faults, "is cut at its right")) << joined(c.faults);
}

// A glyph Dear ImGui cuts on the CPU to a widget's own clip (a combo's preview, AddText with a
// clip rectangle) keeps only part of its corner of the atlas: it is read back all the same and
// said cut. Both ways: the clip through the middle of a glyph is found; a clip past the text's end,
// none; a clip exactly between two glyphs drops the second whole and leaves no trace (said in
// text_fit.hpp), so it is not found.
TEST(TextFit, FindsAGlyphCutOnTheCpu) {
  const char* text = "Heun, one entry wrong";
  const auto clipped_at = [text](float right) {
    return check([text, right] {
      const ImVec4 clip(100, 100, right, 140);
      ImGui::GetForegroundDrawList()->AddText(ImGui::GetFont(), ImGui::GetFontSize(),
                                              ImVec2(100, 110), IM_COL32_WHITE, text, nullptr, 0.0f,
                                              &clip);
    });
  };
  // Where the pen stands before the 'g', and the ink of the 'n' before it and of the 'g'.
  float pen = 0, n_ink_end = 0, g_ink_start = 0, g_ink_end = 0;
  check([&] {
    const ImFont* font = ImGui::GetFont();
    pen = 100 + ImGui::CalcTextSize("Heun, one entry wron").x;
    const ImFontGlyph* n = font->FindGlyph('n');
    const ImFontGlyph* g = font->FindGlyph('g');
    n_ink_end = pen - n->AdvanceX + n->X1;
    g_ink_start = pen + g->X0;
    g_ink_end = pen + g->X1;
  });
  const Checked cut = clipped_at(0.5f * (g_ink_start + g_ink_end));
  EXPECT_TRUE(has(cut.faults, "'Heun, one entry wrong' is cut by its widget's own edge"))
      << joined(cut.faults) << joined(cut.texts);
  const Checked fits = clipped_at(g_ink_end + 20);
  EXPECT_TRUE(fits.faults.empty()) << joined(fits.faults);
  EXPECT_TRUE(has(fits.texts, text)) << joined(fits.texts);
  if (n_ink_end < g_ink_start - 0.5f) {  // (a gap between the two: the 'g' dropped whole)
    const Checked between = clipped_at(0.5f * (n_ink_end + g_ink_start));
    EXPECT_TRUE(between.faults.empty()) << joined(between.faults);
    EXPECT_TRUE(has(between.texts, "Heun, one entry wron")) << joined(between.texts);
  }
}

TEST(TextFit, FindsTextShortenedWithAnEllipsis) {
  const Checked c = check([] {
    ImGui::GetForegroundDrawList()->AddText(ImVec2(50, 50), IM_COL32_WHITE,
                                            "Stability region (dots\u2026");
  });
  EXPECT_TRUE(has(c.faults, "is shortened")) << joined(c.faults);
}

// A window that scrolls shows its last row half: that is scrolling, not a fault. Without the
// scrollbar, the same cut row is one.
TEST(TextFit, ARowHalfInViewInAWindowThatScrollsIsNoFault) {
  const auto rows = [](ImGuiWindowFlags flags) {
    return [flags] {
      ImGui::SetNextWindowPos(ImVec2(10, 10));
      ImGui::SetNextWindowSize(ImVec2(
          300, ImGui::GetStyle().WindowPadding.y + 5.5f * ImGui::GetTextLineHeightWithSpacing()));
      ImGui::Begin("rows", nullptr, ImGuiWindowFlags_NoTitleBar | flags);
      for (int k = 0; k < 20; ++k) ImGui::Text("row %d", k);
      ImGui::End();
    };
  };
  const Checked scrolls = check(rows(0));
  EXPECT_TRUE(scrolls.faults.empty()) << joined(scrolls.faults);
  const Checked fixed = check(rows(ImGuiWindowFlags_NoScrollbar));
  EXPECT_TRUE(has(fixed.faults, "is cut at its bottom"))
      << joined(fixed.faults) << joined(fixed.texts);
}

// Text under a window drawn over it is not seen: its overlap with the window's own is not judged.
TEST(TextFit, TextHiddenUnderAWindowIsNotJudged) {
  const Checked c = check([] {
    ImGui::GetBackgroundDrawList()->AddText(ImVec2(40, 40), IM_COL32_WHITE,
                                            "Midpoint went unstable at t = 1.2 s");
    ImGui::SetNextWindowPos(ImVec2(20, 20));
    ImGui::SetNextWindowSize(ImVec2(400, 200));
    ImGui::SetNextWindowBgAlpha(1.0f);
    ImGui::Begin("Stability region (G)");
    ImGui::TextUnformatted("a chart");
    ImGui::End();
  });
  EXPECT_TRUE(c.faults.empty()) << joined(c.faults);
  // The same label over the window (the foreground): it is.
  const Checked over = check([] {
    ImGui::GetForegroundDrawList()->AddText(ImVec2(40, 25), IM_COL32_WHITE,
                                            "Midpoint went unstable at t = 1.2 s");
    ImGui::SetNextWindowPos(ImVec2(20, 20));
    ImGui::SetNextWindowSize(ImVec2(400, 200));
    ImGui::Begin("Stability region (G)");
    ImGui::End();
  });
  EXPECT_TRUE(has(over.faults, "overlaps")) << joined(over.faults);
}

// Wrapping keeps a quantity whole: "t = 0.0667 s" is never broken across lines where a line can
// hold it (in a narrower one it breaks at its spaces after all, rather than run past the edge).
TEST(TextFit, WrappingKeepsAQuantityOnOneLine) {
  ImGui::CreateContext();
  ui::apply_theme(1.0f);
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  const ImFont* f = ImGui::GetIO().Fonts->Fonts[0];
  const std::string text = "Symplectic Euler diverged at t = 0.0667 s";
  const float group = f->CalcTextSizeA(f->FontSize, FLT_MAX, 0.0f, "t = 0.0667 s").x;
  for (float width = group; width < 400; width += 7) {
    const std::string wrapped = ui::wrap_text(text, f, f->FontSize, width);
    EXPECT_NE(wrapped.find("t = 0.0667 s"), std::string::npos) << width << ": " << wrapped;
  }
  ImGui::DestroyContext();
}

}  // namespace
}  // namespace springlab::test
