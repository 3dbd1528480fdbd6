#include "ui/text_wrap.hpp"

#include <cfloat>

namespace springlab::ui {

std::string wrap_at_spaces(const std::string& text, const ImFont* font, float size, float width) {
  const auto wide = [&](const std::string& line) {
    return font->CalcTextSizeA(size, FLT_MAX, 0.0f, line.data(), line.data() + line.size()).x > width;
  };
  std::string out, line, word;
  const auto place = [&] {  // the word on this line if it fits, else on the next
    if (word.empty()) return;
    if (!line.empty() && wide(line + ' ' + word)) {
      out += line + '\n';
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    word.clear();
  };
  for (const char c : text) {
    if (c == ' ' || c == '\n') {
      place();
      if (c == '\n') {
        out += line + '\n';
        line.clear();
      }
    } else {
      word += c;
    }
  }
  place();
  return out + line;
}

void text_wrapped(const std::string& text, ImVec4 color, float width) {
  if (width <= 0.0f) width = ImGui::GetContentRegionAvail().x;
  const std::string lines = wrap_at_spaces(text, ImGui::GetFont(), ImGui::GetFontSize(), width);
  if (color.w > 0.0f) ImGui::PushStyleColor(ImGuiCol_Text, color);
  ImGui::TextUnformatted(lines.c_str());
  if (color.w > 0.0f) ImGui::PopStyleColor();
}

void text_wrapped_disabled(const std::string& text, float width) {
  text_wrapped(text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled), width);
}

}  // namespace springlab::ui
