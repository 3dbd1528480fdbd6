// From a Session to a Frame: springs coloured by strain (or by method in compare mode),
// particles (pinned ones ringed, the held one highlighted), cloth and box surfaces, colliders,
// trails. Plain data in, plain data out.
#pragma once

#include "draw/frame.hpp"
#include "draw/lane_views.hpp"
#include "session/session.hpp"

namespace springlab::draw {

struct ViewOptions {
  Camera camera;
  bool springs = true;
  bool particles = true;  // all of them; else only the pinned, held and watched ones
  bool surfaces = true;
  bool trails = true;
  double strain_scale = 0.02;  // the strain at which the colour map saturates
  double spacing = 0.1;        // the scene's typical spring length, sizes particles and lines
  // The mode that limits each lane's method (stability.hpp): an arrow at every particle, its
  // displacement in that mode, the largest three spacings long, so that a class sees which motion
  // blows up first.
  bool mode = false;
  float line_scale = 1.0f;                              // presentation mode draws lines thicker
  CompareLayout compare_layout = CompareLayout::Apart;  // compare's lanes: a view each, or one

  // Defaults for a scene: a surface hides the springs and particles it is made of.
  static ViewOptions for_scene(const Scene& scene);
};

// The frames of a session's views (lane_views.hpp, as options.compare_layout lays them) in
// `viewport`, where in the framebuffer the scene goes. A lane that diverged is drawn as its last
// sane state (Lane::sane), faded: never its blown-up geometry.
std::vector<Frame> build_frames(const app::Session& session, const ViewOptions& options,
                                Viewport viewport);
// One view's frame: its lanes, with its camera.
Frame build_frame(const app::Session& session, const ViewOptions& options, const LaneView& view);
// Every lane in one view of `viewport`.
Frame build_frame(const app::Session& session, const ViewOptions& options, Viewport viewport);

// Where a lane is, for a label beside it: the top of its bounding box (the sane state's for a
// lane that diverged).
Eigen::Vector3d label_anchor(const app::Lane& lane);

}  // namespace springlab::draw
