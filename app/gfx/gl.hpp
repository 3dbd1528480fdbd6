// OpenGL for every platform, and the only place that knows which one it is. On the desktop:
// OpenGL 3.3 core through libepoxy, which resolves functions in a GLFW window and in a headless
// EGL context alike, with no init call (docs/platform.md, "OpenGL function loading"). In the
// browser: OpenGL ES 3.0 (WebGL2), whose functions emscripten links directly. Every GL call of
// springlab is in app/gfx/.
#pragma once

#ifdef __EMSCRIPTEN__
#include <GLES3/gl3.h>
#define SPRINGLAB_GLES 1
#else
#include <epoxy/gl.h>
#define SPRINGLAB_GLES 0
#endif

namespace springlab::gfx {

// Whether the context is OpenGL ES (the browser's WebGL2). The shaders are written once, in GLSL
// 3.30 core; program.cpp gives them ES 3.00's first line and precisions there.
inline constexpr bool kGles = SPRINGLAB_GLES;

}  // namespace springlab::gfx
