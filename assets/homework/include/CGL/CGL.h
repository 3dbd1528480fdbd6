// The exercise's umbrella header, CGL/CGL.h: what it brings a student's rope.cpp. The exercise's
// CGL includes misc.h (<algorithm>, <cmath>, <limits>, <string>) and, through the library's other
// headers (its viewer, renderer and text), <vector>, <iostream>, <sstream>, <map>, <chrono> and
// the C headers; a rope.cpp that leans on any of them compiles in the exercise, so it compiles
// here. The classes the exercise forward-declares are declared too.
#ifndef CGL_CGL_H
#define CGL_CGL_H

#include <cassert>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "misc.h"

namespace CGL {

typedef double CGLfloat;

class Vector2D;
class Vector3D;
class Vector4D;
class Matrix3x3;
class Matrix4x4;
class Quaternion;
class Complex;
class Color;
class Renderer;
class OSDText;
class Viewer;
class Timer;

}  // namespace CGL

#include "vector2D.h"

#endif  // CGL_CGL_H
