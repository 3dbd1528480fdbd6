// Where the panels go, chosen by the window's shape and size (in layout units: pixels / the UI
// scale, the browser's CSS pixels at UI scale 1):
//   Wide     a laptop or a monitor (at least 1200 x 700): the controls on the left, the charts
//            along the bottom, the scene in the rest; the layout springlab always had.
//   Compact  a small laptop or a tablet on its side (landscape, under 1200 x 700): one column on
//            the left, the controls over one chart, and the scene in all the rest.
//   Upright  a phone or a tablet held upright (taller than wide, under 900 wide): the scene on top
//            (at least 40 % of the window), one chart under it, and the controls in a sheet at
//            the bottom: one row (menu, play or pause, step, the method, dt) that opens to all.
//   Side     a phone on its side (under 500 high): the scene beside the controls, which fold
//            away to a strip of buttons (folded at first under a lesson's band).
// The lesson's band, when there is one, runs across the top in every layout. The accuracy chart,
// open in a lesson or beside compare mode's lanes, takes the scene's and the charts' place, less
// a column for the lanes (place_accuracy).
#pragma once

#include "draw/scene_frame.hpp"

namespace springlab::ui {

struct UiState;

enum class LayoutKind { Wide, Compact, Upright, Side };

struct Rect {
  float x = 0, y = 0, w = 0, h = 0;
  bool empty() const { return !(w > 0.0f && h > 0.0f); }
};

struct PanelLayout {
  LayoutKind kind = LayoutKind::Wide;
  Rect controls;  // the controls' panel (empty: folded or hidden)
  Rect strip;     // Upright: the sheet's one row; Side: the folded panel's strip of buttons
  Rect charts;    // the charts' panel (empty: none)
  Rect accuracy;  // the accuracy chart's (empty: it floats over the scene where it is dragged)
  draw::Viewport scene;
  bool touch = false;  // Upright and Side: frames at least 44 layout units high, for a thumb
};

// The layout of a width x height window (pixels) for the UI's state: its scale, whether the
// panels are shown, presentation mode, the band's height, the sheet or strip opened or folded;
// and whether the session compares lanes (they keep a column beside the accuracy chart).
PanelLayout panel_layout(const UiState& ui, bool comparing, int width, int height);
LayoutKind layout_kind(float width_units, float height_units);

}  // namespace springlab::ui
