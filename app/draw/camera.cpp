#include "draw/camera.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

namespace springlab::draw {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

Mat4f look_at(const Vec3f& eye, const Vec3f& target, const Vec3f& up) {
  const Vec3f f = (target - eye).normalized();
  const Vec3f s = f.cross(up).normalized();
  const Vec3f u = s.cross(f);
  Mat4f m = Mat4f::Identity();
  m.row(0) << s.x(), s.y(), s.z(), -s.dot(eye);
  m.row(1) << u.x(), u.y(), u.z(), -u.dot(eye);
  m.row(2) << -f.x(), -f.y(), -f.z(), f.dot(eye);
  return m;
}

Mat4f perspective(float fovy, float aspect, float near, float far) {
  const float t = 1.0f / std::tan(0.5f * fovy);
  Mat4f m = Mat4f::Zero();
  m(0, 0) = t / aspect;
  m(1, 1) = t;
  m(2, 2) = (far + near) / (near - far);
  m(2, 3) = 2.0f * far * near / (near - far);
  m(3, 2) = -1.0f;
  return m;
}

Mat4f orthographic(float half_w, float half_h, float near, float far) {
  Mat4f m = Mat4f::Identity();
  m(0, 0) = 1.0f / half_w;
  m(1, 1) = 1.0f / half_h;
  m(2, 2) = -2.0f / (far - near);
  m(2, 3) = -(far + near) / (far - near);
  return m;
}

}  // namespace

ViewCamera view_camera(const Camera& camera, int width, int height) {
  ViewCamera v;
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const Vec3f target = camera.target.cast<float>();
  if (camera.view == View::Planar) {
    const float half_h = static_cast<float>(camera.height) * 0.5f;
    v.orthographic = true;
    v.eye = target + Vec3f(0, 0, 100);
    v.view = look_at(v.eye, target, Vec3f::UnitY());
    v.projection = orthographic(half_h * aspect, half_h, 1.0f, 200.0f);
    v.world_per_pixel = static_cast<float>(camera.height) / static_cast<float>(height);
    return v;
  }
  const double yaw = camera.yaw * kDegree, pitch = camera.pitch * kDegree;
  const Vec3f offset = Eigen::Vector3d(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                                       std::cos(pitch) * std::cos(yaw))
                           .cast<float>() *
                       static_cast<float>(camera.distance);
  v.eye = target + offset;
  v.view = look_at(v.eye, target, Vec3f::UnitY());
  const float fovy = static_cast<float>(camera.fov * kDegree);
  const float d = static_cast<float>(camera.distance);
  v.projection = perspective(fovy, aspect, 0.02f * d, 50.0f * d);
  v.world_per_pixel = 2.0f * d * std::tan(0.5f * fovy) / static_cast<float>(height);
  return v;
}

Ray pixel_ray(const ViewCamera& camera, double x, double y, int width, int height) {
  const Eigen::Matrix4d inverse = (camera.projection * camera.view).cast<double>().inverse();
  const double nx = 2.0 * x / width - 1.0, ny = 1.0 - 2.0 * y / height;
  const auto unproject = [&](double z) {
    const Eigen::Vector4d p = inverse * Eigen::Vector4d(nx, ny, z, 1.0);
    return Eigen::Vector3d(p.head<3>() / p.w());
  };
  const Eigen::Vector3d near = unproject(-1.0), far = unproject(1.0);
  return {near, (far - near).normalized()};
}

Eigen::Vector3d project(const ViewCamera& camera, const Eigen::Vector3d& world, int width,
                        int height) {
  const Eigen::Vector4d clip = (camera.projection * camera.view).cast<double>() *
                               Eigen::Vector4d(world.x(), world.y(), world.z(), 1.0);
  const Eigen::Vector3d ndc = clip.head<3>() / clip.w();
  return {(ndc.x() + 1.0) * 0.5 * width, (1.0 - ndc.y()) * 0.5 * height, 0.5 * (ndc.z() + 1.0)};
}

}  // namespace springlab::draw
