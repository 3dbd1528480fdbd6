// Text wrapped where a reader expects a line to break. In Latin text, at spaces only: Dear
// ImGui's own wrap (1.86) also breaks after punctuation, so it splits numbers ("its mode: 504." on
// one line and "7 rad/s" on the next). In Chinese, which has no spaces, between any two ideographs
// too, but never before a closing mark (，。、；：？！）」 and the like) nor after an opening one
// (（「“ ...): the rules of line breaking for CJK text (kinsoku, UAX #14's classes CL, OP, ID).
#pragma once

#include <imgui.h>

#include <string>

namespace springlab::ui {

// `text` with a line break wherever the next word would pass `width` pixels in `font` at `size`
// (a word wider than `width` gets a line of its own); its own line breaks kept, runs of spaces
// made one. A "word" is a run of text between spaces, or one ideograph with the marks bound to it.
std::string wrap_text(const std::string& text, const ImFont* font, float size, float width);

// Whether a line may break between two characters with no space between them (code points).
bool may_break_between(char32_t before, char32_t after);

// Draws `text` in the current font, wrapped to `width` pixels (0: to the window's edge), in
// `color` (the style's text colour when its alpha is 0).
void text_wrapped(const std::string& text, ImVec4 color = ImVec4(0, 0, 0, 0), float width = 0.0f);

// The same in the style's disabled colour: a note, an explanation.
void text_wrapped_disabled(const std::string& text, float width = 0.0f);

// Widgets wrapped as words are: ImGui::SameLine() where the next item, `width` pixels wide, still
// fits the window's row after the last one, else nothing (it starts a new row).
void same_line_if_fits(float width);

}  // namespace springlab::ui
