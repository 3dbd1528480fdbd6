// The app's Compare panel: the sweep of `springlab compare` run on the scene on screen, in the
// background, with progress and cancel, and the same charts filling in as the runs finish.
#pragma once

#include <array>

#include "session/background_sweep.hpp"
#include "session/session.hpp"
#include "ui/layout.hpp"
#include "ui/method_choice.hpp"

namespace springlab::ui {

struct ComparePanel {
  bool open = false;
  int points = 6;
  float duration = 1.0f;     // s simulated by each run
  float step_range = 16.0f;  // from dt / range to 2 dt
  MethodChoice methods;      // which to sweep (none ticked: all)
  int chart = 0;             // the tab shown: compare_charts' order (0: error vs time, 1: vs work)
  app::BackgroundSweep sweep;

  // The settings for the session's scene as it is now.
  SweepSettings settings(const app::Session& session) const;
  void start(const app::Session& session);
};

// Draws the panel (when open): in the place the layout gives it (PanelLayout::accuracy), opaque
// and kept there; where that is empty, over the scene's upper part, where it can be dragged.
void draw_compare_panel(ComparePanel& panel, const app::Session& session, float scale,
                        const Rect& place, int width, int height);

}  // namespace springlab::ui
