// CGL::Vector2D as the rope exercise (GAMES101 homework 8, after CS 184's CGL) has it: the same
// members, operators and free functions, written for springlab so that a student's rope.cpp
// compiles unchanged. (The exercise's compound assignments return void; these return the
// vector, which accepts every use of theirs.)
#ifndef CGL_VECTOR2D_H
#define CGL_VECTOR2D_H

#include <cmath>
#include <ostream>

#include "CGL.h"

namespace CGL {

class Vector2D {
 public:
  double x, y;

  Vector2D() : x(0.0), y(0.0) {}
  Vector2D(double x, double y) : x(x), y(y) {}
  Vector2D(const Vector2D& v) : x(v.x), y(v.y) {}
  Vector2D& operator=(const Vector2D& v) = default;

  double& operator[](const int& index) { return (&x)[index]; }
  const double& operator[](const int& index) const { return (&x)[index]; }

  Vector2D operator-() const { return Vector2D(-x, -y); }
  Vector2D operator+(const Vector2D& v) const { return Vector2D(x + v.x, y + v.y); }
  Vector2D operator-(const Vector2D& v) const { return Vector2D(x - v.x, y - v.y); }
  Vector2D operator*(double r) const { return Vector2D(x * r, y * r); }
  Vector2D operator/(double r) const {
    Vector2D u = *this;
    u /= r;
    return u;
  }
  Vector2D& operator+=(const Vector2D& v) {
    x += v.x;
    y += v.y;
    return *this;
  }
  Vector2D& operator-=(const Vector2D& v) {
    x -= v.x;
    y -= v.y;
    return *this;
  }
  Vector2D& operator*=(double r) {
    x *= r;
    y *= r;
    return *this;
  }
  Vector2D& operator/=(double r) {
    x /= r;
    y /= r;
    return *this;
  }

  double norm() const { return std::sqrt(x * x + y * y); }
  double norm2() const { return x * x + y * y; }
  Vector2D unit() const { return *this / norm(); }
  void normalize() { *this /= norm(); }
};

inline Vector2D operator*(double r, const Vector2D& v) { return v * r; }
inline double dot(const Vector2D& u, const Vector2D& v) { return u.x * v.x + u.y * v.y; }
inline double cross(const Vector2D& u, const Vector2D& v) { return u.x * v.y - u.y * v.x; }
inline std::ostream& operator<<(std::ostream& os, const Vector2D& v) {
  return os << "(" << v.x << "," << v.y << ")";
}

}  // namespace CGL

#endif  // CGL_VECTOR2D_H
