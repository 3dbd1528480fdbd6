#include "ui/label_place.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#include "draw/camera.hpp"
#include "session/mass_spring_kind.hpp"

namespace springlab::ui {

Box corner_box(const Box& room, float width, float height, const Drawn& drawn,
               const std::vector<Box>& blocked, const std::vector<Corner>& order) {
  const auto at = [&](Corner c) {
    const bool right = c == Corner::TopRight || c == Corner::BottomRight;
    const bool bottom = c == Corner::BottomLeft || c == Corner::BottomRight;
    const float x = right ? room.x1 - width : room.x0;
    const float y = bottom ? room.y1 - height : room.y0;
    return Box{x, y, x + width, y + height};
  };
  std::optional<Box> best;
  std::pair<long, long> least;
  for (const Corner c : order) {
    const Box box = at(c);
    if (std::any_of(blocked.begin(), blocked.end(), [&](const Box& b) { return b.meets(box); }))
      continue;
    const auto covered = [&](const std::vector<Eigen::Vector2f>& points) {
      return static_cast<long>(std::count_if(
          points.begin(), points.end(), [&](const Eigen::Vector2f& p) { return box.holds(p); }));
    };
    const std::pair<long, long> here{covered(drawn.body), covered(drawn.trails)};
    if (!best || here < least) best = box, least = here;
  }
  return best.value_or(at(order.front()));
}

Drawn drawn_points(const app::Session& session, const draw::LaneView& view, bool trails) {
  constexpr int kMost = 4000;
  Drawn drawn;
  const draw::Viewport& vp = view.viewport;
  const auto to = [&](std::vector<Eigen::Vector2f>& points) {
    return [&](const Vec3& x) {
      const Eigen::Vector3d p = draw::project(view.view, x, vp.width, vp.height);
      if (p.z() >= 0.0 && p.z() <= 1.0)
        points.emplace_back(vp.x + static_cast<float>(p.x()), vp.y + static_cast<float>(p.y()));
    };
  };
  const auto add = to(drawn.body);
  const auto add_trail = to(drawn.trails);
  for (const int k : view.lanes) {
    const app::Lane& lane = session.lanes()[k];
    const Model& m = lane.sim.model();
    const State& s = lane.shown();
    const bool emits = !m.emitters.empty();
    const int n = s.particle_count(), springs = m.spring_count();
    // Along each spring, where there are few (a spring's line is most of what the view shows);
    // else every particle, or a stride through them.
    const int along = springs > 0 && springs * 8 <= kMost ? 8 : 0;
    for (int j = 0; j < springs && along > 0; ++j)
      for (int t = 1; t < along; ++t) {
        const double f = static_cast<double>(t) / along;
        add((1 - f) * s.x.row(m.spring_a[j]).transpose() + f * s.x.row(m.spring_b[j]).transpose());
      }
    const int stride = std::max(1, n / kMost);
    for (int i = 0; i < n; i += stride)
      if (!emits || lane.sim.emission().alive(i)) add(s.x.row(i).transpose());
    // Its trails (drawn where the view shows them; a label over one hides where a particle went).
    if (const app::MassSpringLane* part = app::mass_spring_lane(lane); part && trails)
      for (const auto& trail : part->trails)
        for (std::size_t k = 0; k < trail.size(); k += std::max<std::size_t>(1, trail.size() / 500))
          add_trail(trail[k]);
  }
  return drawn;
}

}  // namespace springlab::ui
