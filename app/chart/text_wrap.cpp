#include "chart/text_wrap.hpp"

#include <cfloat>
#include <string_view>

namespace springlab::ui {

namespace {

// Ideographs, kana, hangul, CJK punctuation and full-width forms: a line may break around them.
bool breaks_around(char32_t c) {
  return (c >= 0x2E80 && c <= 0x9FFF) || (c >= 0xAC00 && c <= 0xD7AF) || (c >= 0xF900 && c <= 0xFAFF) ||
         (c >= 0xFE30 && c <= 0xFE4F) || (c >= 0xFF00 && c <= 0xFFEF) || c >= 0x20000;
}

// Marks that close (never start a line) and that open (never end one).
constexpr std::u32string_view kClosing = U"，。、；：？！）」』】〉》〕］｝”’…‥～·・,.;:!?)]}%";
constexpr std::u32string_view kOpening = U"（「『【〈《〔［｛“‘([{";

// One UTF-8 character from s[i], advancing i (a malformed byte is taken as itself).
char32_t next_char(const std::string& s, std::size_t& i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b = byte(i);
  int extra = b >= 0xF0 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : 0;
  if (i + extra >= s.size()) extra = 0;
  char32_t c = extra == 0 ? b : b & (0x3F >> extra);
  for (int k = 1; k <= extra; ++k) c = (c << 6) | (byte(i + k) & 0x3F);
  i += 1 + extra;
  return c;
}

}  // namespace

bool may_break_between(char32_t before, char32_t after) {
  if (!breaks_around(before) && !breaks_around(after)) return false;  // inside a Latin word
  return kClosing.find(after) == std::u32string_view::npos && kOpening.find(before) == std::u32string_view::npos;
}

std::string wrap_text(const std::string& text, const ImFont* font, float size, float width) {
  const auto wide = [&](const std::string& line) {
    return font->CalcTextSizeA(size, FLT_MAX, 0.0f, line.data(), line.data() + line.size()).x > width;
  };
  std::string out, line, word;
  bool spaced = false;  // a space before `word`
  const auto place = [&] {  // the word on this line if it fits, else on the next
    if (word.empty()) return;
    const std::string joined = line + (spaced && !line.empty() ? " " : "") + word;
    if (!line.empty() && wide(joined)) {
      out += line + '\n';
      line = word;
    } else {
      line = joined;
    }
    word.clear();
  };
  char32_t last = 0;  // the character before, in this word
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t start = i;
    const char32_t c = next_char(text, i);
    if (c == ' ' || c == '\n') {
      place();
      spaced = true;
      last = 0;
      if (c == '\n') {
        out += line + '\n';
        line.clear();
      }
      continue;
    }
    if (!word.empty() && may_break_between(last, c)) {
      place();
      spaced = false;
    }
    word.append(text, start, i - start);
    last = c;
  }
  place();
  return out + line;
}

void text_wrapped(const std::string& text, ImVec4 color, float width) {
  if (width <= 0.0f) width = ImGui::GetContentRegionAvail().x;
  const std::string lines = wrap_text(text, ImGui::GetFont(), ImGui::GetFontSize(), width);
  if (color.w > 0.0f) ImGui::PushStyleColor(ImGuiCol_Text, color);
  ImGui::TextUnformatted(lines.c_str());
  if (color.w > 0.0f) ImGui::PopStyleColor();
}

void text_wrapped_disabled(const std::string& text, float width) {
  text_wrapped(text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled), width);
}

void same_line_if_fits(float width) {
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width <= right) ImGui::SameLine();
}

}  // namespace springlab::ui
