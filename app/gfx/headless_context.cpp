#include "gfx/headless_context.hpp"

#include <epoxy/egl.h>

#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "gfx/gl.hpp"

namespace springlab::gfx {

namespace {

const char* const kInstall =
    "; headless rendering needs EGL and Mesa: apt-get install libegl1 libegl-mesa0 "
    "libgl1-mesa-dri (scripts/setup.sh installs them)";

// The display: the software device when asked (or when it is the only one), else the default
// device, else Mesa's surfaceless platform.
EGLDisplay open_display(bool software) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!client) throw std::runtime_error(std::string("EGL is not available") + kInstall);
  const auto has = [&](const char* ext) { return std::strstr(client, ext) != nullptr; };
  if (has("EGL_EXT_device_enumeration") && has("EGL_EXT_platform_device")) {
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (eglQueryDevicesEXT(16, devices, &count) && count > 0) {
      EGLDeviceEXT chosen = nullptr;
      for (EGLint i = 0; i < count; ++i) {
        const char* ext = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
        const bool is_software = ext && std::strstr(ext, "EGL_MESA_device_software");
        if (software ? is_software : !chosen) chosen = devices[i];
        if (!software && !is_software) {
          chosen = devices[i];
          break;  // a hardware device is preferred when software is not asked for
        }
      }
      if (chosen) {
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, chosen, nullptr);
        if (d != EGL_NO_DISPLAY) return d;
      }
    }
  }
  if (has("EGL_MESA_platform_surfaceless")) {
    EGLDisplay d =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d != EGL_NO_DISPLAY) return d;
  }
  throw std::runtime_error(std::string("no EGL display without a window system could be opened") +
                           kInstall);
}

}  // namespace

HeadlessContext::HeadlessContext(bool software) {
  // Mesa's loader warnings would come before our one clear message; keep them unless asked for.
  ::setenv("EGL_LOG_LEVEL", "fatal", 0);
  EGLDisplay display = open_display(software);
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor))
    throw std::runtime_error(std::string("EGL could not be initialised") + kInstall);
  display_ = display;
  if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("EGL has no desktop OpenGL");
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  // Surfaceless contexts may have no config at all; EGL_KHR_no_config_context allows that.
  eglChooseConfig(display, config_attributes, &config, 1, &configs);
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                       3,
                                       EGL_CONTEXT_MINOR_VERSION,
                                       3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  EGLContext context = eglCreateContext(display, configs > 0 ? config : EGL_NO_CONFIG_KHR,
                                        EGL_NO_CONTEXT, context_attributes);
  if (context == EGL_NO_CONTEXT)
    throw std::runtime_error(std::string("EGL could not make an OpenGL 3.3 core context") +
                             kInstall);
  context_ = context;
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
    throw std::runtime_error("EGL could not make the context current without a surface");
}

HeadlessContext::~HeadlessContext() {
  if (display_) {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_) eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
}

std::string HeadlessContext::renderer() const {
  const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return r ? r : "unknown";
}

bool software_renderer(const std::string& gl_renderer) {
  return gl_renderer.find("llvmpipe") != std::string::npos ||
         gl_renderer.find("softpipe") != std::string::npos;
}

}  // namespace springlab::gfx
