#include "ui/tableau_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <nlohmann/json.hpp>

#include "chart/text_wrap.hpp"
#include "springlab/error.hpp"
#include "springlab/text.hpp"
#include "util/data_dir.hpp"

namespace springlab::ui {

namespace {

void set(TableauPanel::Cell& cell, const std::string& text) {
  std::snprintf(cell.data(), cell.size(), "%s", text.c_str());
}

}  // namespace

TableauPanel::TableauPanel() {
  // Heun's, to start from: the lecture's midpoint's neighbour.
  for (auto& row : a)
    for (Cell& c : row) set(c, "0");
  for (Cell& c : b) set(c, "0");
  set(a[1][0], "1");
  set(b[0], "1/2");
  set(b[1], "1/2");
}

void TableauPanel::load(const ButcherTableau& t) {
  if (t.stages > kMaxStages) {
    error = format_text(tr("%s has %d stages; the panel holds %d"), t.name.c_str(), t.stages,
                        kMaxStages);
    return;
  }
  stages = t.stages;
  name = t.name;
  for (int i = 0; i < kMaxStages; ++i) {
    for (int j = 0; j < kMaxStages; ++j)
      set(a[i][j], i < stages && j < stages
                       ? t.a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)].text
                       : "0");
    set(b[i], i < stages ? t.b[static_cast<std::size_t>(i)].text : "0");
  }
  dirty = true;
}

std::string TableauPanel::json() const {
  nlohmann::json doc;
  doc["name"] = name;
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < stages; ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int j = 0; j < stages; ++j) row.push_back(std::string(a[i][j].data()));
    rows.push_back(row);
  }
  doc["A"] = rows;
  nlohmann::json weights = nlohmann::json::array();
  for (int i = 0; i < stages; ++i) weights.push_back(std::string(b[i].data()));
  doc["b"] = weights;
  return doc.dump();
}

void TableauPanel::check() {
  dirty = false;
  tableau.reset();
  analysis.reset();
  error.clear();
  error_row = error_col = -1;
  try {
    tableau = parse_tableau(json(), tr("your method"));
    analysis = analyse_tableau(*tableau);
  } catch (const InputError& e) {
    // "your method: /A/1/0: A row 2, column 1 ...": the cell from the pointer, the rest to show.
    error = e.what();
    const std::size_t at = error.find(": /");
    if (at != std::string::npos) {
      const std::size_t end = error.find(": ", at + 2);
      const std::string pointer = error.substr(at + 2, end - at - 2);
      int i = -1, j = -1;
      if (std::sscanf(pointer.c_str(), "/A/%d/%d", &i, &j) == 2)
        error_row = i, error_col = j;
      else if (std::sscanf(pointer.c_str(), "/b/%d", &i) == 1)
        error_row = i;
      error = end == std::string::npos ? error : error.substr(end + 2);
    }
  }
}

std::string run_beside(const ButcherTableau& tableau, app::Session& session) {
  std::string why;
  for (int k = 1; k <= 32; ++k) {
    const std::string name =
        k == 1 ? "mine" : "mine-" + std::to_string(k);  // not shown: a method's name
    try {
      // The lanes' rows and the new method's (a mass-spring scene's row k is Method k).
      const int m = static_cast<int>(add_tableau_method(tableau, name));
      std::vector<int> lanes;
      for (const app::Lane& l : session.lanes()) lanes.push_back(session.kind().row_of(l));
      if (std::find(lanes.begin(), lanes.end(), m) == lanes.end()) {
        if (lanes.size() >= app::Session::kMaxLanes) lanes.pop_back();
        lanes.push_back(m);
      }
      session.set_compare_rows(lanes);
      return format_text(tr("running as '%s' beside the other lanes"), name.c_str());
    } catch (const InputError& e) {
      why = e.what();  // the name is another tableau's (a row is never replaced): the next one
    }
  }
  return why;
}

namespace {

// The grid: c (the row sums, as the steps use them), A's lower triangle and diagonal, then b; the
// cell an error points at in red.
void tableau_grid(TableauPanel& panel, float scale) {
  const float cell = 62.0f * scale;
  const ImVec4 red(0.65f, 0.12f, 0.10f, 1.0f);
  if (ImGui::BeginTable("tableau", panel.stages + 1, ImGuiTableFlags_SizingFixedFit)) {
    for (int i = 0; i <= panel.stages; ++i) {
      const bool weights = i == panel.stages;
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      if (weights)
        ImGui::TextUnformatted("b");
      else if (panel.tableau)
        ImGui::TextDisabled("c%d = %s", i + 1,
                            panel.tableau->c[static_cast<std::size_t>(i)].text.c_str());
      else
        ImGui::TextDisabled("c%d", i + 1);
      for (int j = 0; j < panel.stages; ++j) {
        ImGui::TableNextColumn();
        if (!weights && j > i) {  // above the diagonal: diagonally implicit at most
          ImGui::TextDisabled("  .");
          continue;
        }
        TableauPanel::Cell& c = weights ? panel.b[j] : panel.a[i][j];
        const bool bad = weights ? panel.error_row == j && panel.error_col < 0
                                 : panel.error_row == i && panel.error_col == j;
        if (bad) ImGui::PushStyleColor(ImGuiCol_FrameBg, red);
        ImGui::SetNextItemWidth(cell);
        const std::string id = "##" + std::to_string(i) + "_" + std::to_string(j);
        if (ImGui::InputText(id.c_str(), c.data(), c.size())) panel.dirty = true;
        if (bad) ImGui::PopStyleColor();
      }
    }
    ImGui::EndTable();
  }
}

// What the cells make, at once: the order, exactly, the first condition failed, R(z) and its
// stretch of each axis; or the error.
void tableau_verdict(const TableauPanel& panel) {
  const float wrap = ImGui::GetContentRegionAvail().x;
  if (!panel.error.empty()) {
    text_wrapped(panel.error, ImVec4(1.0f, 0.45f, 0.40f, 1.0f), wrap);
  } else if (panel.analysis && panel.tableau) {
    const TableauAnalysis& a = *panel.analysis;
    std::string order = format_text(a.order == TableauAnalysis::kMaxOrder
                                        ? tr("order %d or more, exactly (%d conditions checked)")
                                        : tr("order %d, exactly (%d conditions checked)"),
                                    a.order, a.conditions);
    if (a.order_to_rounding > a.order)
      order += format_text(tr("; %d to rounding"), a.order_to_rounding);
    text_wrapped(
        (panel.tableau->is_explicit() ? tr("explicit, ") : tr("diagonally implicit, ")) + order, {},
        wrap);
    if (a.first_failure) {
      const OrderCondition& f = *a.first_failure;
      text_wrapped(
          format_text(tr("fails at order %d, tree %s: %s = %s, but this tableau gives %s"), f.order,
                      f.tree.c_str(), f.formula.c_str(), f.rhs.c_str(), f.lhs.c_str()),
          {}, wrap);
    }
    text_wrapped("R(z) = " + stability_function_text(a), {}, wrap);
    const std::string real = std::isinf(a.real_limit) ? tr("the whole negative real axis")
                             : a.real_limit == 0.0
                                 ? tr("no part of the negative real axis")
                                 : "[-" + axis_limit_text(a.real_limit, 4) + ", 0]";
    const std::string imaginary = std::isinf(a.imaginary_limit) ? tr("the whole imaginary axis")
                                  : a.imaginary_limit == 0.0
                                      ? tr("the imaginary axis only at 0")
                                      : "[-" + axis_limit_text(a.imaginary_limit, 4) + "i, " +
                                            axis_limit_text(a.imaginary_limit, 4) + "i]";
    text_wrapped(format_text(tr("|R| <= 1 on %s, and on %s"), real.c_str(), imaginary.c_str()), {},
                 wrap);
    for (const std::string& w : a.warnings) ImGui::TextDisabled("%s", w.c_str());
  }
}

}  // namespace

void draw_tableau_panel(TableauPanel& panel, app::Session& session,
                        const std::vector<std::string>& shipped, float scale) {
  if (!panel.open) return;
  // Beside the left panel, opaque (the cells are read, not the scene through them).
  ImGui::SetNextWindowPos(ImVec2(380.0f * scale, 20.0f * scale), ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(ImVec2(560.0f * scale, 430.0f * scale), ImGuiCond_Appearing);
  ImGui::SetNextWindowBgAlpha(0.97f);
  if (!ImGui::Begin((tr("Your method (Y)") + std::string("###tableau")).c_str(), &panel.open,
                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  // Start from a shipped tableau.
  ImGui::SetNextItemWidth(170.0f * scale);
  if (ImGui::BeginCombo(tr("start from"), panel.name.c_str())) {
    for (const std::string& n : shipped)
      if (ImGui::Selectable(n.c_str())) {
        try {
          panel.load(load_tableau_file(app::resolve_tableau(n)));
        } catch (const InputError& e) {
          panel.error = e.what();
        }
      }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90.0f * scale);
  if (ImGui::InputInt(tr("stages"), &panel.stages)) {
    panel.stages = std::clamp(panel.stages, 1, TableauPanel::kMaxStages);
    panel.dirty = true;
  }
  if (panel.dirty) panel.check();

  tableau_grid(panel, scale);
  ImGui::TextDisabled(tr("entries: 1/6, -2, 0.25; the diagonal makes a stage implicit"));
  ImGui::Separator();

  tableau_verdict(panel);

  ImGui::BeginDisabled(!panel.tableau);
  if (ImGui::Button(tr("Run beside")) && panel.tableau)
    panel.run_message = run_beside(*panel.tableau, session);
  ImGui::EndDisabled();
  if (!panel.run_message.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", panel.run_message.c_str());
  }
  ImGui::End();
}

}  // namespace springlab::ui
