// Every shipped lesson's text fits the band it is drawn in at 1280 x 720 (ui/lesson_band.hpp):
// the caption in two lines of its own font, the prompt on one line, the title row beside its
// buttons; measured with Dear ImGui's own text layout and the app's fonts (no GL needed).
#include "ui/lesson_band.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>
#include <cfloat>

#include "chart/text_wrap.hpp"
#include "lesson/lesson_library.hpp"
#include "springlab/text.hpp"
#include "ui/theme.hpp"
#include "util/language.hpp"

namespace springlab::test {
namespace {

struct Fonts {
  Fonts() {
    ImGui::CreateContext();
    ui::apply_theme(1.0f);
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // builds the atlas
  }
  ~Fonts() { ImGui::DestroyContext(); }
  // Lines `text` takes in `font` wrapped at `width` pixels, as the band wraps it.
  static int lines(int font, const std::string& text, float width) {
    ImFont* f = ImGui::GetIO().Fonts->Fonts[font];
    const std::string wrapped = ui::wrap_text(text, f, f->FontSize, width);
    for (std::size_t a = 0, b = 0; a <= wrapped.size(); a = b + 1) {  // and each line fits
      b = std::min(wrapped.find('\n', a), wrapped.size());
      const float w =
          f->CalcTextSizeA(f->FontSize, FLT_MAX, 0.0f, wrapped.data() + a, wrapped.data() + b).x;
      EXPECT_LE(w, width) << wrapped.substr(a, b - a);
    }
    return 1 + static_cast<int>(std::count(wrapped.begin(), wrapped.end(), '\n'));
  }
};

// Breaks fall only at spaces, every one where the next word would pass the width: a number stays
// whole ("0.973": Dear ImGui's own wrap breaks after a full stop), and so does an equation's
// side with its "=" ("(hω)²) = 0.973." where a line holds it: the next "word" is then that group).
TEST(LessonBand, WrapsOnlyAtSpacesAndAsLateAsItCan) {
  Fonts fonts;
  ImFont* f = ImGui::GetIO().Fonts->Fonts[ui::kCaptionFont];
  const auto width = [&](const std::string& s) {
    return f->CalcTextSizeA(f->FontSize, FLT_MAX, 0.0f, s.c_str()).x;
  };
  const std::string text = "its energy by 1 / (1 + (h\u03c9)\u00b2) = 0.973. Stable, but not true.";
  for (float w = width("(h\u03c9)\u00b2)"); w < width(text) + 10.0f; w += 7.0f) {
    const std::string wrapped = ui::wrap_text(text, f, f->FontSize, w);
    std::string joined = wrapped;
    std::replace(joined.begin(), joined.end(), '\n', ' ');
    ASSERT_EQ(joined, text) << w;  // only spaces became breaks
    for (std::size_t a = 0, b = 0; b < wrapped.size(); a = b + 1) {
      b = std::min(wrapped.find('\n', a), wrapped.size());
      if (b == wrapped.size()) break;
      std::size_t next = std::min(wrapped.find_first_of(" \n", b + 1), wrapped.size());
      // (Glued to the next two words by an "=" after it, where the three fit a line.)
      if (wrapped.compare(next, 3, " = ") == 0) {
        const std::size_t group = std::min(wrapped.find_first_of(" \n", next + 3), wrapped.size());
        if (width(wrapped.substr(b + 1, group - b - 1)) <= w) next = group;
      }
      EXPECT_GT(width(wrapped.substr(a, b - a) + " " + wrapped.substr(b + 1, next - b - 1)), w)
          << wrapped;
    }
  }
  EXPECT_EQ(ui::wrap_text("one\ntwo", f, f->FontSize, 1000.0f), "one\ntwo");
}

TEST(LessonBand, EveryShippedLessonsTextFitsAt1280x720) {
  Fonts fonts;
  ASSERT_GT(ImGui::GetIO().Fonts->Fonts.Size, ui::kCaptionFont);
  const float inner = 1280.0f - 2 * 12.0f;  // the band's padding
  // (The measure itself: kMaxCaption characters of ordinary words do not fit one line, twice as
  // many do not fit two.)
  std::string words;
  while (words.size() < static_cast<std::size_t>(kMaxCaption)) words += "spring ";
  EXPECT_EQ(Fonts::lines(ui::kCaptionFont, words, inner), 2);
  EXPECT_GE(Fonts::lines(ui::kCaptionFont, words + words, inner), 3);
  const auto files = app::shipped_lesson_files();
  ASSERT_GE(files.size(), 10u);
  for (const std::string& file : files) {
    const Lesson lesson = app::open_lesson(file);
    for (const LessonStep& step : lesson.steps) {
      EXPECT_LE(Fonts::lines(ui::kCaptionFont, step.caption, inner), 2)
          << lesson.name << ": " << step.caption;
      if (!step.prompt.empty()) {
        EXPECT_EQ(Fonts::lines(ui::kPanelFont, "Try this: " + step.prompt, inner), 1)
            << lesson.name << ": " << step.prompt;
      }
      // The title row leaves room for its three buttons (about 300 pixels).
      const std::string row =
          "Lesson 10 of 10  \u00b7  " + lesson.title + "   \u2014   step 1 of 2: " + step.title;
      EXPECT_EQ(Fonts::lines(ui::kPanelFont, row, inner - 300.0f), 1) << lesson.name << ": " << row;
    }
  }
}

// The app in Simplified Chinese for the rest of a test (the fonts made after it carry its glyphs).
struct Chinese {
  Chinese() { app::use_language("zh-CN"); }
  ~Chinese() { app::use_language("en"); }
};

// Every character of every translation has a glyph in each of the app's fonts: no tofu, no "?".
TEST(LessonBand, EveryTranslatedCharacterHasAGlyph) {
  Chinese chinese;
  Fonts fonts;
  const Catalog* catalog = current_catalog();
  ASSERT_NE(catalog, nullptr);
  ASSERT_GT(catalog->entries.size(), 300u);
  int checked = 0;
  for (const auto& [english, translated] : catalog->entries) {
    ImVector<ImWchar> chars;
    ImFontGlyphRangesBuilder one;
    one.AddText(translated.c_str());
    one.BuildRanges(&chars);
    for (int k = 0; k + 1 < chars.Size; k += 2)
      for (int c = chars[k]; c <= chars[k + 1]; ++c) {
        if (c == '\n') continue;
        for (int font = 0; font < ImGui::GetIO().Fonts->Fonts.Size; ++font)
          EXPECT_NE(ImGui::GetIO().Fonts->Fonts[font]->FindGlyphNoFallback(static_cast<ImWchar>(c)),
                    nullptr)
              << "U+" << std::hex << c << " in \"" << translated << "\"";
        ++checked;
      }
  }
  EXPECT_GT(checked, 2000);
}

// Switching the language (the View panel's menu) remakes the fonts: with Chinese's glyphs, then
// without them again (English's atlas as it was).
TEST(LessonBand, SwitchingTheLanguageRemakesTheFontsWithItsGlyphs) {
  const auto atlas = [] {
    ImGui::CreateContext();
    ui::apply_theme(1.0f);
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    const bool chinese =
        ImGui::GetIO().Fonts->Fonts[0]->FindGlyphNoFallback(0x80fd) != nullptr;  // 能
    const int area = w * h;
    ImGui::DestroyContext();
    return std::make_pair(chinese, area);
  };
  const auto english = atlas();
  EXPECT_FALSE(english.first);
  app::use_language("zh-CN");
  const auto chinese = atlas();
  EXPECT_TRUE(chinese.first);
  EXPECT_GT(chinese.second, english.second);
  app::use_language("en");
  EXPECT_EQ(atlas(), english);
}

// Chinese has no spaces: a line breaks between two ideographs, as late as it can, but never
// before a closing mark (，。）...) nor after an opening one (（“...), and a Latin word or number
// inside stays whole.
TEST(LessonBand, ChineseBreaksBetweenIdeographsNeverBeforeAClosingMark) {
  Chinese chinese;
  Fonts fonts;
  EXPECT_TRUE(ui::may_break_between(U'能', U'量'));   // 能|量
  EXPECT_FALSE(ui::may_break_between(U'量', U'，'));  // 量|，
  EXPECT_FALSE(ui::may_break_between(U'量', U'。'));  // 量|。
  EXPECT_FALSE(ui::may_break_between(U'（', U'阶'));  // （|阶
  EXPECT_FALSE(ui::may_break_between(U'“', U'对'));   // “|对
  EXPECT_TRUE(ui::may_break_between(U'。', U'半'));   // 。|半
  EXPECT_FALSE(ui::may_break_between(U'1', U'2'));    // a number
  EXPECT_FALSE(ui::may_break_between(U'e', U'r'));    // a word
  ImFont* f = ImGui::GetIO().Fonts->Fonts[ui::kCaptionFont];
  const auto width = [&](const std::string& s) {
    return f->CalcTextSizeA(f->FontSize, FLT_MAX, 0.0f, s.c_str()).x;
  };
  // Lesson 3's caption, in its translation: ideographs, full-width marks, a formula with spaces.
  const std::string text =
      tr("Explicit Euler uses the old velocity and the old force: each step multiplies the energy "
         "by 1 + (h\u03c9)\u00b2 "
         "= 1.028. Symplectic Euler's stays level.");
  ASSERT_NE(text.find("\u663e\u5f0f\u6b27\u62c9"), std::string::npos);  // 显式欧拉: translated
  const std::u32string closing = U"\uff0c\u3002\u3001\uff1b\uff1a\uff1f\uff01\uff09",
                       opening = U"\uff08\u201c";
  const auto first_char = [](const std::string& line) {  // the line's first code point
    char32_t c = static_cast<unsigned char>(line[0]);
    if (c >= 0xE0) c = ((c & 0x0F) << 12) | ((line[1] & 0x3F) << 6) | (line[2] & 0x3F);
    return c;
  };
  int wrapped_lines = 0;
  for (float w = width("1.028\u3002"); w < width(text) + 10.0f; w += 9.0f) {
    const std::string wrapped = ui::wrap_text(text, f, f->FontSize, w);
    std::string joined;  // a break at a space took the space; one between ideographs took nothing
    for (std::size_t a = 0, b = 0; a <= wrapped.size(); a = b + 1) {
      b = std::min(wrapped.find('\n', a), wrapped.size());
      const std::string line = wrapped.substr(a, b - a);
      ASSERT_FALSE(line.empty()) << wrapped;
      EXPECT_LE(width(line), w) << line;
      if (a > 0) {
        EXPECT_EQ(closing.find(first_char(line)), std::u32string::npos)
            << "a line starts with a closing mark: " << line;
        ++wrapped_lines;
      }
      if (!joined.empty() && text.compare(joined.size(), 1, " ") == 0) joined += ' ';
      joined += line;
    }
    EXPECT_EQ(joined, text) << w;
    for (const char32_t c : opening) {  // no line ends with an opening mark
      std::string mark;
      mark += static_cast<char>(0xE0 | (c >> 12));
      mark += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      mark += static_cast<char>(0x80 | (c & 0x3F));
      EXPECT_EQ(wrapped.find(mark + "\n"), std::string::npos) << wrapped;
    }
    EXPECT_NE(wrapped.find("1.028"), std::string::npos) << wrapped;  // the number whole
  }
  EXPECT_GT(wrapped_lines, 20);
}

// Every lesson in Chinese fits the band at 1280 x 720 as in English: the caption in two lines,
// the prompt on one, the title row beside its buttons.
TEST(LessonBand, EveryShippedLessonsTextInChineseFitsAt1280x720) {
  Chinese chinese;
  Fonts fonts;
  const float inner = 1280.0f - 2 * 12.0f;
  for (const std::string& file : app::shipped_lesson_files()) {
    const Lesson lesson = app::open_lesson(file);
    for (const LessonStep& step : lesson.steps) {
      const std::string caption = tr(step.caption);
      EXPECT_NE(caption, step.caption) << "not translated: " << step.caption;
      EXPECT_LE(Fonts::lines(ui::kCaptionFont, caption, inner), 2)
          << lesson.name << ": " << caption;
      if (!step.prompt.empty()) {
        const std::string prompt = format_text(tr("Try this: %s"), tr(step.prompt).c_str());
        EXPECT_NE(tr(step.prompt), step.prompt) << "not translated: " << step.prompt;
        EXPECT_EQ(Fonts::lines(ui::kPanelFont, prompt, inner), 1) << lesson.name << ": " << prompt;
      }
      const std::string row = format_text(tr("Lesson %d of %d"), 10, 12) + "  \u00b7  " +
                              tr(lesson.title) + "   \u2014   " +
                              format_text(tr("step %d of %d: %s"), 1, 2, tr(step.title).c_str());
      EXPECT_EQ(Fonts::lines(ui::kPanelFont, row, inner - 300.0f), 1) << lesson.name << ": " << row;
    }
  }
}

// A narrow window (a laptop's browser) wraps a caption onto more lines: the band grows to hold
// them all, and never shrinks below two, so the scene keeps its place from step to step.
TEST(LessonBand, GrowsWithItsCaptionInANarrowWindow) {
  Fonts fonts;
  ui::LessonBand band;
  band.caption =
      "Its springs' k_s = 380000 N/m at h = 1/60 s: h\u03c9_max is about 90, far past every "
      "explicit "
      "method's limit. Explicit lanes explode; implicit Euler holds.";
  EXPECT_EQ(ui::lesson_band_height(band, 1280.0f, 1.0f), ui::lesson_band_height(1.0f, 2));
  band.title = "Implicit Euler on a stiff chain";
  band.step_title = "One step a frame";
  band.durations = {6.0, 6.0};
  band.number = 7;
  band.count = 12;
  // The title row: beside its buttons at 1280 units; narrower, the buttons take a row of their
  // own above it, and on a phone (390) the title wraps onto two.
  EXPECT_EQ(ui::lesson_band_height(band, 1280.0f, 1.0f), ui::lesson_band_height(1.0f, 2, 1));
  for (const auto& [width, title_rows] :
       std::vector<std::pair<float, int>>{{760.0f, 2}, {600.0f, 2}, {390.0f, 3}}) {
    // (On a phone, under 600 units, the caption is in the panels' font: the scene keeps its room.)
    const bool narrow = width < 600.0f;
    const int lines =
        Fonts::lines(narrow ? ui::kPanelFont : ui::kCaptionFont, band.caption, width - 2 * 12.0f);
    EXPECT_GT(lines, 2) << width;
    EXPECT_EQ(ui::lesson_band_height(band, width, 1.0f),
              ui::lesson_band_height(1.0f, lines, title_rows, 1, narrow))
        << width;
  }
  EXPECT_GT(ui::lesson_band_height(1.0f, 3), ui::lesson_band_height(1.0f, 2));
  band.caption = "Short.";
  EXPECT_EQ(ui::lesson_band_height(band, 1280.0f, 1.0f), ui::lesson_band_height(1.0f, 2));
}

// The band's own arithmetic: its height holds the rows it lays out, at any scale.
TEST(LessonBand, HeightGrowsWithTheScale) {
  EXPECT_NEAR(ui::lesson_band_height(2.0f), 2.0f * ui::lesson_band_height(1.0f), 1e-3f);
  EXPECT_GT(ui::lesson_band_height(1.0f),
            2 * ui::kFontSize * ui::kCaptionScale + 2 * ui::kFontSize);
}

}  // namespace
}  // namespace springlab::test
