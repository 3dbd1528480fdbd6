#include "gfx/render_target.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace springlab::gfx {

RenderTarget::~RenderTarget() {
  release();
}

void RenderTarget::release() {
  if (msaa_fbo_) glDeleteFramebuffers(1, &msaa_fbo_);
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  const GLuint buffers[] = {msaa_color_, msaa_depth_, color_};
  for (GLuint b : buffers)
    if (b) glDeleteRenderbuffers(1, &b);
  msaa_fbo_ = fbo_ = msaa_color_ = msaa_depth_ = color_ = 0;
}

void RenderTarget::resize(int width, int height, int samples) {
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples = std::clamp(samples, 0, std::max(0, static_cast<int>(max_samples)));
  if (width == width_ && height == height_ && samples == samples_ && fbo_) return;
  release();
  width_ = width;
  height_ = height;
  samples_ = samples;

  // The plain framebuffer: the resolve target, or, with no multisampling, where everything is
  // drawn (then it needs the depth buffer).
  glGenFramebuffers(1, &fbo_);
  glGenRenderbuffers(1, &color_);
  glBindRenderbuffer(GL_RENDERBUFFER, color_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
  if (samples == 0) {
    glGenRenderbuffers(1, &msaa_depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, msaa_depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msaa_depth_);
  }
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("the framebuffer is incomplete");
  if (samples == 0) return;

  glGenFramebuffers(1, &msaa_fbo_);
  glGenRenderbuffers(1, &msaa_color_);
  glGenRenderbuffers(1, &msaa_depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, msaa_color_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, msaa_depth_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaa_color_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msaa_depth_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("the multisampled framebuffer is incomplete");
}

void RenderTarget::bind_for_drawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, samples_ > 0 ? msaa_fbo_ : fbo_);
  glViewport(0, 0, width_, height_);
}

void RenderTarget::resolve() const {
  if (samples_ == 0) return;  // drawn straight into the plain framebuffer
  glBindFramebuffer(GL_READ_FRAMEBUFFER, msaa_fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

void RenderTarget::read_rgba(std::vector<std::uint8_t>& pixels, bool bottom_up) const {
  const std::size_t row = static_cast<std::size_t>(width_) * 4;
  pixels.resize(row * height_);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  if (bottom_up) return;
  // GL reads bottom-up.
  std::vector<std::uint8_t> swap(row);
  for (int y = 0; y < height_ / 2; ++y) {
    std::uint8_t* top = pixels.data() + y * row;
    std::uint8_t* bottom = pixels.data() + (height_ - 1 - y) * row;
    std::memcpy(swap.data(), top, row);
    std::memcpy(top, bottom, row);
    std::memcpy(bottom, swap.data(), row);
  }
}

void RenderTarget::blit_to_window(int window_width, int window_height) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, window_width, window_height, GL_COLOR_BUFFER_BIT,
                    GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace springlab::gfx
