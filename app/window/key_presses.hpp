// Keys pressed for the window, one every other frame: `springlab view --keys F6,Down,Space`,
// so that a script (and the tests) can run the panels by keyboard as a person would, through
// the same input Dear ImGui takes from GLFW.
#pragma once

#include <string>
#include <vector>

namespace springlab::app {

struct KeyPress {
  int key = 0;  // GLFW_KEY_*
  bool shift = false, ctrl = false;
  std::string name;  // as given
};

// "F6,Shift+F6,Down,Space,Enter,Escape,Tab,Ctrl+Tab,Left,Right,Up,A..Z,0..9": throws InputError
// (naming `option`) for a key it does not know.
std::vector<KeyPress> parse_key_presses(const std::string& text, const std::string& option);

// Before the frame's ImGui::NewFrame: frame 2k + first presses key k, frame 2k + first + 1 lets it
// go (each press seen as one, as a person's would be).
void press_keys(const std::vector<KeyPress>& keys, long frame, long first);

}  // namespace springlab::app
