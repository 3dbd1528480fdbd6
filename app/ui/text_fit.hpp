// Text that does not fit its place, found in what Dear ImGui draws (its draw lists, not the
// pixels): a piece of text whose glyphs lie over another's, glyphs cut by the rectangle their
// widget clips them to, and text shortened with an ellipsis. `render --check-text` runs it on
// every frame it writes; the golden frames are checked with it in English and in Chinese.
#pragma once

#include <imgui.h>

#include <string>
#include <vector>

namespace springlab::ui {

// Glyphs drawn one after another on one line: a label, a number, a line of a paragraph.
struct TextRun {
  std::string text;            // UTF-8, its spaces where the pen moved on between glyphs
  ImVec4 box{0, 0, 0, 0};      // x0, y0, x1, y1: its glyphs' bounds
  std::vector<ImVec4> glyphs;  // whole, a glyph drawn cut on the CPU as it would be uncut
  bool cut = false;            // a glyph drawn cut on the CPU (its widget's own clip)
  ImVec4 clip{0, 0, 0, 0};     // the rectangle its widget clips it to
  int list = 0;                // its draw list's place in the draw data
};

// The glyph quads of every draw list, told from other shapes by their texture coordinates (each
// glyph's own corner of the font atlas, or a part of it: a glyph Dear ImGui cut to a widget's
// own clip on the CPU, a combo's preview or a clipped label), in drawing order, grouped into runs.
// A glyph wholly past such a clip is not drawn at all and leaves no trace: a preview cut between
// two glyphs cannot be seen here (widest_beside, ui/widgets.hpp, gives the combos their room).
std::vector<TextRun> text_runs(const ImDrawData& data, const ImFontAtlas& fonts);

// What the windows do to the text under and in them, from the current Dear ImGui context: where
// text may be cut at the top and bottom (the insides of the windows that scroll: a scrollbar
// shows there is more), and what each window hides (its rectangle, where its background is
// opaque, over the text of the draw lists drawn before its own).
struct Windows {
  std::vector<ImVec4> scrolling;
  struct Cover {
    ImVec4 rect;
    int list;  // its draw list's place in the draw data
  };
  std::vector<Cover> covers;
};
Windows windows_of(const ImDrawData& data);

// One sentence a fault: "'k_s (N/m)' overlaps '7.5e+03' at (120, 236)", "'4 Damping buys Eule'
// is cut at its right by its widget's edge (...)", "'(dots...' is shortened". Text hidden under a
// window is not seen, so not judged.
std::vector<std::string> text_faults(const std::vector<TextRun>& runs, const Windows& windows = {});

}  // namespace springlab::ui
