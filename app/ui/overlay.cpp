#include "ui/overlay.hpp"

#include <imgui.h>

#include <algorithm>

#include "draw/palette.hpp"

namespace springlab::ui {

namespace {
ImU32 u32(const draw::Rgba& c) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, c.a)); }
}  // namespace

void draw_overlay(const app::Session& session, const draw::Viewport& viewport, float scale,
                  const std::string& scene_name, bool caption) {
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  const float pad = 10.0f * scale, line = ImGui::GetTextLineHeightWithSpacing();
  const ImU32 text = IM_COL32(240, 242, 245, 255), back = IM_COL32(10, 12, 14, 190);

  if (caption) {
    char s[256];
    const auto& lanes = session.lanes();
    if (const auto& ik = lanes.front().ik; ik && !session.comparing())
      std::snprintf(s, sizeof s, "%s  |  %s  |  iteration %d, error %.3g m%s", scene_name.c_str(),
                    ik_solver_info(ik->solver).label, ik->status.iterations, ik->status.error,
                    ik->status.reachable ? "" : "  |  target out of reach");
    else
      std::snprintf(s, sizeof s, "%s  |  %s  |  t = %.3f s", scene_name.c_str(),
                    session.comparing() ? "compare" : method_info(session.method()).label, lanes.front().sim.state().t);
    const ImVec2 size = ImGui::CalcTextSize(s);
    const ImVec2 p(viewport.x + pad, viewport.y + viewport.height - pad - size.y);
    dl->AddRectFilled(ImVec2(p.x - 6, p.y - 3), ImVec2(p.x + size.x + 6, p.y + size.y + 3), back, 4.0f);
    dl->AddText(p, text, s);
  }

  if (!session.comparing()) return;
  std::vector<std::string> rows;
  float width = 0.0f;
  for (const app::Lane& lane : session.lanes()) {
    std::string row = lane.ik ? ik_solver_info(lane.ik->solver).label : method_info(lane.sim.settings().method).label;
    if (lane.ik) {
      char s[96];
      std::snprintf(s, sizeof s, "  %d it., error %.2g m%s", lane.ik->status.iterations, lane.ik->status.error,
                    lane.ik->status.converged ? "" : lane.ik->status.stalled ? " (stuck)" : "");
      row += s;
    }
    if (lane.sim.diverged()) {
      char s[64];
      std::snprintf(s, sizeof s, "  diverged at t = %.3g s", lane.sim.divergence()->t);
      row += s;
    }
    width = std::max(width, ImGui::CalcTextSize(row.c_str()).x);
    rows.push_back(row);
  }
  const float swatch = 22.0f * scale;
  const ImVec2 p(viewport.x + viewport.width - pad - width - swatch - 10.0f * scale, viewport.y + pad);
  dl->AddRectFilled(ImVec2(p.x - 8, p.y - 4), ImVec2(viewport.x + viewport.width - pad + 4, p.y + rows.size() * line + 2),
                    back, 4.0f);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const app::Lane& lane = session.lanes()[k];
    const float y = p.y + k * line;
    draw::Rgba c = lane.ik ? draw::solver_color(lane.ik->solver) : draw::method_color(lane.sim.settings().method);
    dl->AddLine(ImVec2(p.x, y + 0.5f * line), ImVec2(p.x + swatch, y + 0.5f * line), u32(c), 4.0f * scale);
    if (lane.sim.diverged()) c = {1.0f, 0.45f, 0.4f, 1.0f};
    dl->AddText(ImVec2(p.x + swatch + 8.0f * scale, y), lane.sim.diverged() ? u32(c) : text, rows[k].c_str());
  }
}

}  // namespace springlab::ui
