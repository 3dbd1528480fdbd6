// The driver that `springlab homework check` and `springlab view --homework` compile beside a
// student's rope.cpp. It runs in its own process: springlab writes commands on its standard input
// and reads the replies on descriptor 3, so that the student's own printing (standard output and
// error) never mixes with them, and a crash, an exception or an endless loop in the student's code
// takes down only this process. Every number goes both ways as a hexadecimal float (%a), exactly.
//
//   build sx sy ex ey nodes mass k pinned_count pinned...   -> rope M S, M "mass" lines, S "spring" lines
//   set M, then M lines: x y last_x last_y vx vy fx fy      -> ok
//   sim euler|verlet dt gx gy steps                         -> per step "state n" and M state lines
//   quit
// Each command ends with "ok", or "error <what>" if the student's code threw.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

#include "CGL/vector2D.h"
#include "mass.h"
#include "rope.h"
#include "spring.h"

namespace {

FILE* reply = nullptr;
CGL::Rope* rope = nullptr;

void print_state(const CGL::Mass& m) {
  std::fprintf(reply, "%a %a %a %a %a %a %a %a\n", m.position.x, m.position.y, m.last_position.x,
               m.last_position.y, m.velocity.x, m.velocity.y, m.forces.x, m.forces.y);
}

int index_of(const CGL::Mass* m) {
  for (size_t i = 0; i < rope->masses.size(); ++i)
    if (rope->masses[i] == m) return static_cast<int>(i);
  return -1;
}

double number(std::istringstream& in) {  // a hexadecimal float, which operator>> does not read
  std::string word;
  in >> word;
  return std::strtod(word.c_str(), nullptr);
}

void build(std::istringstream& in) {
  const double sx = number(in), sy = number(in), ex = number(in), ey = number(in);
  int nodes = 0, pinned_count = 0;
  in >> nodes;
  const double mass = number(in), k = number(in);
  in >> pinned_count;
  std::vector<int> pinned(pinned_count);
  for (int& p : pinned) in >> p;
  rope = new CGL::Rope(CGL::Vector2D(sx, sy), CGL::Vector2D(ex, ey), nodes, static_cast<float>(mass),
                       static_cast<float>(k), pinned);
  std::fprintf(reply, "rope %zu %zu\n", rope->masses.size(), rope->springs.size());
  for (const CGL::Mass* m : rope->masses) {
    std::fprintf(reply, "mass %a %a %d ", m->start_position.x, m->start_position.y, m->pinned ? 1 : 0);
    std::fprintf(reply, "%a ", static_cast<double>(m->mass));
    print_state(*m);
  }
  for (const CGL::Spring* s : rope->springs)
    std::fprintf(reply, "spring %d %d %a %a\n", index_of(s->m1), index_of(s->m2), static_cast<double>(s->k),
                 s->rest_length);
}

void set(std::istringstream& in) {
  size_t count = 0;
  in >> count;
  std::string line;
  for (size_t i = 0; i < count && std::getline(std::cin, line); ++i) {
    std::istringstream values(line);
    double d[8];
    for (double& value : d) value = number(values);
    if (i >= rope->masses.size()) continue;
    CGL::Mass& m = *rope->masses[i];
    m.position = {d[0], d[1]};
    m.last_position = {d[2], d[3]};
    m.velocity = {d[4], d[5]};
    m.forces = {d[6], d[7]};
  }
}

void simulate(std::istringstream& in) {
  std::string scheme;
  in >> scheme;
  const float dt = static_cast<float>(number(in));
  const double gx = number(in), gy = number(in);
  const CGL::Vector2D gravity(gx, gy);
  int steps = 0;
  in >> steps;
  const bool verlet = scheme == "verlet";
  for (int n = 1; n <= steps; ++n) {
    if (verlet) rope->simulateVerlet(dt, gravity);
    else rope->simulateEuler(dt, gravity);
    std::fprintf(reply, "state %d\n", n);
    for (const CGL::Mass* m : rope->masses) print_state(*m);
    std::fflush(reply);
  }
}

}  // namespace

int main() {
  reply = fdopen(3, "w");
  if (!reply) {
    std::fprintf(stderr, "the rope runner must be started by springlab (descriptor 3 is its reply channel)\n");
    return 2;
  }
  std::string line;
  while (std::getline(std::cin, line)) {
    std::istringstream in(line);
    std::string command;
    in >> command;
    if (command == "quit") break;
    try {
      if (command == "build") build(in);
      else if (!rope) throw std::runtime_error("no rope built yet");
      else if (command == "set") set(in);
      else if (command == "sim") simulate(in);
      std::fprintf(reply, "ok\n");
    } catch (const std::exception& e) {
      std::fprintf(reply, "error %s\n", e.what());
    } catch (...) {
      std::fprintf(reply, "error an exception that is not a std::exception\n");
    }
    std::fflush(reply);
  }
  return 0;
}
