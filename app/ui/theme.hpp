// Dear ImGui set up for a classroom: a high-contrast dark theme, a large TrueType font
// (DejaVu Sans from Debian's fonts-dejavu-core, or ImGui's own font scaled cleanly when it is
// missing), everything scaled by one factor (--ui-scale, or the monitor's content scale).
#pragma once

namespace springlab::ui {

// Call after ImGui::CreateContext() and before the renderer backend builds the font atlas.
void apply_theme(float scale);

// The font's pixel size at scale 1.
inline constexpr float kFontSize = 17.0f;

// The fonts, in ImGui's atlas order: the panels', presentation mode's, the lesson captions'.
enum FontIndex { kPanelFont = 0, kPresentationFont = 1, kCaptionFont = 2 };
inline constexpr float kCaptionScale = 1.5f;

}  // namespace springlab::ui
