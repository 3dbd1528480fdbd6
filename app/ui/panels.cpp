// The app's panels, drawn with Dear ImGui each frame from the session and the UI's state. One
// function a window (draw_panels calls them in this order), as imgui_demo.cpp is laid out:
//
//   strip               the strip of buttons along the foot (a phone held upright)
//   controls_window     "springlab": pickers, the platform's controls, about, the scene kind's
//                       controls (kind_panels.hpp: mass_spring_panels.cpp, ik_panels.cpp), tools
//                       (cost, the kind's tools, a particle by keys, view and files)
//   charts_window       "Charts": the kind's, or a lesson's own
//   region              the stability region (region_window)
//   divergence_window   "Diverged": the single view's banner and the way out
//   message_window      "Message": a file that failed to load
//   keys_window         "Keys" (F1)
//
// The widgets they share are ui/widgets.hpp's; what a scene kind draws in them, its panels' own
// (kind_panels.hpp).
#include "ui/panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "chart/text_wrap.hpp"
#include "draw/palette.hpp"
#include "springlab/text.hpp"
#include "ui/interaction.hpp"
#include "ui/kind_panels.hpp"
#include "ui/layout.hpp"
#include "ui/mass_spring_panels.hpp"
#include "ui/widgets.hpp"
#include "util/language.hpp"

namespace springlab::ui {

namespace {

constexpr ImGuiWindowFlags kPanel = ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove |
                                    ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse;
// The two docked panels sit where the scene is never drawn (scene_viewport), over the plain
// background: filling them again would only cost time (on a software rasteriser, most of a frame).
constexpr ImGuiWindowFlags kDocked = kPanel | ImGuiWindowFlags_NoBackground;

void region_window(app::Session& session, UiState& ui, float x, float y, float width,
                   float height) {
  if (!ui.region) return;
  ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Appearing);
  ImGui::SetNextWindowBgAlpha(1.0f);  // (over the charts, theirs must not show through its own)
  if (!ImGui::Begin((tr("Stability region (G)") + std::string("###region")).c_str(), &ui.region,
                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  std::string none;
  std::vector<chart::Chart> shown = region_charts(session, none);
  if (!none.empty()) ImGui::TextDisabled("%s", none.c_str());
  const ImVec2 room = ImGui::GetContentRegionAvail();
  charts_row(shown, room.x, room.y);
  ImGui::End();
}

}  // namespace

Ranges Ranges::of(const app::Session& session) {
  Ranges r;
  r.ks = session.stiffness();
  r.kd = session.damping();
  r.dt = session.primary().sim.settings().dt;
  r.mass = session.mass();
  r.drag = session.primary().sim.model().drag;
  r.gravity = session.primary().sim.model().gravity.norm();
  return r;
}

std::vector<Method> compare_methods(const UiState& ui) {
  std::vector<Method> out;
  for (const MethodInfo& m : methods())
    if (ui.compare_choice.has(m.id) && out.size() < app::Session::kMaxLanes) out.push_back(m.id);
  return out;
}

namespace {
float layout_scale(const UiState& ui) {
  return ui.scale * (ui.presentation ? kPresentationScale : 1.0f);
}
}  // namespace

draw::Viewport scene_viewport(const UiState& ui, const app::Session& session, int width,
                              int height) {
  return panel_layout(ui, session.comparing(), width, height).scene;
}

Rect accuracy_rect(const UiState& ui, const app::Session& session, int width, int height) {
  return panel_layout(ui, session.comparing(), width, height).accuracy;
}

namespace {

// The touch layouts' strip: Upright's sheet folded to one row (its menu, play or pause, step, the
// method, dt), or Side's folded panel (its menu, play or pause, step, one above the other).
void strip(app::Session& session, UiState& ui, const PanelLayout& layout) {
  const Rect& r = layout.strip;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y));
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h));
  ImGui::Begin("##strip", nullptr,
               kPanel | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
  const bool row = layout.kind == LayoutKind::Upright;
  const float button = ImGui::GetFrameHeight();
  const auto next = [&] {
    if (row) ImGui::SameLine();
  };
  if (ImGui::Button("\u2261", ImVec2(button, button))) {  // the menu: all the controls
    if (row)
      ui.sheet_open = true;
    else
      ui.side_open = true;
  }
  next();
  if (ImGui::Button(session.paused() ? ">" : "||", ImVec2(button, button)))
    session.set_paused(!session.paused());
  next();
  if (ImGui::Button("S", ImVec2(button, button))) {
    session.set_paused(true);
    session.step_once();
  }
  if (row) kind_panels(session.kind()).strip(session, ui, button);  // the kind's tail: its row, ...
  ImGui::End();
}

// Each window of the panels, a function (the index is at the top of this file).

// The scene's picker and the lessons' (a choice is a request, taken after the frame).
void pickers(const UiState& ui, Requests& requests) {
  if (!ui.scenes.empty()) widest_beside(tr("scene"));
  if (!ui.scenes.empty() && ImGui::BeginCombo(tr("scene"), ui.scene_name.c_str())) {
    for (const std::string& name : ui.scenes)
      if (ImGui::Selectable(name.c_str(), name == ui.scene_name)) requests.load = name;
    ImGui::EndCombo();
  }
  // The lessons: the lecture, step by step (the band across the top then leads).
  if (!ui.lessons.empty()) {
    // (Its number and title where they fit the box, else "4 of 13": never a title cut mid-word;
    // and "(none)" where "(none: explore freely)" would be cut.)
    widest_beside(tr("lesson"));
    const float room =
        ImGui::CalcItemWidth() - ImGui::GetFrameHeight() - 2.0f * ImGui::GetStyle().FramePadding.x;
    std::string current = tr("(none: explore freely)");
    if (ImGui::CalcTextSize(current.c_str()).x > room) current = tr("(none)");
    for (std::size_t k = 0; k < ui.lessons.size(); ++k)
      if (ui.lessons[k].first == ui.lesson) {
        current = std::to_string(k + 1) + "  " + tr(ui.lessons[k].second);
        if (ImGui::CalcTextSize(current.c_str()).x > room) {
          char s[64];
          std::snprintf(s, sizeof s, tr("%zu of %zu"), k + 1, ui.lessons.size());
          current = s;
        }
      }
    widest_beside(tr("lesson"));
    if (ImGui::BeginCombo(tr("lesson"), current.c_str())) {
      if (ImGui::Selectable(tr("(none: explore freely)"), ui.lesson.empty())) requests.lesson = "";
      for (std::size_t k = 0; k < ui.lessons.size(); ++k) {
        const std::string label = std::to_string(k + 1) + "  " + tr(ui.lessons[k].second);
        if (ImGui::Selectable(label.c_str(), ui.lessons[k].first == ui.lesson))
          requests.lesson = ui.lessons[k].first;
      }
      ImGui::EndCombo();
    }
  }
}

// The scene's description: its first sentence, the rest on hover (on touch, all of it).
void about(const app::Session& session, float scale, bool touch) {
  const std::string text = tr(session.scene().description);
  const std::size_t stop =
      touch ? std::string::npos : text.find(". ");  // (touch: all of it, no hover)
  text_wrapped_disabled(stop == std::string::npos ? text : text.substr(0, stop + 1) + " (...)");
  if (ImGui::IsItemHovered() && stop != std::string::npos) {
    ImGui::BeginTooltip();
    text_wrapped(text, {}, 420.0f * scale);
    ImGui::EndTooltip();
  }
}

// A particle held and moved without a pointer (ui/interaction.hpp: hold, nudge), for the
// keyboard's navigation of the panels: its number, Hold it or Let go, and four arrows that
// repeat while held.
void particle_by_keys(app::Session& session, UiState& ui) {
  const int n = session.primary().sim.state().particle_count();
  if (n == 0) return;
  ImGui::InputInt(tr("particle"), &ui.key_particle);
  ui.key_particle = std::clamp(ui.key_particle, 0, n - 1);
  if (session.grabbed() < 0) {
    if (ImGui::Button(tr("Hold it"))) hold(session, ui.key_particle);
    return;
  }
  if (ImGui::Button(tr("Let go"))) return release(session);
  ImGui::PushButtonRepeat(true);
  const std::tuple<const char*, ImGuiDir, double, double> arrows[] = {
      {"##left", ImGuiDir_Left, -1, 0},
      {"##right", ImGuiDir_Right, 1, 0},
      {"##up", ImGuiDir_Up, 0, 1},
      {"##down", ImGuiDir_Down, 0, -1}};
  for (const auto& [id, dir, dx, dy] : arrows) {
    ImGui::SameLine();
    if (ImGui::ArrowButton(id, dir)) nudge(session, dx, dy);
  }
  ImGui::PopButtonRepeat();
}

// Below the controls: what a frame costs, the kind's tools (its studies and compare choices), a
// particle by keys and the view and files.
void tools(app::Session& session, UiState& ui, const FrameStats& stats, float scale, bool touch,
           Requests& requests) {
  if (stats.timed)
    ImGui::TextDisabled(tr("a frame: %.1f ms simulating, %.1f drawing"), stats.sim_ms,
                        stats.draw_ms);
  else
    ImGui::TextDisabled(tr("a frame: %lld force evaluations"),
                        static_cast<long long>(stats.force_evals));
  // Compare: each lane's part of it, in its colour, and how the lanes are shown.
  if (session.comparing()) {
    for (std::size_t k = 0; k < session.lanes().size() && k < stats.lanes.size(); ++k) {
      const app::Lane& lane = session.lanes()[k];
      const Counters& work = stats.lanes[k];
      const std::string label = app::lane_label(lane);
      const ImVec4 colour = lane.sim.diverged() ? kBeyond : v4(draw::lane_color(lane));
      char line[200];
      if (lane.sim.diverged())
        std::snprintf(line, sizeof line, tr("%s: none (it diverged)"), label.c_str());
      else if (work.solver_iterations > 0)
        std::snprintf(line, sizeof line, tr("%s: %lld force evaluations + %lld solver iterations"),
                      label.c_str(), static_cast<long long>(work.force_evals),
                      static_cast<long long>(work.solver_iterations));
      else
        std::snprintf(line, sizeof line, tr("%s: %lld force evaluations"), label.c_str(),
                      static_cast<long long>(work.force_evals));
      ImGui::Indent();
      text_wrapped(line, colour);
      ImGui::Unindent();
    }
    ImGui::TextUnformatted(tr("lanes:"));
    ImGui::SameLine();
    if (ImGui::RadioButton(tr("apart"), ui.view.compare_layout == draw::CompareLayout::Apart))
      ui.view.compare_layout = draw::CompareLayout::Apart;
    ImGui::SameLine();
    if (ImGui::RadioButton(tr("together"), ui.view.compare_layout == draw::CompareLayout::Together))
      ui.view.compare_layout = draw::CompareLayout::Together;
  }
  kind_panels(session.kind()).tools(session, ui, scale);
  if (ImGui::CollapsingHeader(tr("A particle by keys"))) particle_by_keys(session, ui);
  if (ImGui::CollapsingHeader(tr("View and files"))) {
    ImGui::InputTextWithHint("##open", tr("a scene file (or drop one)"), ui.open_path,
                             sizeof ui.open_path);
    ImGui::SameLine();
    if (ImGui::Button(tr("Open")) && ui.open_path[0]) requests.load = std::string(ui.open_path);
    ImGui::Checkbox(tr("springs"), &ui.view.springs);
    ImGui::SameLine();
    ImGui::Checkbox(tr("particles"), &ui.view.particles);
    ImGui::SameLine();
    ImGui::Checkbox(tr("surface"), &ui.view.surfaces);
    ImGui::Checkbox(tr("the limiting mode (M)"), &ui.view.mode);
    double strain = ui.view.strain_scale;
    if (slider(tr("strain scale"), strain, 1e-3, 0.5, true, touch, "+-%.3f"))
      ui.view.strain_scale = strain;
    ImGui::Checkbox(tr("presentation (P)"), &ui.presentation);
    // The language, switched live (the fonts are remade before the next frame).
    const std::string now = current_language();
    const auto& all = app::languages();
    const auto shown =
        std::find_if(all.begin(), all.end(), [&](const app::Language& l) { return now == l.tag; });
    widest_beside(tr("language"));
    if (ImGui::BeginCombo(tr("language"), shown == all.end() ? now.c_str() : shown->name.c_str())) {
      for (const app::Language& l : all)
        if (ImGui::Selectable(l.name.c_str(), now == l.tag) && now != l.tag)
          requests.language = l.tag;
      ImGui::EndCombo();
    }
  }
}

// The controls' window: the pickers, the platform's own controls, the simulation's and the tools.
void controls_window(app::Session& session, UiState& ui, const FrameStats& stats,
                     const PanelLayout& layout, ImGuiWindowFlags docked, float scale,
                     bool presenting, Requests& requests) {
  const Rect& c = layout.controls;
  ImGui::SetNextWindowPos(ImVec2(c.x, c.y));
  ImGui::SetNextWindowSize(ImVec2(c.w, c.h));
  ImGui::Begin("springlab", nullptr, docked | ImGuiWindowFlags_NoTitleBar);
  ImGui::PushItemWidth(-std::min(130.0f * scale, 0.4f * c.w));
  if (layout.touch) {  // the way back to the scene's room: close the sheet, fold the panel
    if (ImGui::Button(layout.kind == LayoutKind::Upright ? "\u2193" : "\u2190",
                      ImVec2(ImGui::GetFrameHeight(), 0))) {
      if (layout.kind == LayoutKind::Upright)
        ui.sheet_open = false;
      else
        ui.side_open = false;
    }
    ImGui::SameLine();
  }
  pickers(ui, requests);
  if (ui.platform_controls) ui.platform_controls();
  about(session, scale, layout.touch);
  ImGui::Separator();
  kind_panels(session.kind()).controls(session, ui, stats, layout, presenting);
  if (!presenting) tools(session, ui, stats, scale, layout.touch, requests);
  ImGui::PopItemWidth();
  ImGui::End();
}

// The charts' window: side by side; one in presentation mode and in the upright layout (the
// lesson's first).
void charts_window(app::Session& session, const UiState& ui, const PanelLayout& layout,
                   ImGuiWindowFlags docked) {
  const Rect& c = layout.charts;
  ImGui::SetNextWindowPos(ImVec2(c.x, c.y));
  ImGui::SetNextWindowSize(ImVec2(c.w, c.h));
  ImGui::Begin("Charts", nullptr, docked | ImGuiWindowFlags_NoTitleBar);
  std::vector<LessonChart> only = ui.lesson_charts;
  const bool one = layout.kind == LayoutKind::Upright || layout.kind == LayoutKind::Compact;
  if (one && only.size() > 1) only.erase(only.begin() + 1, only.end());
  kind_panels(session.kind())
      .charts(session, ImGui::GetContentRegionAvail().x, ImGui::GetContentRegionAvail().y,
              ui.presentation || one, only);
  ImGui::End();
}

// The stability region's window, over the scene's top left; in compare mode, where the lanes tile
// the scene and any place in it hides a lane, over the charts instead (homework 8's step 7 had it
// over the whole symplectic Euler lane its caption is about), or over the accuracy chart's lower
// half where that has taken the charts' place.
void region(app::Session& session, UiState& ui, const PanelLayout& layout, float scale, int width,
            int height) {
  const float pad = 8.0f * scale;
  const Rect& a = layout.accuracy;
  if (session.comparing() && layout.kind == LayoutKind::Wide && !layout.charts.empty()) {
    region_window(session, ui, layout.charts.x, layout.charts.y, layout.charts.w, layout.charts.h);
  } else if (session.comparing() && !a.empty()) {
    region_window(session, ui, a.x, a.y + 0.5f * a.h, a.w, 0.5f * a.h);
  } else if (layout.kind == LayoutKind::Wide) {
    region_window(session, ui, layout.charts.x, layout.controls.y,
                  0.55f * (width - layout.charts.x), 0.55f * height);
  } else {
    const float x = layout.scene.x + pad, y = layout.scene.y + pad;
    region_window(session, ui, x, y,
                  std::max(0.55f * (width - x), std::min(480.0f * scale, width - x - pad)),
                  std::max(0.55f * height, 0.5f * layout.scene.height));
  }
}

// Divergence in the single view: a banner, and the way out.
void divergence_window(app::Session& session, const UiState& ui, float scale, int width,
                       int height) {
  const float pad = 8.0f * scale;
  const Simulation& first = session.primary().sim;
  if (const Divergence* trouble = first.trouble(); !session.comparing() && trouble) {
    // In a lesson, where diverging is often the point, one line at the foot of the scene (the
    // explanation on hover), never over the caption or what it describes: none while the
    // accuracy window the step opened covers the scene (its chart is what the caption describes;
    // the panel's lane line says the divergence in red).
    const bool lesson = ui.band > 0.0f;
    if (lesson && ui.accuracy) return;
    const draw::Viewport scene = scene_viewport(ui, session, width, height);
    if (lesson)
      ImGui::SetNextWindowPos(
          ImVec2(scene.x + 0.5f * scene.width, static_cast<float>(scene.y + scene.height) - pad),
          ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    else
      ImGui::SetNextWindowPos(ImVec2(0.5f * width, 0.30f * height), ImGuiCond_Always,
                              ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(lesson ? 0.0f : 560.0f * scale, 0.0f));
    ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.35f, 0.05f, 0.05f, 0.95f));
    ImGui::Begin((tr("Diverged") + std::string("###diverged")).c_str(), nullptr,
                 kPanel | ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::Text(trouble->unstable ? tr("The simulation went numerically unstable at t = %.4g s")
                                  : tr("The simulation diverged at t = %.4g s"),
                trouble->t);
    if (lesson) {
      if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        text_wrapped(trouble->message(), {}, 520.0f * scale);
        ImGui::EndTooltip();
      }
      ImGui::SameLine();
    } else {
      text_wrapped(trouble->message());  // the limit once analysed
    }
    if (ImGui::Button(tr("Reset (R)"))) session.reset();
    ImGui::End();
    ImGui::PopStyleColor();
  }
}

// A message (a file that failed to load), until dismissed.
void message_window(UiState& ui, float scale, int width, int height) {
  ImGui::SetNextWindowPos(ImVec2(0.5f * width, 0.12f * height), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(600.0f * scale, 0.0f));
  ImGui::Begin((tr("Message") + std::string("###message")).c_str(), nullptr,
               kPanel | ImGuiWindowFlags_AlwaysAutoResize);
  text_wrapped(ui.message, kNear, 600.0f * scale - 2.0f * ImGui::GetStyle().WindowPadding.x);
  if (ImGui::Button(tr("OK"))) ui.message.clear();
  ImGui::End();
}

// The keys (F1).
void keys_window(UiState& ui, int width, int height) {
  ImGui::SetNextWindowPos(ImVec2(0.5f * width, 0.5f * height), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  ImGui::Begin((tr("Keys") + std::string("###keys")).c_str(), &ui.help,
               kPanel | ImGuiWindowFlags_AlwaysAutoResize);
  const char* keys[][2] = {
      {N_("space"), N_("pause or resume")},
      {N_("S"), N_("one step")},
      {N_("R"), N_("reset")},
      {N_("1 - 9"), N_("choose a method")},
      {N_("C"), N_("compare mode on or off")},
      {N_("H"), N_("hide or show the panels")},
      {N_("A"), N_("accuracy against cost: chart every method")},
      {N_("G"), N_("the stability region, with the scene's modes")},
      {N_("Y"), N_("your method: type a Butcher tableau, run it beside")},
      {N_("M"), N_("show the mode that limits the step")},
      {N_("P"), N_("presentation mode: larger, for a projector")},
      {N_("\u2192  PgDn  N"), N_("lesson: the next step")},
      {N_("\u2190  PgUp  B"), N_("lesson: the step before")},
      {N_("F1"), N_("this help")},
      {N_("F6  Ctrl+Tab"), N_("the keys into the panels, panel after panel")},
      {N_("\u2190\u2191\u2192\u2193  space  Enter"), N_("in a panel: move, press, type a value")},
      {N_("Esc  (in a panel)"), N_("the keys back to the scene")},
      {N_("left drag"), N_("move a particle (release lets it go with its speed)")},
      {N_("right drag"), N_("orbit the camera (3D) / pan (2D)")},
      {N_("middle drag"), N_("pan")},
      {N_("wheel"), N_("zoom")},
      {N_("Esc"), N_("quit")}};
  if (ImGui::BeginTable("keys", 2)) {
    for (const auto& k : keys) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextColored(kNeutral, "%s", tr(k[0]));
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(tr(k[1]));
    }
    ImGui::EndTable();
  }
  ImGui::End();
}

}  // namespace

Requests draw_panels(app::Session& session, UiState& ui, const FrameStats& stats, int width,
                     int height) {
  Requests requests;
  ImGuiIO& io = ImGui::GetIO();
  const bool large = ui.presentation && io.Fonts->Fonts.Size > 1;
  if (large) ImGui::PushFont(io.Fonts->Fonts[1]);
  const float scale = layout_scale(ui);
  const bool presenting = ui.presentation;
  const PanelLayout layout = panel_layout(ui, session.comparing(), width, height);
  // A thumb's targets: frames at least 44 units high (Apple's guideline; Material's is 48 dp).
  if (layout.touch) {
    const float frame_pad =
        std::max(ImGui::GetStyle().FramePadding.y, 0.5f * (44.0f * scale - ImGui::GetFontSize()));
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding,
                        ImVec2(ImGui::GetStyle().FramePadding.x, frame_pad));
    ImGui::PushStyleVar(ImGuiStyleVar_GrabMinSize, 30.0f * scale);
  }
  // The panels over the scene (a window too small to share): they keep their background.
  const bool over = layout.scene.x == 0 && layout.scene.width == width &&
                    !layout.controls.empty() &&
                    (layout.kind == LayoutKind::Wide || layout.kind == LayoutKind::Compact);
  const ImGuiWindowFlags docked = over || layout.touch ? kPanel : kDocked;

  if (ui.panels && !layout.strip.empty()) strip(session, ui, layout);
  if (ui.panels && !layout.controls.empty())
    controls_window(session, ui, stats, layout, docked, scale, presenting, requests);
  // (Where the accuracy chart takes the charts' place, the layout leaves them none.)
  if (ui.panels && !layout.charts.empty()) charts_window(session, ui, layout, docked);
  if (ui.panels) region(session, ui, layout, scale, width, height);
  divergence_window(session, ui, scale, width, height);
  if (!ui.message.empty()) message_window(ui, scale, width, height);
  if (ui.help) keys_window(ui, width, height);
  if (layout.touch) ImGui::PopStyleVar(2);
  if (large) ImGui::PopFont();
  return requests;
}

std::vector<Counters> lane_counters(const app::Session& session) {
  std::vector<Counters> now;
  for (const app::Lane& lane : session.lanes()) now.push_back(lane.sim.counters());
  return now;
}

void count_frame(FrameStats& stats, const app::Session& session,
                 const std::vector<Counters>& before) {
  stats.lanes.clear();
  stats.force_evals = stats.linear_solves = stats.solver_iterations = 0;
  for (std::size_t k = 0; k < session.lanes().size(); ++k) {
    const Counters& after = session.lanes()[k].sim.counters();
    Counters work;
    if (k < before.size()) {
      work.force_evals = after.force_evals - before[k].force_evals;
      work.linear_solves = after.linear_solves - before[k].linear_solves;
      work.solver_iterations = after.solver_iterations - before[k].solver_iterations;
    }
    stats.force_evals += work.force_evals;
    stats.linear_solves += work.linear_solves;
    stats.solver_iterations += work.solver_iterations;
    stats.lanes.push_back(work);
  }
}

}  // namespace springlab::ui
