#include "chart/text_wrap.hpp"

#include <algorithm>
#include <cfloat>
#include <iterator>
#include <string_view>
#include <vector>

namespace springlab::ui {

namespace {

// Ideographs, kana, hangul, CJK punctuation and full-width forms: a line may break around them.
bool breaks_around(char32_t c) {
  return (c >= 0x2E80 && c <= 0x9FFF) || (c >= 0xAC00 && c <= 0xD7AF) ||
         (c >= 0xF900 && c <= 0xFAFF) || (c >= 0xFE30 && c <= 0xFE4F) ||
         (c >= 0xFF00 && c <= 0xFFEF) || c >= 0x20000;
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

// A number ("1.95", "-2e-05", "0.0667").
bool number(std::string_view w) {
  if (w.empty()) return false;
  bool digit = false;
  for (const char c : w) {
    if (c >= '0' && c <= '9')
      digit = true;
    else if (c != '.' && c != '-' && c != '+' && c != 'e')
      return false;
  }
  return digit;
}

// The spaces a line must not break at, made no-break spaces (U+00A0): either side of "=" and
// between a number and its unit ("t = 1.95 s" stays on one line).
std::string glued(const std::string& text) {
  static constexpr std::string_view kUnits[] = {
      "s", "ms", "m", "cm", "mm", "J", "N", "kg", "Hz", "rad/s", "m/s", "N/m", "%"};  // not shown
  std::vector<std::string_view> words;
  std::vector<char> after;  // the separator after each word (' ', '\n' or 0 at the end)
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i)
    if (i == text.size() || text[i] == ' ' || text[i] == '\n') {
      words.emplace_back(text.data() + start, i - start);
      after.push_back(i == text.size() ? 0 : text[i]);
      start = i + 1;
    }
  std::string out;
  for (std::size_t k = 0; k < words.size(); ++k) {
    out += words[k];
    if (!after[k]) break;
    const std::string_view next = k + 1 < words.size() ? words[k + 1] : std::string_view();
    const bool unit = number(words[k]) &&
                      std::find(std::begin(kUnits), std::end(kUnits), next) != std::end(kUnits);
    const bool keep = after[k] == ' ' && (words[k] == "=" || next == "=" || unit);
    out += keep ? "\u00a0" : std::string(1, after[k]);
  }
  return out;
}

}  // namespace

bool may_break_between(char32_t before, char32_t after) {
  if (!breaks_around(before) && !breaks_around(after)) return false;  // inside a Latin word
  return kClosing.find(after) == std::u32string_view::npos &&
         kOpening.find(before) == std::u32string_view::npos;
}

std::string wrap_text(const std::string& given, const ImFont* font, float size, float width) {
  const std::string text = glued(given);
  const auto wide = [&](const std::string& line) {
    return font->CalcTextSizeA(size, FLT_MAX, 0.0f, line.data(), line.data() + line.size()).x >
           width;
  };
  std::string out, line, word;
  bool spaced = false;  // a space before `word`
  // `part` on this line if it fits, else on the next.
  const auto put = [&](const std::string& part, bool space_before) {
    const std::string joined = line + (space_before && !line.empty() ? " " : "") + part;
    if (!line.empty() && wide(joined)) {
      out += line + '\n';
      line = part;
    } else {
      line = joined;
    }
  };
  const auto place = [&] {
    if (word.empty()) return;
    // A glued group wider than a line is broken at its no-break spaces after all.
    if (wide(word) && word.find("\u00a0") != std::string::npos) {
      std::size_t from = 0;
      for (std::size_t at = word.find("\u00a0");; at = word.find("\u00a0", from)) {
        put(word.substr(from, at == std::string::npos ? std::string::npos : at - from),
            from > 0 || spaced);
        if (at == std::string::npos) break;
        from = at + 2;
      }
    } else {
      put(word, spaced);
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
  // The no-break spaces back to spaces (the font need not have the glyph).
  std::string wrapped = out + line, plain;
  for (std::size_t i = 0; i < wrapped.size(); ++i) {
    if (wrapped.compare(i, 2, "\u00a0") == 0) {
      plain += ' ';
      ++i;
    } else {
      plain += wrapped[i];
    }
  }
  return plain;
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
  if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width <= right)
    ImGui::SameLine();
}

}  // namespace springlab::ui
