#include "gfx/renderer.hpp"

#include <Eigen/Geometry>
#include <cmath>

namespace springlab::gfx {

using draw::Mat4f;
using draw::Vec3f;

namespace {

// Light from above, to the right and in front of the camera, in view space.
const Vec3f kLight = Vec3f(0.35f, 0.75f, 0.55f).normalized();

draw::Mesh make_unit_sphere(int slices, int stacks) {
  draw::Mesh m;
  constexpr float kPi = 3.14159265358979f;
  for (int j = 0; j <= stacks; ++j) {
    const float phi = kPi * static_cast<float>(j) / stacks;
    for (int i = 0; i <= slices; ++i) {
      const float theta = 2.0f * kPi * static_cast<float>(i) / slices;
      const Vec3f p(std::sin(phi) * std::cos(theta), std::cos(phi),
                    std::sin(phi) * std::sin(theta));
      m.positions.push_back(p);
      m.normals.push_back(p);
    }
  }
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      const std::uint32_t a = j * (slices + 1) + i, b = a + slices + 1;
      m.indices.insert(m.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
    }
  return m;
}

void attribute(GLuint index, int size, int stride_floats, int offset_floats, bool instanced) {
  glEnableVertexAttribArray(index);
  glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, stride_floats * sizeof(float),
                        // GL takes a buffer offset as a pointer
                        // NOLINTNEXTLINE(performance-no-int-to-ptr)
                        reinterpret_cast<void*>(offset_floats * sizeof(float)));
  glVertexAttribDivisor(index, instanced ? 1 : 0);
}

}  // namespace

Renderer::Renderer()
    : particle_("particle"),
      line_("line"),
      mesh_("mesh"),
      ground_("ground"),
      unit_sphere_(make_unit_sphere(48, 24)) {
  const float quad[] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
  glGenBuffers(1, &quad_);
  glBindBuffer(GL_ARRAY_BUFFER, quad_);
  glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);

  // Particles: corner + per-instance center, radius, color, pinned (9 floats).
  glGenVertexArrays(1, &particle_vao_);
  glGenBuffers(1, &particle_instances_);
  glBindVertexArray(particle_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, quad_);
  attribute(0, 2, 2, 0, false);
  glBindBuffer(GL_ARRAY_BUFFER, particle_instances_);
  attribute(1, 3, 9, 0, true);
  attribute(2, 1, 9, 3, true);
  attribute(3, 4, 9, 4, true);
  attribute(4, 1, 9, 8, true);

  // Lines: corner (end, side) + per-instance a, b, colours, width (15 floats).
  const float corners[] = {0, -1, 1, -1, 1, 1, 0, -1, 1, 1, 0, 1};
  glGenBuffers(1, &line_corners_);
  glBindBuffer(GL_ARRAY_BUFFER, line_corners_);
  glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
  glGenVertexArrays(1, &line_vao_);
  glGenBuffers(1, &line_instances_);
  glBindVertexArray(line_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, line_corners_);
  attribute(0, 2, 2, 0, false);
  glBindBuffer(GL_ARRAY_BUFFER, line_instances_);
  attribute(1, 3, 15, 0, true);
  attribute(2, 3, 15, 3, true);
  attribute(3, 4, 15, 6, true);
  attribute(4, 4, 15, 10, true);
  attribute(5, 1, 15, 14, true);

  // Meshes: interleaved position and normal.
  glGenVertexArrays(1, &mesh_vao_);
  glGenBuffers(1, &mesh_vertices_);
  glGenBuffers(1, &mesh_indices_);
  glBindVertexArray(mesh_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, mesh_vertices_);
  attribute(0, 3, 6, 0, false);
  attribute(1, 3, 6, 3, false);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh_indices_);

  glGenVertexArrays(1, &ground_vao_);
  glBindVertexArray(ground_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, quad_);
  attribute(0, 2, 2, 0, false);
  glBindVertexArray(0);
}

Renderer::~Renderer() {
  const GLuint buffers[] = {quad_,           particle_instances_, line_corners_,
                            line_instances_, mesh_vertices_,      mesh_indices_};
  glDeleteBuffers(6, buffers);
  const GLuint arrays[] = {particle_vao_, line_vao_, mesh_vao_, ground_vao_};
  glDeleteVertexArrays(4, arrays);
}

void Renderer::draw(std::span<const draw::Frame> frames, int fb_width, int fb_height) {
  glViewport(0, 0, fb_width, fb_height);
  const draw::Rgba background =
      frames.empty() ? draw::Frame().background : frames.front().background;
  glClearColor(background.r, background.g, background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  for (const draw::Frame& frame : frames) draw_view(frame, fb_width, fb_height);
}

void Renderer::draw_view(const draw::Frame& frame, int fb_width, int fb_height) {
  const draw::Viewport& v = frame.viewport;
  const int width = v.width > 0 ? v.width : fb_width, height = v.height > 0 ? v.height : fb_height;
  glViewport(v.x, fb_height - v.y - height, width, height);  // GL counts rows from the bottom
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_CULL_FACE);
#if !SPRINGLAB_GLES
  glEnable(GL_MULTISAMPLE);  // (ES has no switch: a target with samples is multisampled)
#endif
  draw_planes(frame);
  draw_meshes(frame);
  draw_lines(frame, width, height);
  draw_particles(frame);
  glBindVertexArray(0);
  glUseProgram(0);
}

void Renderer::draw_planes(const draw::Frame& frame) {
  if (frame.planes.empty()) return;
  ground_.use();
  ground_.set("view_projection", Mat4f(frame.camera.projection * frame.camera.view));
  ground_.set("background", frame.background);
  glBindVertexArray(ground_vao_);
  // Pushed back a little so that what lies on the ground is drawn over it.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 2.0f);
  for (const draw::Plane& p : frame.planes) {
    const Vec3f n = p.normal.normalized();
    const Vec3f u =
        (std::abs(n.y()) < 0.9f ? n.cross(Vec3f::UnitY()) : n.cross(Vec3f::UnitX())).normalized();
    const Vec3f v = n.cross(u);
    ground_.set("origin", p.point);
    ground_.set("axis_u", Vec3f(u * p.extent));
    ground_.set("axis_v", Vec3f(v * p.extent));
    ground_.set("unit_u", u);
    ground_.set("unit_v", v);
    ground_.set("cell", p.cell);
    ground_.set("extent", p.extent);
    glDrawArrays(GL_TRIANGLES, 0, 6);
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void Renderer::draw_mesh(const draw::Mesh& mesh, const Mat4f& model, const draw::Rgba& front,
                         const draw::Rgba& back) {
  scratch_.resize(mesh.positions.size() * 6);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      scratch_[6 * i + c] = mesh.positions[i][c];
      scratch_[6 * i + 3 + c] = mesh.normals[i][c];
    }
  }
  glBindVertexArray(mesh_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, mesh_vertices_);
  glBufferData(GL_ARRAY_BUFFER, scratch_.size() * sizeof(float), scratch_.data(), GL_STREAM_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh_indices_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, mesh.indices.size() * sizeof(std::uint32_t),
               mesh.indices.data(), GL_STREAM_DRAW);
  mesh_.set("model", model);
  mesh_.set("front_color", front);
  mesh_.set("back_color", back);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.indices.size()), GL_UNSIGNED_INT, nullptr);
}

void Renderer::draw_meshes(const draw::Frame& frame) {
  if (frame.meshes.empty() && frame.spheres.empty()) return;
  mesh_.use();
  mesh_.set("view", frame.camera.view);
  mesh_.set("projection", frame.camera.projection);
  mesh_.set("light_dir", kLight);
  // Surfaces sit a little behind the springs drawn on them.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  for (const draw::Sphere& s : frame.spheres) {
    Mat4f model = Mat4f::Identity();
    model.topLeftCorner<3, 3>() *= s.radius;
    model.topRightCorner<3, 1>() = s.center;
    draw_mesh(unit_sphere_, model, s.color, s.color);
  }
  for (const draw::Mesh& m : frame.meshes) draw_mesh(m, Mat4f::Identity(), m.front, m.back);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void Renderer::draw_lines(const draw::Frame& frame, int width, int height) {
  if (frame.lines.empty()) return;
  scratch_.resize(frame.lines.size() * 15);
  float* p = scratch_.data();
  for (const draw::Line& l : frame.lines) {
    const float values[15] = {l.a.x(),     l.a.y(),     l.a.z(),     l.b.x(),     l.b.y(),
                              l.b.z(),     l.color_a.r, l.color_a.g, l.color_a.b, l.color_a.a,
                              l.color_b.r, l.color_b.g, l.color_b.b, l.color_b.a, l.width};
    std::copy(values, values + 15, p);
    p += 15;
  }
  line_.use();
  line_.set("view_projection", Mat4f(frame.camera.projection * frame.camera.view));
  line_.set("viewport", static_cast<float>(width), static_cast<float>(height));
  glBindVertexArray(line_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, line_instances_);
  glBufferData(GL_ARRAY_BUFFER, scratch_.size() * sizeof(float), scratch_.data(), GL_STREAM_DRAW);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glDrawArraysInstanced(GL_TRIANGLES, 0, 6, static_cast<GLsizei>(frame.lines.size()));
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

void Renderer::draw_particles(const draw::Frame& frame) {
  if (frame.particles.empty()) return;
  scratch_.resize(frame.particles.size() * 9);
  float* p = scratch_.data();
  for (const draw::Particle& q : frame.particles) {
    const float values[9] = {q.position.x(), q.position.y(), q.position.z(),
                             q.radius,       q.color.r,      q.color.g,
                             q.color.b,      q.color.a,      q.pinned ? 1.0f : 0.0f};
    std::copy(values, values + 9, p);
    p += 9;
  }
  particle_.use();
  particle_.set("view", frame.camera.view);
  particle_.set("projection", frame.camera.projection);
  particle_.set("light_dir", kLight);
  glBindVertexArray(particle_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, particle_instances_);
  glBufferData(GL_ARRAY_BUFFER, scratch_.size() * sizeof(float), scratch_.data(), GL_STREAM_DRAW);
  // Multisampled: the soft edge becomes coverage; else it is blended.
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  if (samples > 0) {
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  } else {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  }
  glDrawArraysInstanced(GL_TRIANGLES, 0, 6, static_cast<GLsizei>(frame.particles.size()));
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glDisable(GL_BLEND);
}

}  // namespace springlab::gfx
