// From a scene's Camera (orbit or planar) and a viewport to view and projection matrices, and
// back: the ray under a pixel (for picking and dragging). Plain maths, no GL.
#pragma once

#include "draw/frame.hpp"
#include "springlab/scene.hpp"

namespace springlab::draw {

ViewCamera view_camera(const Camera& camera, int width, int height);

struct Ray {
  Eigen::Vector3d origin, direction;  // direction of unit length
};

// The ray through pixel (x, y), measured from the top-left corner of a width x height viewport.
Ray pixel_ray(const ViewCamera& camera, double x, double y, int width, int height);

// Where a world point lands, in pixels from the top-left; z in [0, 1] is its depth.
Eigen::Vector3d project(const ViewCamera& camera, const Eigen::Vector3d& world, int width,
                        int height);

}  // namespace springlab::draw
