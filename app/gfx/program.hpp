// A GLSL program built from a vertex and a fragment shader file of shaders/.
#pragma once

#include <string>

#include "draw/frame.hpp"
#include "gfx/gl.hpp"

namespace springlab::gfx {

class Program {
 public:
  Program() = default;
  // Loads shaders/<name>.vert and shaders/<name>.frag; throws std::runtime_error with the
  // compiler's log.
  explicit Program(const std::string& name);
  ~Program();
  Program(Program&& other) noexcept;
  Program& operator=(Program&& other) noexcept;

  void use() const { glUseProgram(id_); }
  GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }
  void set(const char* name, const draw::Mat4f& m) const;
  void set(const char* name, const draw::Vec3f& v) const;
  void set(const char* name, const draw::Rgba& c) const;
  void set(const char* name, float x) const;
  void set(const char* name, float x, float y) const;

 private:
  GLuint id_ = 0;
};

}  // namespace springlab::gfx
