// Dear ImGui set up for a classroom: a high-contrast dark theme, a large TrueType font
// (DejaVu Sans from Debian's fonts-dejavu-core, or ImGui's own font scaled cleanly when it is
// missing), everything scaled by one factor (--ui-scale, or the monitor's content scale).
#pragma once

#include <imgui.h>

#include "draw/frame.hpp"

namespace springlab::ui {

// Call after ImGui::CreateContext() and before the renderer backend builds the font atlas.
void apply_theme(float scale);

// The font's pixel size at scale 1.
inline constexpr float kFontSize = 17.0f;

// The fonts, in ImGui's atlas order: the panels', presentation mode's, the lesson captions'.
enum FontIndex { kPanelFont = 0, kPresentationFont = 1, kCaptionFont = 2 };
inline constexpr float kCaptionScale = 1.5f;

// The verdicts' colours, as text on the panels (the gauge, a lesson's hints, the help's keys):
// safe, near the limit, beyond it, and neutral; each at least 4.5:1 on the panels as rendered
// (tests/app/palette_test.cpp).
inline constexpr draw::Rgba kSafeText{0.35f, 0.85f, 0.45f, 1}, kNearText{1.0f, 0.75f, 0.2f, 1},
    kBeyondText{1.0f, 0.36f, 0.32f, 1}, kNeutralText{0.55f, 0.75f, 1.0f, 1};

// A colour as ImGui takes it.
inline ImVec4 v4(const draw::Rgba& c) {
  return ImVec4(c.r, c.g, c.b, c.a);
}

}  // namespace springlab::ui
