// From a Session to a Frame: springs coloured by strain (or by method in compare mode),
// particles (pinned ones ringed, the held one highlighted), cloth and box surfaces, colliders,
// trails. Plain data in, plain data out.
#pragma once

#include "draw/frame.hpp"
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

  // Defaults for a scene: a surface hides the springs and particles it is made of.
  static ViewOptions for_scene(const Scene& scene);
};

// `viewport`: where in the framebuffer the scene goes (the whole of it when empty).
Frame build_frame(const app::Session& session, const ViewOptions& options, Viewport viewport);

}  // namespace springlab::draw
