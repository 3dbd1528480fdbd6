#include "gfx/program.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "util/data_dir.hpp"

namespace springlab::gfx {

namespace {

std::string source(const std::string& file) {
  const auto path = app::data_dir() / "shaders" / file;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("shader '" + path.string() + "' cannot be read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The desktop's GLSL 3.30 core as GLSL ES 3.00 (WebGL2): the same source under a new first line,
// with the precisions ES leaves for the program to choose (high: positions in metres and depth).
std::string for_this_gl(std::string text) {
  if (!kGles) return text;
  const std::size_t eol = text.find('\n');
  if (text.rfind("#version", 0) == 0 && eol != std::string::npos) text.erase(0, eol + 1);
  return "#version 300 es\nprecision highp float;\nprecision highp int;\n" + text;
}

GLuint compile(GLenum type, const std::string& file) {
  const std::string text = for_this_gl(source(file));
  const char* p = text.c_str();
  GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &p, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(length + 1);
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    throw std::runtime_error("shader '" + file + "' does not compile: " + log.data());
  }
  return shader;
}

}  // namespace

Program::Program(const std::string& name) {
  const GLuint vs = compile(GL_VERTEX_SHADER, name + ".vert");
  const GLuint fs = compile(GL_FRAGMENT_SHADER, name + ".frag");
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(length + 1);
    glGetProgramInfoLog(id_, length, nullptr, log.data());
    throw std::runtime_error("shader program '" + name + "' does not link: " + log.data());
  }
}

Program::~Program() {
  if (id_) glDeleteProgram(id_);
}

Program::Program(Program&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

Program& Program::operator=(Program&& other) noexcept {
  std::swap(id_, other.id_);
  return *this;
}

void Program::set(const char* name, const draw::Mat4f& m) const {
  glUniformMatrix4fv(uniform(name), 1, GL_FALSE, m.data());  // Eigen is column-major, as GL
}
void Program::set(const char* name, const draw::Vec3f& v) const {
  glUniform3f(uniform(name), v.x(), v.y(), v.z());
}
void Program::set(const char* name, const draw::Rgba& c) const {
  glUniform4f(uniform(name), c.r, c.g, c.b, c.a);
}
void Program::set(const char* name, float x) const {
  glUniform1f(uniform(name), x);
}
void Program::set(const char* name, float x, float y) const {
  glUniform2f(uniform(name), x, y);
}

}  // namespace springlab::gfx
