#include "window/key_presses.hpp"

#define GLFW_INCLUDE_NONE  // (no OpenGL header here: gfx/gl.hpp brings epoxy where GL is drawn)
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <sstream>
#include <utility>

#include "springlab/error.hpp"

namespace springlab::app {

std::vector<KeyPress> parse_key_presses(const std::string& text, const std::string& option) {
  static const std::pair<const char*, int> named[] = {{"F1", GLFW_KEY_F1},
                                                      {"F6", GLFW_KEY_F6},
                                                      {"Down", GLFW_KEY_DOWN},
                                                      {"Up", GLFW_KEY_UP},
                                                      {"Left", GLFW_KEY_LEFT},
                                                      {"Right", GLFW_KEY_RIGHT},
                                                      {"Space", GLFW_KEY_SPACE},
                                                      {"Enter", GLFW_KEY_ENTER},
                                                      {"Escape", GLFW_KEY_ESCAPE},
                                                      {"Tab", GLFW_KEY_TAB},
                                                      {"PageDown", GLFW_KEY_PAGE_DOWN},
                                                      {"PageUp", GLFW_KEY_PAGE_UP},
                                                      {"Home", GLFW_KEY_HOME},
                                                      {"End", GLFW_KEY_END}};
  std::vector<KeyPress> out;
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ',')) {
    KeyPress k;
    k.name = item;
    std::string rest = item;
    for (auto [prefix, flag] : {std::pair{"Shift+", &k.shift}, std::pair{"Ctrl+", &k.ctrl}})
      if (rest.rfind(prefix, 0) == 0) {
        *flag = true;
        rest = rest.substr(std::string(prefix).size());
      }
    for (const auto& [name, key] : named)
      if (rest == name) k.key = key;
    if (rest.size() == 1 && rest[0] >= 'A' && rest[0] <= 'Z') k.key = GLFW_KEY_A + (rest[0] - 'A');
    if (rest.size() == 1 && rest[0] >= '0' && rest[0] <= '9') k.key = GLFW_KEY_0 + (rest[0] - '0');
    if (k.key == 0)
      throw InputError(option + ": unknown key '" + item +
                       "' (keys: F1, F6, Up, Down, Left, Right, Space, Enter, Escape, Tab, PageUp, "
                       "PageDown, Home, End, A-Z, "
                       "0-9, each perhaps after Shift+ or Ctrl+; separated by commas)");
    out.push_back(k);
  }
  if (out.empty()) throw InputError(option + ": no keys given (e.g. F6,Down,Space)");
  return out;
}

void press_keys(const std::vector<KeyPress>& keys, long frame, long first) {
  if (frame < first || (frame - first) / 2 >= static_cast<long>(keys.size())) return;
  const KeyPress& k = keys[static_cast<std::size_t>((frame - first) / 2)];
  const bool down = (frame - first) % 2 == 0;
  ImGuiIO& io = ImGui::GetIO();
  io.KeysDown[k.key] = down;
  io.KeyShift = down && k.shift;
  io.KeyCtrl = down && k.ctrl;
  // A letter or digit types itself too, as GLFW's character callback passes it on.
  if (down && !k.ctrl && k.name.size() == 1 + (k.shift ? 6 : 0)) {
    const char c = k.name.back();
    io.AddInputCharacter(
        static_cast<unsigned>(k.shift || !(c >= 'A' && c <= 'Z') ? c : c - 'A' + 'a'));
  }
}

}  // namespace springlab::app
