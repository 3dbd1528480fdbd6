// A scene kind's UI half (session/scene_kind.hpp has its simulation half): its sections of the
// panels, its charts, its words over the scene, and what compare sets side by side. draw_panels,
// the overlay, the keys and the browser's words draw the frame around them and ask the session's
// kind for its own, so that none of them asks which kind a scene is.
//
//   mass-spring          mass_spring_panels(): mass_spring_panels.cpp (its words: overlay.cpp)
//   inverse kinematics   ik_panels(): ik_panels.cpp
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "chart/chart.hpp"
#include "session/session.hpp"
#include "ui/layout.hpp"
#include "ui/panels.hpp"

namespace springlab::ui {

struct KindPanels {
  // The simulation's controls, under the pickers: the row's picker, the transport and the clocks
  // (ui/widgets.hpp), and what the kind sets and says (`presenting`: presentation mode's fewer).
  void (*controls)(app::Session& session, UiState& ui, const FrameStats& stats,
                   const PanelLayout& layout, bool presenting);
  // Under the controls: the kind's studies (their panels' buttons) and its compare choices.
  // (`scale`: the panels' scale, ui/layout.hpp.)
  void (*tools)(app::Session& session, UiState& ui, float scale);
  // The upright strip's tail, after its menu, play and step buttons.
  void (*strip)(app::Session& session, UiState& ui, float button);
  // The charts' panel: a lesson step's (`only`), or the kind's own.
  void (*charts)(app::Session& session, float width, float height, bool presentation,
                 const std::vector<LessonChart>& only);
  // The charts the browser's words describe (web/access.cpp).
  std::vector<chart::Chart> (*charts_said)(const app::Session& session);
  // The rows C sets side by side.
  std::vector<int> (*compare_choice)(const app::Session& session, const UiState& ui);
  // The caption over a frame without panels, of the single view (compare mode's is every kind's:
  // overlay.cpp), from the scene's name ("slow": "0.42x real time" or ""), and a lane's progress
  // after its label in the legend (leading spaces included).
  std::string (*caption)(const app::Session& session, const std::string& scene_name,
                         const std::string& slow);
  std::string (*progress)(const app::Lane& lane);
};

// The UI half of a scene's kind: the panels registered under its kind_name(). The built-in kinds'
// are there from the start; a kind of one's own adds its own before its first frame (a kind with
// none is a mistake of the program: std::logic_error naming it).
const KindPanels& kind_panels(const app::SceneKind& kind);
void add_kind_panels(std::string_view kind_name, const KindPanels& panels);
const KindPanels& mass_spring_panels();
const KindPanels& ik_panels();

}  // namespace springlab::ui
