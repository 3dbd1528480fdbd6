#include "draw/lane_views.hpp"

#include <algorithm>
#include <cmath>

#include "draw/camera.hpp"
#include "springlab/error.hpp"

namespace springlab::draw {

namespace {

// The shape the shipped scenes are framed for: a tile narrower than it shows the scene's camera
// farther back, so that the whole width a frame shows is in every tile.
constexpr double kFramed = 16.0 / 9.0;

Camera framed(Camera camera, double aspect) {
  const double back = std::max(1.0, kFramed / aspect);
  if (camera.view == View::Planar)
    camera.height *= back;
  else
    camera.distance *= back;
  return camera;
}

}  // namespace

const char* layout_name(CompareLayout layout) {
  return layout == CompareLayout::Apart ? "apart" : "together";
}

CompareLayout parse_compare_layout(std::string_view text, const std::string& what) {
  if (text == "apart") return CompareLayout::Apart;
  if (text == "together") return CompareLayout::Together;
  throw InputError(what + ": must be apart (a view each) or together (one view), got '" +
                   std::string(text) + "'");
}

std::vector<LaneView> lane_views(const app::Session& session, const Camera& camera,
                                 CompareLayout layout, Viewport viewport, float gap) {
  const int n = static_cast<int>(session.lanes().size());
  std::vector<LaneView> views;
  if (n <= 1 || layout == CompareLayout::Together || viewport.width <= 0 || viewport.height <= 0) {
    // (Framed too: a small laptop's or a phone's scene, narrower than 16:9, cut the rope's end.)
    LaneView v;
    v.viewport = viewport;
    v.camera = viewport.width > 0 && viewport.height > 0
                   ? framed(camera, static_cast<double>(viewport.width) / viewport.height)
                   : camera;
    v.view = view_camera(v.camera, std::max(1, viewport.width), std::max(1, viewport.height));
    for (int k = 0; k < n; ++k) v.lanes.push_back(k);
    views.push_back(std::move(v));
    return views;
  }
  // The grid whose tiles hold the largest 16:9 box (no empty row or column).
  int best_cols = n, best_rows = 1;
  double best = -1.0;
  for (int cols = n; cols >= 1; --cols) {
    const int rows = (n + cols - 1) / cols;
    if ((rows - 1) * cols >= n) continue;
    const double w = (viewport.width - (cols - 1) * gap) / cols,
                 h = (viewport.height - (rows - 1) * gap) / rows;
    const double size = std::min(h, w / kFramed);
    if (size > best * (1.0 + 1e-9)) best = size, best_cols = cols, best_rows = rows;
  }
  const double w = (viewport.width - (best_cols - 1) * gap) / best_cols;
  const double h = (viewport.height - (best_rows - 1) * gap) / best_rows;
  for (int k = 0; k < n; ++k) {
    const int row = k / best_cols, col = k % best_cols;
    const int in_row = std::min(best_cols, n - row * best_cols);
    const double shift = 0.5 * (best_cols - in_row) * (w + gap);  // the last row centred
    const int x0 = viewport.x + static_cast<int>(std::lround(shift + col * (w + gap)));
    const int x1 = viewport.x + static_cast<int>(std::lround(shift + col * (w + gap) + w));
    const int y0 = viewport.y + static_cast<int>(std::lround(row * (h + gap)));
    const int y1 = viewport.y + static_cast<int>(std::lround(row * (h + gap) + h));
    LaneView v;
    v.viewport = {x0, y0, std::max(1, x1 - x0), std::max(1, y1 - y0)};
    v.camera = framed(camera, static_cast<double>(v.viewport.width) / v.viewport.height);
    v.view = view_camera(v.camera, v.viewport.width, v.viewport.height);
    v.lanes = {k};
    views.push_back(std::move(v));
  }
  return views;
}

const LaneView* view_at(const std::vector<LaneView>& views, double x, double y) {
  for (const LaneView& v : views)
    if (x >= v.viewport.x && y >= v.viewport.y && x < v.viewport.x + v.viewport.width &&
        y < v.viewport.y + v.viewport.height)
      return &v;
  return nullptr;
}

const LaneView* view_of(const std::vector<LaneView>& views, int lane) {
  for (const LaneView& v : views)
    if (std::find(v.lanes.begin(), v.lanes.end(), lane) != v.lanes.end()) return &v;
  return nullptr;
}

}  // namespace springlab::draw
