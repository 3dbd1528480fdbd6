// The driver that `springlab homework check` and `springlab view --homework` compile beside a
// student's rope.cpp, against the same headers the student's file sees (theirs where they wrote
// their own, the exercise's otherwise). It runs in its own process: springlab writes commands on
// its standard input and reads the replies on descriptor 3, so that the student's own printing
// (standard output and error) never mixes with them, and a crash, an exception or an endless loop
// in the student's code takes down only this process. Every number goes both ways as a
// hexadecimal float (%a), exactly.
//
//   build sx sy ex ey nodes mass k pinned_count pinned...   -> rope M S, M "mass" lines, S "spring" lines
//   make  (the same arguments)                              -> the same, for springlab's own rope
//   set M, then M lines: x y last_x last_y vx vy fx fy      -> ok
//   sim euler|verlet dt gx gy steps                         -> per step "state n" and M state lines
//   quit
// `build` calls the student's constructor; `make` builds the rope as the exercise states it (mass
// i at start + i / (nodes - 1) (end - start), a spring between neighbours) through the exercise's
// other constructor, Rope(masses, springs), so that the steps can be checked while the student's
// constructor is not yet right. Each command ends with "ok", "error <what>" if the student's code
// threw ("error" alone: it threw what is not a std::exception), or "fault <kind> ..." if it built
// what the checker cannot read (null-mass <i>: a null pointer among the masses), which the checker
// puts in words (rope_process.cpp, fault_text).
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unistd.h>
#include <vector>

#include "CGL/vector2D.h"
#include "mass.h"
#include "rope.h"
#include "spring.h"

using namespace CGL;

namespace {

FILE* reply = nullptr;
Rope* rope = nullptr;

// What the runner itself cannot go on with (not the student's exception): replied as "fault".
struct Fault : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void print_state(const Mass& m) {
  std::fprintf(reply, "%a %a %a %a %a %a %a %a\n", static_cast<double>(m.position.x), static_cast<double>(m.position.y),
               static_cast<double>(m.last_position.x), static_cast<double>(m.last_position.y),
               static_cast<double>(m.velocity.x), static_cast<double>(m.velocity.y), static_cast<double>(m.forces.x),
               static_cast<double>(m.forces.y));
}

// Refuses a rope whose masses hold a null pointer: nothing of it could be read or stepped.
void check_masses() {
  for (size_t i = 0; i < rope->masses.size(); ++i)
    if (!rope->masses[i])
      throw Fault("null-mass " + std::to_string(i));  // (the checker words each fault)
}

// A spring's end as an index into masses: -1 for a mass the rope does not hold, -2 for none.
int index_of(const Mass* m) {
  if (!m) return -2;
  for (size_t i = 0; i < rope->masses.size(); ++i)
    if (rope->masses[i] == m) return static_cast<int>(i);
  return -1;
}

double number(std::istringstream& in) {  // a hexadecimal float, which operator>> does not read
  std::string word;
  in >> word;
  return std::strtod(word.c_str(), nullptr);
}

struct Request {
  double sx, sy, ex, ey, mass, k;
  int nodes = 0;
  std::vector<int> pinned;
};

Request read_request(std::istringstream& in) {
  Request r;
  r.sx = number(in), r.sy = number(in), r.ex = number(in), r.ey = number(in);
  in >> r.nodes;
  r.mass = number(in), r.k = number(in);
  int pinned_count = 0;
  in >> pinned_count;
  if (pinned_count < 0 || pinned_count > 1000000) pinned_count = 0;
  r.pinned.resize(pinned_count);
  for (int& p : r.pinned) in >> p;
  return r;
}

void describe() {
  check_masses();
  std::fprintf(reply, "rope %zu %zu\n", rope->masses.size(), rope->springs.size());
  for (const Mass* m : rope->masses) {
    std::fprintf(reply, "mass %a %a %d ", static_cast<double>(m->start_position.x),
                 static_cast<double>(m->start_position.y), m->pinned ? 1 : 0);
    std::fprintf(reply, "%a ", static_cast<double>(m->mass));
    print_state(*m);
  }
  for (const Spring* s : rope->springs) {
    if (!s) {
      std::fprintf(reply, "spring -2 -2 0x0p+0 0x0p+0\n");
      continue;
    }
    std::fprintf(reply, "spring %d %d %a %a\n", index_of(s->m1), index_of(s->m2), static_cast<double>(s->k),
                 static_cast<double>(s->rest_length));
  }
}

void build(std::istringstream& in) {
  const Request r = read_request(in);
  rope = nullptr;
  rope = new Rope(Vector2D(r.sx, r.sy), Vector2D(r.ex, r.ey), r.nodes, static_cast<float>(r.mass),
                  static_cast<float>(r.k), r.pinned);
  describe();
}

// springlab's rope, through the exercise's Rope(masses, springs), where the student's rope.h
// still has it.
// (A template, so that a rope.h without them still compiles: the branch not taken is not built.)
template <typename R = Rope, typename M = Mass, typename S = Spring>
void make(std::istringstream& in) {
  if constexpr (std::is_constructible_v<R, std::vector<M*>&, std::vector<S*>&> &&
                std::is_constructible_v<M, Vector2D, float, bool> && std::is_constructible_v<S, M*, M*, float>) {
    const Request r = read_request(in);
    std::vector<M*> masses;
    std::vector<S*> springs;
    for (int i = 0; i < r.nodes; ++i) {
      const double t = r.nodes > 1 ? static_cast<double>(i) / (r.nodes - 1) : 0.0;
      bool pinned = false;
      for (int p : r.pinned) pinned = pinned || p == i;
      masses.push_back(new M(Vector2D(r.sx + t * (r.ex - r.sx), r.sy + t * (r.ey - r.sy)), static_cast<float>(r.mass), pinned));
    }
    for (int i = 0; i + 1 < r.nodes; ++i) springs.push_back(new S(masses[i], masses[i + 1], static_cast<float>(r.k)));
    rope = new R(masses, springs);
    describe();
  } else {
    throw Fault("no-exercise-constructors");
  }
}

void set(std::istringstream& in) {
  size_t count = 0;
  in >> count;
  std::string line;
  for (size_t i = 0; i < count && std::getline(std::cin, line); ++i) {
    std::istringstream values(line);
    double d[8];
    for (double& value : d) value = number(values);
    if (i >= rope->masses.size() || !rope->masses[i]) continue;
    Mass& m = *rope->masses[i];
    m.position = Vector2D(d[0], d[1]);
    m.last_position = Vector2D(d[2], d[3]);
    m.velocity = Vector2D(d[4], d[5]);
    m.forces = Vector2D(d[6], d[7]);
  }
}

void simulate(std::istringstream& in) {
  std::string scheme;
  in >> scheme;
  const float dt = static_cast<float>(number(in));
  const double gx = number(in), gy = number(in);
  const Vector2D gravity(gx, gy);
  int steps = 0;
  in >> steps;
  const bool verlet = scheme == "verlet";
  for (int n = 1; n <= steps; ++n) {
    if (verlet) rope->simulateVerlet(dt, gravity);
    else rope->simulateEuler(dt, gravity);
    check_masses();
    std::fprintf(reply, "state %d\n", n);
    for (const Mass* m : rope->masses) print_state(*m);
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
      else if (command == "make") make(in);
      else if (!rope) throw Fault("no-rope");
      else if (command == "set") set(in);
      else if (command == "sim") simulate(in);
      std::fprintf(reply, "ok\n");
    } catch (const Fault& e) {
      std::fprintf(reply, "fault %s\n", e.what());
    } catch (const std::exception& e) {
      std::fprintf(reply, "error %s\n", e.what());
    } catch (...) {
      std::fprintf(reply, "error\n");  // (an exception that is not a std::exception)
    }
    std::fflush(reply);
  }
  return 0;
}
