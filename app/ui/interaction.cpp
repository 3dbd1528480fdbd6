#include "ui/interaction.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace springlab::ui {

namespace {

draw::Ray ray_at(const draw::ViewCamera& camera, const draw::Viewport& viewport, Pointer p) {
  return draw::pixel_ray(camera, p.x - viewport.x, p.y - viewport.y, viewport.width,
                         viewport.height);
}

}  // namespace

std::optional<Drag> press(app::Session& session, const draw::ViewCamera& camera,
                          const draw::Viewport& viewport, Pointer pointer, double radius_px,
                          int lane) {
  if (pointer.x < viewport.x || pointer.y < viewport.y ||
      pointer.x >= viewport.x + viewport.width || pointer.y >= viewport.y + viewport.height)
    return std::nullopt;
  // Nearest in screen space among the particles within reach of the pointer, the front one on ties.
  const app::Lane& picked =
      session.lanes()[std::clamp<std::size_t>(lane, 0, session.lanes().size() - 1)];
  const State& s = picked.shown();
  int best = -1;
  double best_d2 = radius_px * radius_px, best_depth = 2.0;
  for (int i = 0; i < s.particle_count(); ++i) {
    const Eigen::Vector3d q =
        draw::project(camera, s.x.row(i).transpose(), viewport.width, viewport.height);
    if (q.z() < 0.0 || q.z() > 1.0) continue;  // behind the eye or past the far plane
    const double dx = q.x() + viewport.x - pointer.x, dy = q.y() + viewport.y - pointer.y;
    const double d2 = dx * dx + dy * dy;
    if (d2 < best_d2 - 1e-9 || (d2 <= best_d2 + 1e-9 && q.z() < best_depth)) {
      best = i;
      best_d2 = d2;
      best_depth = q.z();
    }
  }
  if (best < 0) return std::nullopt;
  Drag drag;
  drag.particle = best;
  drag.lane = lane;
  drag.plane_point = s.x.row(best).transpose();
  const draw::Ray r = ray_at(camera, viewport, pointer);
  drag.plane_normal = -r.direction;
  session.grab(best);
  return drag;
}

void move(app::Session& session, const draw::ViewCamera& camera, const draw::Viewport& viewport,
          Pointer pointer, const Drag& drag) {
  const draw::Ray r = ray_at(camera, viewport, pointer);
  const double denom = r.direction.dot(drag.plane_normal);
  if (std::abs(denom) < 1e-9) return;
  const double t = (drag.plane_point - r.origin).dot(drag.plane_normal) / denom;
  if (t <= 0.0) return;
  session.drag_to(r.origin + t * r.direction);
}

void release(app::Session& session) {
  session.release();
}

bool hold(app::Session& session, int particle) {
  if (particle < 0 || particle >= session.primary().sim.state().particle_count()) return false;
  session.grab(particle);
  session.drag_to(session.primary().sim.state().x.row(particle).transpose());
  return true;
}

void nudge(app::Session& session, double dx, double dy) {
  if (session.grabbed() < 0 || !session.drag_target()) return;
  const Points& x = session.scene().state.x;
  const double extent =
      x.rows() == 0 ? 0.0 : (x.colwise().maxCoeff() - x.colwise().minCoeff()).norm();
  const double step = extent > 0.0 ? extent / 20.0 : 0.05;
  session.drag_to(*session.drag_target() + step * Vec3(dx, dy, 0.0));
}

void orbit(Camera& camera, double dx, double dy) {
  if (camera.view == View::Planar) return;
  camera.yaw = std::fmod(camera.yaw - 0.3 * dx, 360.0);
  camera.pitch = std::clamp(camera.pitch + 0.3 * dy, -89.0, 89.0);
}

void pan(Camera& camera, const draw::ViewCamera& view, double dx, double dy) {
  // Along the view's right and up vectors, one pixel of motion moving the scene one pixel.
  const Eigen::Vector3d right = view.view.row(0).head<3>().cast<double>();
  const Eigen::Vector3d up = view.view.row(1).head<3>().cast<double>();
  camera.target += (-dx * right + dy * up) * view.world_per_pixel;
}

void zoom(Camera& camera, double notches) {
  const double factor = std::pow(0.88, notches);
  if (camera.view == View::Planar)
    camera.height = std::clamp(camera.height * factor, 1e-3, 1e6);
  else
    camera.distance = std::clamp(camera.distance * factor, 1e-3, 1e6);
}

}  // namespace springlab::ui
