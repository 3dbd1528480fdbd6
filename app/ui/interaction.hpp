// Mouse interaction with the scene, apart from any window: picking the particle under the
// pointer, dragging it across a plane that faces the camera, orbiting, panning and zooming the
// camera. The window turns mouse events into these calls; the tests call them directly.
#pragma once

#include <optional>

#include "draw/camera.hpp"
#include "session/session.hpp"

namespace springlab::ui {

// A pointer position in framebuffer pixels from the top-left.
struct Pointer {
  double x = 0, y = 0;
};

struct Drag {
  int particle = -1;
  int lane = 0;  // the lane it was picked in (compare apart: the view's), whose view moves it
  Vec3 plane_point = Vec3::Zero();    // the plane the particle moves in: through where it was
  Vec3 plane_normal = Vec3::UnitZ();  // grabbed, facing the camera
};

// Picks the particle of `lane` nearest the eye among those within `radius_px` pixels of the
// pointer and grabs it (in every lane). Returns the drag, or nothing when no particle is there.
std::optional<Drag> press(app::Session& session, const draw::ViewCamera& camera,
                          const draw::Viewport& viewport, Pointer pointer, double radius_px = 14.0,
                          int lane = 0);
// Moves the held particle to where the pointer's ray meets the drag plane.
void move(app::Session& session, const draw::ViewCamera& camera, const draw::Viewport& viewport,
          Pointer pointer, const Drag& drag);
// Lets go: the particle keeps the velocity it was being dragged with.
void release(app::Session& session);

// A particle held and moved by keys, as a drag holds and moves it (the panels' "A particle by
// keys", the browser's document): held where it is (false: no such particle), then moved a
// twentieth of the scene's extent at its start a press, along the world's x and y (the plane
// the 2D scenes are drawn in).
bool hold(app::Session& session, int particle);
void nudge(app::Session& session, double dx, double dy);

// The camera, by pixels of mouse motion and wheel notches.
void orbit(Camera& camera, double dx, double dy);  // 3D only
void pan(Camera& camera, const draw::ViewCamera& view, double dx, double dy);
void zoom(Camera& camera, double notches);

}  // namespace springlab::ui
