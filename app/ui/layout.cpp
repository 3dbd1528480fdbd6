#include "ui/layout.hpp"

#include <algorithm>
#include <cmath>

#include "ui/panels.hpp"

namespace springlab::ui {

namespace {
// At scale 1: the gap between panels, Wide's left panel and charts (1280 x 720 holds them with
// nothing cut off), the touch layouts' row (a 44-unit frame and its padding) and Side's panel.
constexpr float kPad = 8.0f, kLeftWidth = 360.0f, kChartHeight = 230.0f, kRow = 60.0f,
                kSideWidth = 330.0f, kStrip = 64.0f;
}  // namespace

LayoutKind layout_kind(float w, float h) {
  if (h < 500.0f && w > h) return LayoutKind::Side;
  if (h > w && w < 900.0f) return LayoutKind::Upright;
  if (w < 1200.0f || h < 700.0f) return LayoutKind::Compact;
  return LayoutKind::Wide;
}

namespace {

// The panels by the layout's kind, before the accuracy chart's place is taken out of them.
PanelLayout panels_by_kind(const UiState& ui, int width, int height) {
  PanelLayout out;
  const float s = ui.scale * (ui.presentation ? kPresentationScale : 1.0f);
  const float W = static_cast<float>(width), H = static_cast<float>(height);
  const float band = std::min(ui.band, 0.5f * H);  // the panels' (the scene's is in whole pixels)
  const int scene_top = std::min(static_cast<int>(ui.band), height / 2);
  const float pad = kPad * s;
  const auto viewport = [](float x, float y, float w, float h) {
    return draw::Viewport{static_cast<int>(x), static_cast<int>(y),
                          std::max(0, static_cast<int>(w)), std::max(0, static_cast<int>(h))};
  };
  out.kind = ui.presentation ? LayoutKind::Wide : layout_kind(W / ui.scale, H / ui.scale);
  out.scene = {0, scene_top, width, height - scene_top};
  if (!ui.panels) return out;
  switch (out.kind) {
    case LayoutKind::Wide: {
      const float left = kLeftWidth * s, chart = kChartHeight * s;
      out.controls = {pad, band + pad, left, H - band - 2 * pad};
      out.charts = {left + 2 * pad, H - chart - pad, W - left - 3 * pad, chart};
      // (Whole pixels as the scene has always been cut: the same pictures at the same sizes.)
      const int scene_x = static_cast<int>((kLeftWidth + 2 * kPad) * s);
      const int scene_h = height - static_cast<int>((kChartHeight + 2 * kPad) * s) - scene_top;
      // Too small to share (a tiny window): the scene fills it, the panels over it.
      if (width - scene_x < 64 || scene_h < 64) return out;
      out.scene = {scene_x, scene_top, width - scene_x, scene_h};
      return out;
    }
    case LayoutKind::Compact: {
      // One column on the left: the controls (they scroll), one chart under them; the scene in
      // all the rest, full height (a small laptop's 640 units leave no room for a row of charts).
      const float left = std::clamp(0.28f * W, 270.0f * s, kLeftWidth * s);
      const float chart = std::clamp(0.42f * (H - band), 170.0f * s, 260.0f * s);
      out.controls = {pad, band + pad, left, H - band - 3 * pad - chart};
      out.charts = {pad, H - chart - pad, left, chart};
      out.scene = viewport(left + 2 * pad, band, W - left - 2 * pad, H - band);
      return out;
    }
    case LayoutKind::Upright: {
      out.touch = true;
      const float row = kRow * s;
      out.strip = {0, H - row, W, row};
      const float scene_h = std::max(0.41f * H, 0.5f * (H - band - row));
      out.scene = viewport(0, band, W, scene_h);
      const float below = band + scene_h;
      if (ui.sheet_open)
        out.controls = {0, below, W, H - below};  // over the chart, never the scene
      else if (H - row - below - 2 * pad >= 140.0f * s)
        out.charts = {pad, below + pad, W - 2 * pad, H - row - below - 2 * pad};
      else
        out.scene =
            viewport(0, band, W, H - row - band);  // no room for a chart: the scene takes it
      return out;
    }
    case LayoutKind::Side: {
      out.touch = true;
      const bool open = ui.side_open.value_or(ui.lesson.empty());
      const float panel = open ? std::min(kSideWidth * s, 0.42f * W) : kStrip * s;
      if (open)
        out.controls = {0, band, panel, H - band};
      else
        out.strip = {0, band, panel, H - band};
      out.scene = viewport(panel, band, W - panel, H - band);
      return out;
    }
  }
  return out;
}

// The accuracy chart's place, where the layout gives it one (else it floats over the scene):
//   a lesson's step, a phone    the scene's and the charts' place (the step is about the chart;
//                               a phone has no room to float it);
//   compare mode                the same, less a column on the left where the lanes stack (the
//                               chart over them hid every lane); Upright, where the height allows
//                               both, a row above it.
void place_accuracy(PanelLayout& out, const UiState& ui, bool comparing, float W, float H,
                    float s) {
  if (!ui.accuracy || (ui.lesson.empty() && !comparing && !out.touch)) return;
  const float foot =
      out.strip.empty() || out.strip.y <= static_cast<float>(out.scene.y) ? H : out.strip.y;
  float x = static_cast<float>(out.scene.x), y = static_cast<float>(out.scene.y);
  if (comparing && out.kind == LayoutKind::Upright && foot - y >= 600.0f * s) {
    // The lanes above in 2 of 5 (at least 240 units; a chart needs the 360 under them).
    const int above = static_cast<int>(0.4f * (foot - y));
    out.scene = {out.scene.x, out.scene.y, out.scene.width, above};
    y += static_cast<float>(above);
  } else if (comparing && out.kind != LayoutKind::Upright) {
    // A third of the width: stacked, 2 to 4 lanes of 16:9 are as large as in a row above a
    // chart of the same size, and the chart keeps its width.
    const int column = static_cast<int>(std::round((W - x) / 3.0f));
    out.scene = {out.scene.x, out.scene.y, column, static_cast<int>(foot) - out.scene.y};
    x += static_cast<float>(column);
  }
  const float pad = kPad * s;
  out.accuracy = {x + pad, y + pad, W - x - 2 * pad, foot - y - 2 * pad};
  out.charts = {};  // (under the chart: not drawn)
}

}  // namespace

PanelLayout panel_layout(const UiState& ui, bool comparing, int width, int height) {
  PanelLayout out = panels_by_kind(ui, width, height);
  const float s = ui.scale * (ui.presentation ? kPresentationScale : 1.0f);
  place_accuracy(out, ui, comparing, static_cast<float>(width), static_cast<float>(height), s);
  return out;
}

}  // namespace springlab::ui
