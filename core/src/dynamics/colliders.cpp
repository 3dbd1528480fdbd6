#include "springlab/colliders.hpp"

#include <cmath>

namespace springlab {

namespace {

// Velocity response at a contact with outward unit normal n. Returns the kinetic energy lost.
double respond(Vec3& v, const Vec3& n, double friction, double restitution, double mass) {
  const double vn = v.dot(n);
  if (vn >= 0.0) return 0.0;  // separating: position correction only
  const double before = v.squaredNorm();
  const double dvn = -(1.0 + restitution) * vn;
  Vec3 vt = v - vn * n;
  const double speed_t = vt.norm();
  const double slow = friction * dvn;
  vt = speed_t <= slow ? Vec3::Zero() : Vec3((1.0 - slow / speed_t) * vt);
  v = vt + (vn + dvn) * n;
  return 0.5 * mass * (before - v.squaredNorm());
}

}  // namespace

ContactResult resolve_contacts(const Model& model, State& state) {
  ContactResult result;
  if (!model.has_colliders()) return result;
  for (int i = 0; i < model.particle_count(); ++i) {
    if (model.pinned(i)) continue;
    bool touched = false;
    for (const PlaneCollider& plane : model.planes) {
      Vec3 x = state.x.row(i).transpose();
      const double depth = (x - plane.point).dot(plane.normal) - model.particle_radius;
      if (depth >= 0.0) continue;
      Vec3 v = state.v.row(i).transpose();
      x -= depth * plane.normal;
      result.potential_gained += depth * model.mass[i] * model.gravity.dot(plane.normal);
      result.kinetic_lost +=
          respond(v, plane.normal, plane.friction, plane.restitution, model.mass[i]);
      state.x.row(i) = x.transpose();
      state.v.row(i) = v.transpose();
      touched = true;
    }
    for (const SphereCollider& sphere : model.spheres) {
      Vec3 x = state.x.row(i).transpose();
      const Vec3 r = x - sphere.center;
      const double dist = r.norm();
      const double reach = sphere.radius + model.particle_radius;
      if (dist >= reach) continue;
      // At the very centre any direction is as good: push out along +y.
      const Vec3 n = dist > 0.0 ? Vec3(r / dist) : Vec3::UnitY();
      Vec3 v = state.v.row(i).transpose();
      const Vec3 moved = sphere.center + reach * n - x;
      result.potential_gained -= model.mass[i] * model.gravity.dot(moved);
      x += moved;
      result.kinetic_lost += respond(v, n, sphere.friction, sphere.restitution, model.mass[i]);
      state.x.row(i) = x.transpose();
      state.v.row(i) = v.transpose();
      touched = true;
    }
    result.contacts += touched;
  }
  return result;
}

}  // namespace springlab
