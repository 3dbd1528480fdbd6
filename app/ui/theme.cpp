#include "ui/theme.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "springlab/text.hpp"
#include "ui/panels.hpp"
#include "util/language.hpp"

namespace springlab::ui {

namespace {

// The characters of `base` (ImGui's ranges, 0 ended; may be null) and of the current catalog's
// strings that lie in [lo, hi], as ranges in `out` (pairs, 0 ended); null if there are none.
const ImWchar* clipped_ranges(const Catalog& catalog, const ImWchar* base, ImWchar lo, ImWchar hi,
                              std::vector<ImWchar>& out) {
  ImFontGlyphRangesBuilder builder;
  if (base) builder.AddRanges(base);
  for (const auto& [english, translated] : catalog.entries) builder.AddText(translated.c_str());
  ImVector<ImWchar> all;
  builder.BuildRanges(&all);
  out.clear();
  for (int k = 0; k + 1 < all.Size; k += 2) {
    const ImWchar from = std::max(all[k], lo), to = std::min(all[k + 1], hi);
    if (from <= to) out.insert(out.end(), {from, to});
  }
  if (out.empty()) return nullptr;
  out.push_back(0);
  return out.data();
}

// The glyphs a translation needs beyond DejaVu's: every character from U+2E80 on (CJK punctuation,
// ideographs, full-width forms) in the current catalog's strings. scripts/i18n/cjk_font.py keeps
// exactly these in the font, by the same rule.
const ImWchar* translation_glyphs() {
  static std::vector<ImWchar> ranges;
  const Catalog* catalog = current_catalog();
  return catalog ? clipped_ranges(*catalog, nullptr, 0x2E80, 0xFFFF, ranges) : nullptr;
}

// `base` and, with a catalog, every character below U+2E80 in its strings (a Latin, Greek or
// Cyrillic language's letters, which DejaVu Sans has).
const ImWchar* translated_letters(const ImWchar* base) {
  static std::vector<ImWchar> ranges;
  const Catalog* catalog = current_catalog();
  return catalog ? clipped_ranges(*catalog, base, 0x0001, 0x2E7F, ranges) : base;
}

}  // namespace

void apply_theme(float scale) {
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  const char* font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";  // not shown
  std::error_code ec;
  // Three sizes: the panels', presentation mode's (kPresentationScale larger) and the lesson
  // captions' (kCaptionScale), each drawn at its own size rather than stretched, so that it stays
  // sharp on a projector. The glyphs: Latin-1, Greek, punctuation, super- and subscripts, arrows
  // and math operators (core/src/loading/lesson.cpp lets a caption use exactly these).
  static const ImWchar base[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x205E, 0x2070,
                                 0x209F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};
  // With a translation, also the letters below U+2E80 its strings use.
  const ImWchar* glyphs = translated_letters(base);
  // In another language, its characters from the CJK font merged into each size (drawn at 1x: a
  // CJK glyph's strokes need no oversampling to stay sharp, and 2x would quadruple the atlas).
  const ImWchar* translated = translation_glyphs();
  const std::string cjk = translated ? app::cjk_font_path() : std::string();
  for (const float size : {1.0f, kPresentationScale, kCaptionScale}) {
    if (std::filesystem::exists(font, ec)) {
      ImFontConfig config;
      config.OversampleH = 2;
      config.OversampleV = 2;
      io.Fonts->AddFontFromFileTTF(font, kFontSize * scale * size, &config, glyphs);
      if (!cjk.empty()) {
        ImFontConfig merge;
        merge.MergeMode = true;
        merge.OversampleH = merge.OversampleV = 1;
        merge.PixelSnapH = true;
        // A tenth larger: an ideograph fills its em square, and at DejaVu's size it looks a size
        // smaller than the Latin letters beside it.
        io.Fonts->AddFontFromFileTTF(cjk.c_str(), 1.1f * kFontSize * scale * size, &merge,
                                     translated);
      }
    } else {
      ImFontConfig config;
      config.SizePixels =
          std::round(13.0f * scale * size);  // ProggyClean at a whole size stays crisp enough
      io.Fonts->AddFontDefault(&config);
    }
  }

  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 6.0f;
  style.FrameRounding = 4.0f;
  style.GrabRounding = 1.0f;
  style.WindowBorderSize = 1.0f;
  style.FramePadding = ImVec2(8, 4);
  style.ItemSpacing = ImVec2(10, 6);
  style.WindowPadding = ImVec2(12, 10);
  // A slider's grab a thin bar, not a block over the value written across it.
  style.GrabMinSize = 4.0f;
  ImVec4* c = style.Colors;
  // Near-white text on a near-black, slightly opaque background: readable from the back row.
  c[ImGuiCol_Text] = ImVec4(0.96f, 0.97f, 0.98f, 1.0f);
  c[ImGuiCol_TextDisabled] =
      ImVec4(0.70f, 0.73f, 0.77f, 1.0f);  // 4.5:1 on a field (tests/app/palette_test.cpp)
  c[ImGuiCol_WindowBg] = ImVec4(0.05f, 0.06f, 0.07f, 0.90f);
  c[ImGuiCol_PopupBg] = ImVec4(0.07f, 0.08f, 0.09f, 0.97f);
  c[ImGuiCol_Border] = ImVec4(0.45f, 0.48f, 0.53f, 0.60f);
  c[ImGuiCol_FrameBg] = ImVec4(0.16f, 0.18f, 0.21f, 1.0f);
  c[ImGuiCol_FrameBgHovered] = ImVec4(0.24f, 0.27f, 0.32f, 1.0f);
  c[ImGuiCol_FrameBgActive] = ImVec4(0.28f, 0.32f, 0.38f, 1.0f);
  c[ImGuiCol_TitleBg] = ImVec4(0.10f, 0.12f, 0.15f, 1.0f);
  c[ImGuiCol_TitleBgActive] = ImVec4(0.14f, 0.20f, 0.28f, 1.0f);
  // A slider's value is written across its grab: dark enough for the text on it (4.5:1).
  c[ImGuiCol_SliderGrab] = ImVec4(0.20f, 0.44f, 0.78f, 1.0f);
  c[ImGuiCol_SliderGrabActive] = ImVec4(0.18f, 0.43f, 0.80f, 1.0f);
  c[ImGuiCol_PlotHistogram] =
      ImVec4(0.13f, 0.45f, 0.25f, 1.0f);  // a progress bar, its count written on it
  c[ImGuiCol_Button] = ImVec4(0.20f, 0.36f, 0.55f, 1.0f);
  c[ImGuiCol_ButtonHovered] = ImVec4(0.28f, 0.46f, 0.68f, 1.0f);
  c[ImGuiCol_ButtonActive] = ImVec4(0.34f, 0.54f, 0.78f, 1.0f);
  c[ImGuiCol_CheckMark] = ImVec4(0.55f, 0.85f, 1.00f, 1.0f);
  c[ImGuiCol_Header] = ImVec4(0.20f, 0.36f, 0.55f, 0.8f);
  style.ScaleAllSizes(scale);
}

}  // namespace springlab::ui
