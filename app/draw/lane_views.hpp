// Where compare's lanes are drawn: apart, a view each (tiles of the scene's viewport, each with
// the whole scene framed as for a 16:9 frame), so that lanes that agree never hide one another;
// or together, every lane in one view, each in its colour. One lane: one view, as ever.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "draw/frame.hpp"
#include "session/session.hpp"
#include "springlab/scene.hpp"

namespace springlab::draw {

enum class CompareLayout { Apart, Together };

const char* layout_name(CompareLayout layout);  // "apart", "together"
// From a name; `what` names the option in the message ("--compare-layout", "link: compare-layout").
CompareLayout parse_compare_layout(std::string_view text, const std::string& what);

// One view: its place in the framebuffer (pixels from the top-left), its camera, its lanes.
struct LaneView {
  Viewport viewport;
  Camera camera;    // the scene's camera, framing at least what a 16:9 frame shows of it
  ViewCamera view;  // its matrices for this viewport
  std::vector<int> lanes;
};

// The views of a session in `viewport`: one (one lane, or together), or one a lane (apart), in
// the grid of tiles that shows the scene largest (ties: more columns), the last row centred.
std::vector<LaneView> lane_views(const app::Session& session, const Camera& camera,
                                 CompareLayout layout, Viewport viewport, float gap = 2.0f);

// The view that holds a point (pixels, as the views' viewports), or none.
const LaneView* view_at(const std::vector<LaneView>& views, double x, double y);
// The view that draws a lane.
const LaneView* view_of(const std::vector<LaneView>& views, int lane);

}  // namespace springlab::draw
