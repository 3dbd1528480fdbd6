// The one renderer of springlab: draws a draw::Frame into the bound framebuffer, the same way
// in the window and headless. Owns its shaders and GPU buffers; needs a current GL 3.3 context.
#pragma once

#include <span>

#include "draw/frame.hpp"
#include "gfx/program.hpp"

namespace springlab::gfx {

class Renderer {
 public:
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Clears the bound framebuffer (fb_width x fb_height) and draws each frame into its viewport
  // (compare's lanes apart: a view each).
  void draw(std::span<const draw::Frame> frames, int fb_width, int fb_height);
  void draw(const draw::Frame& frame, int fb_width, int fb_height) {
    draw(std::span(&frame, 1), fb_width, fb_height);
  }

 private:
  void draw_view(const draw::Frame& frame, int fb_width, int fb_height);
  void draw_planes(const draw::Frame& frame);
  void draw_meshes(const draw::Frame& frame);
  void draw_lines(const draw::Frame& frame, int width, int height);
  void draw_particles(const draw::Frame& frame);
  void draw_mesh(const draw::Mesh& mesh, const draw::Mat4f& model, const draw::Rgba& front,
                 const draw::Rgba& back);

  Program particle_, line_, mesh_, ground_;
  GLuint quad_ = 0;  // (-1..1)^2 corners, two triangles
  GLuint particle_vao_ = 0, particle_instances_ = 0;
  GLuint line_corners_ = 0, line_vao_ = 0, line_instances_ = 0;
  GLuint mesh_vao_ = 0, mesh_vertices_ = 0, mesh_indices_ = 0;
  GLuint ground_vao_ = 0;
  draw::Mesh unit_sphere_;
  std::vector<float> scratch_;
};

}  // namespace springlab::gfx
