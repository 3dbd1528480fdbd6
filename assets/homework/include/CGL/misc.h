// CGL's misc.h as the rope exercise has it (GAMES101 homework 8, after CS 184's CGL): the constants
// and small helpers a student's rope.cpp may use, and the standard headers that come with them.
#ifndef CGL_MISC_H
#define CGL_MISC_H

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace CGL {

#define PI (3.14159265358979323)
#define EPS_D (0.00000000001)
#define EPS_F (0.00001f)
#define INF_D (std::numeric_limits<double>::infinity())
#define INF_F (std::numeric_limits<float>::infinity())

template <typename T>
inline T radians(T deg) {
  return deg * (PI / 180);
}

template <typename T>
inline T degrees(T rad) {
  return rad * (180 / PI);
}

template <typename T>
inline T clamp(T x, T lo, T hi) {
  return std::min(std::max(x, lo), hi);
}

}  // namespace CGL

#endif  // CGL_MISC_H
