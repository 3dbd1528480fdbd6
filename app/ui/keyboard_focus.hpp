// Where the keyboard's keys go: to the scene, as the app's shortcuts (Space pauses, the arrows
// step a lesson, Esc quits: the help's keys), or into the panels, as Dear ImGui's keyboard
// navigation (arrows move between controls, Space presses one, Enter types a value, Esc cancels
// an edit). F6 moves the keyboard from the scene into the first panel and on, panel after panel,
// back to the scene after the last (Shift+F6 the other way), as a desktop application's panes
// do; Ctrl+Tab, Dear ImGui's own window switcher, also enters the panels. Esc in a panel (with no
// edit to cancel) and a click on the scene give the keyboard back to the scene.
//
// The panels take the keyboard only when asked: a teacher who clicked a slider and then presses
// Space still pauses, as before (the navigation is off until F6 or Ctrl+Tab).
#pragma once

namespace springlab::ui {

struct KeyboardFocus {
  bool in_panels = false;  // the panels have the keys (navigation on)
  bool editing = false;  // at the end of the last frame, a control was being used (Esc cancels it)
};

// After ImGui::NewFrame and before the app's shortcuts: F6, Shift+F6, Ctrl+Tab, Esc and clicks
// move the keyboard between the scene and the panels. Returns whether this frame's keys are the
// panels' (the Esc that gives them back to the scene included).
bool update_keyboard_focus(KeyboardFocus& focus);

// After the frame's windows: whether a control is in use (a slider held, a value being typed, a
// list open), for the next frame's Esc.
void end_keyboard_focus_frame(KeyboardFocus& focus);

}  // namespace springlab::ui
