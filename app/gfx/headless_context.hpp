// An OpenGL 3.3 core context with no display and no window: EGL on Mesa's surfaceless or device
// platform. Everything is drawn into framebuffer objects.
#pragma once

#include <string>

namespace springlab::gfx {

class HeadlessContext {
 public:
  // `software`: use Mesa's software rasteriser (llvmpipe) even where a GPU is present, so that
  // golden images have the same pixels on every machine. Throws std::runtime_error, saying what
  // to install, when no EGL display can be made.
  explicit HeadlessContext(bool software);
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  std::string renderer() const;  // "llvmpipe (LLVM 15.0.6, 256 bits)"

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
};

// Whether an OpenGL renderer string (GL_RENDERER) names one of Mesa's software rasterisers,
// which draw with the CPU's cores.
bool software_renderer(const std::string& gl_renderer);

}  // namespace springlab::gfx
