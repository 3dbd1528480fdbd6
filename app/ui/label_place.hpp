// Where the scene's labels go (ui/overlay.hpp): a legend or a view's title in the corner of its
// view that covers least of what the view draws. A rope starts along the top of its view and a
// thrown cloth crosses it, so no one corner is always clear (a diverged rope lay under its title).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "draw/lane_views.hpp"

namespace springlab::ui {

struct Box {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool meets(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
  bool holds(const Eigen::Vector2f& p) const {
    return p.x() >= x0 && p.x() <= x1 && p.y() >= y0 && p.y() <= y1;
  }
};

enum class Corner { TopLeft, TopRight, BottomLeft, BottomRight };

// What a view draws, as points in the views' units: its lanes' bodies, and the trails behind
// them (a label may cover a trail sooner than a body).
struct Drawn {
  std::vector<Eigen::Vector2f> body, trails;
};

// The box of a width x height label in a corner of `room` (a view less its margins): the first
// of `order` that covers the fewest body points, then the fewest trail points (ties: the
// earlier), and meets none of `blocked` (where every corner meets one, the first).
Box corner_box(const Box& room, float width, float height, const Drawn& drawn,
               const std::vector<Box>& blocked, const std::vector<Corner>& order);

// What a view draws of its lanes: each lane's particles as drawn (its last sane state where it
// diverged; those alive where the scene emits them) and points along its springs, at most about
// 4000 a lane; with `trails`, points along its trails.
Drawn drawn_points(const app::Session& session, const draw::LaneView& view, bool trails);

}  // namespace springlab::ui
