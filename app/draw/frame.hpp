// A Frame: a plain description of what to draw, built from simulation states (scene_frame.cpp)
// and drawn by the renderer (gfx/renderer.cpp). No GL here: the simulation side never touches
// the GPU, and the renderer never reads a simulation.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace springlab::draw {

using Vec3f = Eigen::Vector3f;
using Mat4f = Eigen::Matrix4f;

struct Rgba {
  float r = 0, g = 0, b = 0, a = 1;
};

struct ViewCamera {
  Mat4f view = Mat4f::Identity();
  Mat4f projection = Mat4f::Identity();
  Vec3f eye = Vec3f::Zero();
  bool orthographic = false;
  float world_per_pixel = 0.01f;  // at the target: sizes particles and lines consistently
};

struct Particle {
  Vec3f position;
  float radius;  // m
  Rgba color;
  bool pinned;  // drawn with a dark ring
};

// A line segment of constant width in pixels; trails are chains of them.
struct Line {
  Vec3f a, b;
  Rgba color_a, color_b;
  float width;  // pixels
};

struct Mesh {
  std::vector<Vec3f> positions;
  std::vector<Vec3f> normals;  // one per position
  std::vector<std::uint32_t> indices;
  Rgba front, back;
};

struct Plane {
  Vec3f point, normal;
  float extent;  // half the side of the square drawn, m
  float cell;    // checker size, m
};

struct Sphere {
  Vec3f center;
  float radius;
  Rgba color;
};

// Where the scene is drawn in the framebuffer, in pixels from the top-left; the rest is
// background (the panels' place).
struct Viewport {
  int x = 0, y = 0, width = 0, height = 0;
};

struct Frame {
  ViewCamera camera;
  Viewport viewport;
  Rgba background{0.10f, 0.11f, 0.13f, 1.0f};
  std::vector<Plane> planes;
  std::vector<Sphere> spheres;
  std::vector<Mesh> meshes;
  std::vector<Line> lines;
  std::vector<Particle> particles;
};

}  // namespace springlab::draw
