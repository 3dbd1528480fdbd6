// OpenGL through libepoxy, which resolves functions in a GLFW window and in a headless EGL
// context alike, with no init call (PLATFORM.md). Every GL call of springlab is in app/gfx/.
#pragma once

#include <epoxy/gl.h>
