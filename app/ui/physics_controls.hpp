// The physics' sliders as data: what each sets, its label, value and range, read from the session
// and the ranges of the scene as loaded. The panels draw them (ui/mass_spring_panels.cpp) and the
// browser's accessible document offers them as its own sliders (web/access.cpp): one list, the same
// ranges.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "session/session.hpp"
#include "ui/panels.hpp"

namespace springlab::ui {

struct PhysicsControl {
  const char* id;     // "ks", "kd", "dt", "mass", "gravity", "drag"
  std::string label;  // as the panel shows it, translated: "k_s (N/m)", "dt (s)"
  double value = 0.0, lo = 0.0, hi = 1.0;
  bool log = true;  // a logarithmic slider
  const char* format = "%.3g";
  std::function<void(app::Session&, double)> set;
};

// In the panel's order: k_s and k_d (where the scene has springs), dt, then mass, gravity and drag.
std::vector<PhysicsControl> physics_controls(const app::Session& session, const UiState& ui);

}  // namespace springlab::ui
