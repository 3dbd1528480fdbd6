// Where every frame is drawn, in the window and headless alike: a multisampled framebuffer
// object (4x where the driver allows, fewer where it does not) resolved into a plain one, which
// is read back as RGBA rows from the top or blitted to a window. With 0 samples the frame is
// drawn into the plain one directly.
#pragma once

#include <cstdint>
#include <vector>

#include "gfx/gl.hpp"

namespace springlab::gfx {

class RenderTarget {
 public:
  RenderTarget() = default;
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  // (Re)allocates for a size; cheap when the size is unchanged.
  void resize(int width, int height, int samples = 4);
  void bind_for_drawing() const;
  // Resolves the samples into the plain framebuffer.
  void resolve() const;
  // Reads the resolved image: width x height RGBA, rows from the top, or from the bottom as GL
  // reads them (a consumer that can take them so spares a copy of the frame).
  void read_rgba(std::vector<std::uint8_t>& pixels, bool bottom_up = false) const;
  // Copies the resolved image to the default framebuffer (a window).
  void blit_to_window(int window_width, int window_height) const;

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }

 private:
  void release();
  int width_ = 0, height_ = 0, samples_ = 0;
  GLuint msaa_fbo_ = 0, msaa_color_ = 0, msaa_depth_ = 0;
  GLuint fbo_ = 0, color_ = 0;
};

}  // namespace springlab::gfx
