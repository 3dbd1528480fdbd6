// What the keyboard shortcuts do, apart from the keys themselves (the window maps GLFW keys to
// these), so that tests drive them exactly as a keypress would.
#pragma once

#include "session/session.hpp"
#include "ui/panels.hpp"

namespace springlab::ui {

enum class Action {
  TogglePause,         // space
  Step,                // S: one step, paused
  Reset,               // R
  ToggleCompare,       // C: the ticked methods, else the scene's, else four classics
  TogglePanels,        // H
  ToggleHelp,          // F1
  ToggleAccuracy,      // A: the Compare panel
  ToggleRegion,        // G: the stability region
  ToggleTableau,       // Y: your method
  ToggleMode,          // M: the limiting mode on the scene
  TogglePresentation,  // P: larger, for a projector
  Method1,
  Method2,
  Method3,
  Method4,
  Method5,
  Method6,
  Method7,
  Method8,
  Method9,  // 1 - 9
};

void perform(Action action, app::Session& session, UiState& ui);

}  // namespace springlab::ui
