#include "ui/overlay.hpp"
#include "ui/kind_panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "draw/camera.hpp"
#include "draw/palette.hpp"
#include "draw/scene_frame.hpp"
#include "springlab/text.hpp"

namespace springlab::ui {

namespace {
ImU32 u32(const draw::Rgba& c) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, c.a)); }


const ImU32 kText = IM_COL32(240, 242, 245, 255), kBack = IM_COL32(10, 12, 14, 190);

// The compare legend, top right: each lane's colour, name and its own clock (a lane that diverged
// stopped).
struct Legend {
  std::vector<std::string> rows;
  ImVec2 at;     // the first row's swatch
  ImVec4 box;    // its background: x0, y0, x1, y1
};

Legend legend_of(const app::Session& session, const draw::Viewport& viewport, float scale) {
  const float pad = 10.0f * scale, line = ImGui::GetTextLineHeightWithSpacing();
  Legend legend;
  float width = 0.0f;
  for (const app::Lane& lane : session.lanes()) {
    const std::string row = app::lane_label(lane) + kind_panels(session.kind()).progress(lane);
    width = std::max(width, ImGui::CalcTextSize(row.c_str()).x);
    legend.rows.push_back(row);
  }
  const float swatch = 22.0f * scale;
  legend.at = ImVec2(viewport.x + viewport.width - pad - width - swatch - 10.0f * scale, viewport.y + pad);
  legend.box = ImVec4(legend.at.x - 8, legend.at.y - 4, viewport.x + viewport.width - pad + 4,
                      legend.at.y + legend.rows.size() * line + 2);
  return legend;
}

void draw_legend(const app::Session& session, const Legend& legend, float scale) {
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  const float line = ImGui::GetTextLineHeightWithSpacing(), swatch = 22.0f * scale;
  dl->AddRectFilled(ImVec2(legend.box.x, legend.box.y), ImVec2(legend.box.z, legend.box.w), kBack, 4.0f);
  for (std::size_t k = 0; k < legend.rows.size(); ++k) {
    const app::Lane& lane = session.lanes()[k];
    const float y = legend.at.y + k * line;
    const draw::Rgba c = draw::lane_color(lane);
    dl->AddLine(ImVec2(legend.at.x, y + 0.5f * line), ImVec2(legend.at.x + swatch, y + 0.5f * line), u32(c),
                4.0f * scale);
    dl->AddText(ImVec2(legend.at.x + swatch + 8.0f * scale, y), lane.sim.trouble() ? u32(draw::kDiverged) : kText,
                legend.rows[k].c_str());
  }
}
}  // namespace

// The mass-spring kind's words (kind_panels.hpp): its method and time, or where it diverged.
std::string mass_spring_caption(const app::Session& session, const std::string& scene_name, const std::string& slow) {
  char s[320];
  std::snprintf(s, sizeof s, "%s  |  %s  |  t = %.3f s%s%s", scene_name.c_str(), app::lane_label(session.primary()).c_str(),
                session.primary().sim.state().t, slow.empty() ? "" : "  |  ", slow.c_str());
  return s;
}

std::string mass_spring_progress(const app::Lane& lane) {
  char s[96];
  if (const Divergence* trouble = lane.sim.trouble())
    std::snprintf(s, sizeof s, tr("  %s at t = %.3g s"), trouble->unstable ? tr("went unstable") : tr("diverged"), trouble->t);
  else
    std::snprintf(s, sizeof s, "  t = %.3f s", lane.sim.state().t);
  return s;
}

std::string realtime_text(double realtime) {
  if (!(realtime < 0.95)) return "";
  char s[48];
  std::snprintf(s, sizeof s, tr("%.2gx real time"), realtime);
  return s;
}

void draw_overlay(const app::Session& session, const draw::ViewCamera& camera, const draw::Viewport& viewport,
                  const std::string& scene_name, const OverlayOptions& options) {
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  const float scale = options.scale;
  const float pad = 10.0f * scale;
  const ImU32 text = kText, back = kBack;
  const ImU32 red = u32(draw::kDiverged);

  if (options.caption) {
    char s[320];
    const std::string slow = realtime_text(options.realtime);
    if (session.comparing())
      std::snprintf(s, sizeof s, "%s  |  %s  |  t = %.3f s%s%s", scene_name.c_str(), tr("compare"),
                    session.simulated_target(), slow.empty() ? "" : "  |  ", slow.c_str());
    else
      std::snprintf(s, sizeof s, "%s", kind_panels(session.kind()).caption(session, scene_name, slow).c_str());
    const ImVec2 size = ImGui::CalcTextSize(s);
    const ImVec2 p(viewport.x + pad, viewport.y + viewport.height - pad - size.y);
    dl->AddRectFilled(ImVec2(p.x - 6, p.y - 3), ImVec2(p.x + size.x + 6, p.y + size.y + 3), back, 4.0f);
    dl->AddText(p, text, s);
  }

  // A lane waiting for its stability analysis (its sub-steps are chosen from it).
  bool waiting = false;
  for (const app::Lane& lane : session.lanes()) waiting |= session.background_analysis() && lane.waiting();
  if (waiting) {
    const char* s = tr("analysing stability: choosing the sub-steps...");
    const ImVec2 size = ImGui::CalcTextSize(s);
    const ImVec2 p(viewport.x + 0.5f * (viewport.width - size.x), viewport.y + 0.45f * viewport.height);
    dl->AddRectFilled(ImVec2(p.x - 8, p.y - 4), ImVec2(p.x + size.x + 8, p.y + size.y + 4), back, 4.0f);
    dl->AddText(p, text, s);
  }

  // A red label beside each lane that diverged, at the top of its last sane state (one under
  // another, or under the legend, where they would overlap).
  std::optional<Legend> legend;
  if (session.comparing()) legend = legend_of(session, viewport, scale);
  std::vector<ImVec4> placed;
  if (legend) placed.push_back(legend->box);
  for (const app::Lane& lane : session.lanes()) {
    const Divergence* trouble = lane.sim.trouble();
    if (!trouble) continue;
    char s[160];
    std::snprintf(s, sizeof s, tr("%s %s at t = %.3g s"), app::lane_label(lane).c_str(),
                  trouble->unstable ? tr("went unstable") : tr("diverged"), trouble->t);
    const Eigen::Vector3d at = draw::project(camera, draw::label_anchor(lane), viewport.width, viewport.height);
    const ImVec2 size = ImGui::CalcTextSize(s);
    float x = viewport.x + static_cast<float>(at.x()) - 0.5f * size.x;
    float y = viewport.y + static_cast<float>(at.y()) - size.y - 8.0f * scale;
    x = std::clamp(x, viewport.x + pad, viewport.x + viewport.width - pad - size.x);
    y = std::clamp(y, viewport.y + pad, viewport.y + viewport.height - pad - size.y);
    // Its background (5 px either side, 2 above and below) clear of every one placed: moved under
    // the one it meets, 2 px apart (each move passes one box for good, so at most one a box).
    for (std::size_t moves = 0; moves <= placed.size(); ++moves) {
      const auto meets = [&](const ImVec4& r) {
        return x - 5 < r.z && x + size.x + 5 > r.x && y - 2 < r.w && y + size.y + 2 > r.y;
      };
      const auto hit = std::find_if(placed.begin(), placed.end(), meets);
      if (hit == placed.end()) break;
      y = hit->w + 4.0f;
    }
    placed.push_back(ImVec4(x - 5, y - 2, x + size.x + 5, y + size.y + 2));
    dl->AddRectFilled(ImVec2(x - 5, y - 2), ImVec2(x + size.x + 5, y + size.y + 2), back, 4.0f);
    dl->AddText(ImVec2(x, y), red, s);
  }

  if (legend) draw_legend(session, *legend, scale);
}

}  // namespace springlab::ui
