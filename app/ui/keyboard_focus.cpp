#include "ui/keyboard_focus.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <vector>

namespace springlab::ui {
namespace {

// The panels the keyboard visits, in reading order (top to bottom, then left to right): the
// windows shown this frame that take navigation, not Dear ImGui's hidden fallback window, and
// not tooltips, popups or child windows (a child is reached through its parent).
std::vector<ImGuiWindow*> panels() {
  std::vector<ImGuiWindow*> out;
  for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows) {
    if (!w->WasActive || w->Hidden || w->IsFallbackWindow) continue;
    if (w->Flags &
        (ImGuiWindowFlags_ChildWindow | ImGuiWindowFlags_Tooltip | ImGuiWindowFlags_Popup |
         ImGuiWindowFlags_NoNavInputs | ImGuiWindowFlags_NoNavFocus))
      continue;
    out.push_back(w);
  }
  std::stable_sort(out.begin(), out.end(), [](const ImGuiWindow* a, const ImGuiWindow* b) {
    return a->Pos.y != b->Pos.y ? a->Pos.y < b->Pos.y : a->Pos.x < b->Pos.x;
  });
  return out;
}

void enter(KeyboardFocus& focus) {
  focus.in_panels = true;
  ImGui::GetIO().ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard;
}

void leave(KeyboardFocus& focus) {
  focus.in_panels = false;
  ImGui::GetIO().ConfigFlags &= ~ImGuiConfigFlags_NavEnableKeyboard;
  ImGui::FocusWindow(nullptr);
}

// Focuses a panel with its highlight shown on its last control (its first, the first time), as
// Dear ImGui's Ctrl+Tab does.
void focus_panel(ImGuiWindow* w) {
  ImGuiContext& g = *ImGui::GetCurrentContext();
  ImGui::ClearActiveID();
  ImGui::FocusWindow(w);
  if (w->NavLastIds[0] == 0) ImGui::NavInitWindow(w, false);
  g.NavDisableHighlight = false;  // the focus is shown (a frame around the control)
  g.NavDisableMouseHover = true;
}

}  // namespace

bool update_keyboard_focus(KeyboardFocus& focus) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGuiContext& g = *ImGui::GetCurrentContext();
  const bool before = focus.in_panels;  // (the Esc that leaves the panels is still theirs)
  // Ctrl+Tab: Dear ImGui switches windows (with or without navigation); the keys follow it.
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_TAB, false) && !focus.in_panels) enter(focus);
  if (ImGui::IsKeyPressed(GLFW_KEY_F6, false)) {
    const std::vector<ImGuiWindow*> all = panels();
    // Where the keyboard is now: -1 the scene, else the focused panel's place.
    int at = -1;
    if (focus.in_panels && g.NavWindow)
      for (std::size_t i = 0; i < all.size(); ++i)
        if (all[i] == g.NavWindow->RootWindow) at = static_cast<int>(i);
    const int n = static_cast<int>(all.size());
    // The ring: scene, panel 0, ..., panel n-1, scene.
    int next = io.KeyShift ? (at == -1 ? n - 1 : at - 1) : (at + 1 < n ? at + 1 : -1);
    if (next < 0 || n == 0) {
      leave(focus);
    } else {
      enter(focus);
      focus_panel(all[static_cast<std::size_t>(next)]);
    }
    return before || focus.in_panels;
  }
  if (focus.in_panels) {
    // A click on the scene (Dear ImGui then focuses no window), or Esc with nothing to cancel.
    const bool esc = ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false) && !focus.editing;
    if (esc || (!g.NavWindow && !g.NavWindowingTarget)) leave(focus);
  }
  return before || focus.in_panels;
}

void end_keyboard_focus_frame(KeyboardFocus& focus) {
  ImGuiContext& g = *ImGui::GetCurrentContext();
  focus.editing = ImGui::IsAnyItemActive() || g.OpenPopupStack.Size > 0;
}

}  // namespace springlab::ui
