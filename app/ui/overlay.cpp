#include "ui/overlay.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "chart/imgui_chart.hpp"
#include "chart/text_wrap.hpp"
#include "draw/camera.hpp"
#include "draw/marks.hpp"
#include "draw/palette.hpp"
#include "draw/scene_frame.hpp"
#include "springlab/text.hpp"
#include "ui/kind_panels.hpp"
#include "ui/label_place.hpp"

namespace springlab::ui {

namespace {
ImU32 u32(const draw::Rgba& c) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, c.a));
}

const ImU32 kText = IM_COL32(240, 242, 245, 255), kBack = IM_COL32(10, 12, 14, 190),
            kSeparator = IM_COL32(90, 96, 108, 255);

// All of it is the scene's: drawn under the windows (the stability region's over a view), in
// Dear ImGui's background draw list.

// The compare legend: each lane's colour, mark, name and its own clock (a lane that diverged
// stopped). Together: every lane's, top right of the scene. Apart: a view's own, at its top left.
// Either moves to another corner where that covers less of what the view draws.
struct Legend {
  std::vector<int> lanes;
  std::vector<std::string> rows;  // wrapped to the room there is
  std::vector<float> tops;        // each row's top, from the first's
  ImVec2 at;                      // the first row's swatch
  ImVec4 box;                     // its background: x0, y0, x1, y1
};

float swatch_width(float scale) {
  return 22.0f * scale;
}

// "; drawn as at 1.53 s" for a lane drawn as its last sane state, from a time before it diverged;
// "; blowing up: drawn as at 0.15 s" for one that left its bounds before the divergence test said.
std::string drawn_as(const app::Lane& lane) {
  char s[96];
  if (lane.blowing_up) {
    std::snprintf(s, sizeof s, tr("; blowing up: drawn as at %.3g s"), lane.sane.t);
    return s;
  }
  const Divergence* trouble = lane.sim.trouble();
  if (!trouble || !lane.sim.diverged() || !(lane.sane.t < trouble->t - 1e-9)) return "";
  std::snprintf(s, sizeof s, tr("; drawn as at %.3g s"), lane.sane.t);
  return s;
}

// `text` wrapped to `width` pixels in the current font.
std::string wrapped(const std::string& text, float width) {
  return wrap_text(text, ImGui::GetFont(), ImGui::GetFontSize(), std::max(width, 1.0f));
}

// Together, the legend of every lane; apart, a view's title: in the corner of the view that
// covers least of what it draws (ui/label_place.hpp), clear of `blocked` (the caption).
Legend legend_of(const app::Session& session, const draw::LaneView& view, bool together,
                 const std::vector<Box>& blocked, bool trails, float scale) {
  const std::vector<int>& lanes = view.lanes;
  const draw::Viewport& viewport = view.viewport;
  const float pad = 10.0f * scale, spacing = ImGui::GetStyle().ItemSpacing.y;
  const float swatch = swatch_width(scale);
  const float room = viewport.width - 2.0f * pad - 12.0f - swatch - 10.0f * scale;
  Legend legend;
  legend.lanes = lanes;
  float width = 0.0f, height = 0.0f;
  for (const int k : lanes) {
    const app::Lane& lane = session.lanes()[k];
    // A view's own title says too what it draws of a lane that diverged.
    const std::string row =
        wrapped(app::lane_label(lane) + kind_panels(session.kind()).progress(lane) +
                    (together ? "" : drawn_as(lane)),
                room);
    const ImVec2 size = ImGui::CalcTextSize(row.c_str());
    width = std::max(width, size.x);
    legend.tops.push_back(height);
    height += size.y + spacing;
    legend.rows.push_back(row);
  }
  const float inner = swatch + 10.0f * scale + width;
  using C = Corner;
  const std::vector<C> order =
      together ? std::vector<C>{C::TopRight, C::TopLeft, C::BottomRight, C::BottomLeft}
               : std::vector<C>{C::TopLeft, C::TopRight, C::BottomLeft, C::BottomRight};
  // (Its background reaches 8 left of the swatch and 4 right of the text, 4 above and 2 below.)
  const Box corners{viewport.x + pad, viewport.y + pad - 4.0f,
                    viewport.x + viewport.width - pad + 4.0f,
                    viewport.y + viewport.height - pad + 2.0f};
  const Box box = corner_box(corners, inner + 12.0f, height + 6.0f,
                             drawn_points(session, view, trails), blocked, order);
  legend.at = ImVec2(box.x0 + 8, box.y0 + 4);
  legend.box = ImVec4(box.x0, box.y0, box.x1, box.y1);
  return legend;
}

void draw_legend(const app::Session& session, const Legend& legend, float scale) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const float line = ImGui::GetTextLineHeight(), swatch = swatch_width(scale);
  dl->AddRectFilled(ImVec2(legend.box.x, legend.box.y), ImVec2(legend.box.z, legend.box.w), kBack,
                    4.0f);
  for (std::size_t k = 0; k < legend.rows.size(); ++k) {
    const app::Lane& lane = session.lanes()[legend.lanes[k]];
    const float y = legend.at.y + legend.tops[k];
    const draw::Rgba c = draw::lane_color(lane);
    dl->AddLine(ImVec2(legend.at.x, y + 0.5f * line), ImVec2(legend.at.x + swatch, y + 0.5f * line),
                u32(c), 4.0f * scale);
    chart::draw_mark(dl, draw::lane_mark(lane),
                     ImVec2(legend.at.x + 0.5f * swatch, y + 0.5f * line), 4.5f * scale, u32(c));
    dl->AddText(ImVec2(legend.at.x + swatch + 8.0f * scale, y),
                lane.sim.trouble() || lane.blowing_up ? u32(draw::kDiverged) : kText,
                legend.rows[k].c_str());
  }
}

// A red label beside each lane that diverged, at the top of its last sane state (one under
// another, or under the legend, where they would overlap), with the time it is drawn at; apart,
// its view's title says it.
void draw_diverged_labels(ImDrawList* dl, const app::Session& session,
                          const std::vector<draw::LaneView>& views,
                          const std::vector<Legend>& legends, float scale) {
  const float pad = 10.0f * scale;
  const ImU32 back = kBack, red = u32(draw::kDiverged);
  std::vector<ImVec4> placed;
  placed.reserve(legends.size());
  for (const Legend& legend : legends) placed.push_back(legend.box);
  for (std::size_t index = 0; index < session.lanes().size() && views.size() == 1; ++index) {
    const app::Lane& lane = session.lanes()[index];
    const Divergence* trouble = lane.sim.trouble();
    const draw::LaneView* view = draw::view_of(views, static_cast<int>(index));
    if (!trouble || !view) continue;
    char s[200];
    std::snprintf(s, sizeof s, tr("%s %s at t = %.3g s"), app::lane_label(lane).c_str(),
                  trouble->unstable ? tr("went unstable") : tr("diverged"), trouble->t);
    const draw::Viewport& vp = view->viewport;
    const std::string label = wrapped(s + drawn_as(lane), vp.width - 2.0f * pad - 10.0f);
    const Eigen::Vector3d at =
        draw::project(view->view, draw::label_anchor(lane), vp.width, vp.height);
    const ImVec2 size = ImGui::CalcTextSize(label.c_str());
    float x = vp.x + static_cast<float>(at.x()) - 0.5f * size.x;
    float y = vp.y + static_cast<float>(at.y()) - size.y - 8.0f * scale;
    x = std::clamp(x, vp.x + pad, std::max(vp.x + pad, vp.x + vp.width - pad - size.x));
    y = std::clamp(y, vp.y + pad, vp.y + vp.height - pad - size.y);
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
    dl->AddText(ImVec2(x, y), red, label.c_str());
  }
}

}  // namespace

// The mass-spring kind's words (kind_panels.hpp): its method and time, or where it diverged.
std::string mass_spring_caption(const app::Session& session, const std::string& scene_name,
                                const std::string& slow) {
  char s[320];
  std::snprintf(s, sizeof s, "%s  |  %s  |  t = %.3f s%s%s", scene_name.c_str(),
                app::lane_label(session.primary()).c_str(), session.primary().sim.state().t,
                slow.empty() ? "" : "  |  ", slow.c_str());
  return s;
}

std::string mass_spring_progress(const app::Lane& lane) {
  char s[96];
  if (const Divergence* trouble = lane.sim.trouble())
    std::snprintf(s, sizeof s, tr("  %s at t = %.3g s"),
                  trouble->unstable ? tr("went unstable") : tr("diverged"), trouble->t);
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

void draw_overlay(const app::Session& session, const std::vector<draw::LaneView>& views,
                  const draw::Viewport& viewport, const std::string& scene_name,
                  const OverlayOptions& options) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const float scale = options.scale;
  const float pad = 10.0f * scale;
  const ImU32 text = kText, back = kBack;

  // Apart: a thin line between the views.
  if (views.size() > 1)
    for (const draw::LaneView& v : views) {
      const draw::Viewport& p = v.viewport;
      dl->AddRect(ImVec2(p.x - 1.0f, p.y - 1.0f),
                  ImVec2(p.x + p.width + 1.0f, p.y + p.height + 1.0f), kSeparator);
    }

  std::vector<Box> blocked;  // (the caption's, where there is one)
  if (options.caption) {
    char s[320];
    const std::string slow = realtime_text(options.realtime);
    if (session.comparing())
      std::snprintf(s, sizeof s, "%s  |  %s  |  t = %.3f s%s%s", scene_name.c_str(), tr("compare"),
                    session.simulated_target(), slow.empty() ? "" : "  |  ", slow.c_str());
    else
      std::snprintf(s, sizeof s, "%s",
                    kind_panels(session.kind()).caption(session, scene_name, slow).c_str());
    const ImVec2 size = ImGui::CalcTextSize(s);
    const ImVec2 p(viewport.x + pad, viewport.y + viewport.height - pad - size.y);
    dl->AddRectFilled(ImVec2(p.x - 6, p.y - 3), ImVec2(p.x + size.x + 6, p.y + size.y + 3), back,
                      4.0f);
    dl->AddText(p, text, s);
    blocked.push_back({p.x - 6, p.y - 3, p.x + size.x + 6, p.y + size.y + 3});
  }

  // A lane waiting for its stability analysis (its sub-steps are chosen from it).
  bool waiting = false;
  for (const app::Lane& lane : session.lanes())
    waiting |= session.background_analysis() && lane.waiting();
  if (waiting) {
    const char* s = tr("analysing stability: choosing the sub-steps...");
    const ImVec2 size = ImGui::CalcTextSize(s);
    const ImVec2 p(viewport.x + 0.5f * (viewport.width - size.x),
                   viewport.y + 0.45f * viewport.height);
    dl->AddRectFilled(ImVec2(p.x - 8, p.y - 4), ImVec2(p.x + size.x + 8, p.y + size.y + 4), back,
                      4.0f);
    dl->AddText(p, text, s);
  }

  // The legends: one for the lanes together, or a view's own title.
  std::vector<Legend> legends;
  if (session.comparing())
    for (const draw::LaneView& v : views)
      legends.push_back(legend_of(session, v, views.size() == 1, blocked, options.trails, scale));
  draw_diverged_labels(dl, session, views, legends, scale);

  for (const Legend& legend : legends) draw_legend(session, legend, scale);
}

}  // namespace springlab::ui
