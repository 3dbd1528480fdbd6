#include "homework/rope_process.hpp"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>

#include "springlab/text.hpp"

namespace springlab::app {

using namespace homework;

namespace {

std::string hex(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%a", v);
  return text;
}

double number(std::istringstream& in) {
  std::string word;
  in >> word;
  return std::strtod(word.c_str(), nullptr);
}

// What the runner could not go on with (runner.cpp's Fault), in words.
std::string fault_text(const std::string& fault) {
  std::istringstream in(fault);
  std::string kind;
  in >> kind;
  if (kind == "null-mass") {
    int i = -1;
    in >> i;
    return format_text(tr("left masses[%d] a null pointer (push_back a new Mass for each node)"),
                       i);
  }
  if (kind == "no-exercise-constructors")
    return tr(
        "springlab cannot build its own rope with these headers: the exercise's "
        "Rope(vector<Mass *> &, vector<Spring *> &), Mass(Vector2D, float, bool) and "
        "Spring(Mass *, Mass *, float) are needed");
  if (kind == "no-rope") return tr("was asked to step before a rope was built");
  return fault;
}

MassState parse_state(std::istringstream& in) {
  MassState m;
  m.x.x() = number(in), m.x.y() = number(in);
  m.x_last.x() = number(in), m.x_last.y() = number(in);
  m.v.x() = number(in), m.v.y() = number(in);
  m.f.x() = number(in), m.f.y() = number(in);
  return m;
}

}  // namespace

RopeProcess::RopeProcess(std::filesystem::path runner, std::filesystem::path folder,
                         std::chrono::milliseconds limit)
    : runner_(std::move(runner)), folder_(std::move(folder)), limit_(limit) {
  // Its own file for what the student's code prints: a check and the app's lanes run side by side.
  static std::atomic<int> made{0};
  output_ = folder_ / ("output-" + std::to_string(++made) + ".txt");
}

ChildProcess& RopeProcess::child() {
  if (!child_)
    child_ = std::make_unique<ChildProcess>(std::vector<std::string>{runner_.string()}, output_);
  return *child_;
}

void RopeProcess::failed(const std::string& doing, const std::string& error,
                         const std::string& fault) {
  std::string what;
  if (!fault.empty())
    what = doing + " " + fault_text(fault);
  else if (!error.empty())
    what = threw_text(doing, error);
  else if (child_ && child_->timed_out())
    what = timed_out_text(doing, static_cast<double>(limit_.count()) / 1000.0);
  else
    what = ended_text(doing, child_ ? child_->wait() : "");
  const std::string printed = last_lines(output_, 3);
  // (A check of the standard library's that stopped it: said plainly, instead of its own words.)
  if (const std::string check = library_check_text(printed); !check.empty())
    what = doing + " " + check;
  else if (!printed.empty())
    what += printed_text(printed);
  child_.reset();  // the next call starts afresh
  throw CodeFailure(what);
}

std::string RopeProcess::next(const std::string& doing,
                              std::chrono::steady_clock::time_point deadline) {
  std::optional<std::string> line = child_->read_line(deadline);
  if (!line) failed(doing);
  if (line->rfind("error ", 0) == 0) failed(doing, line->substr(6));
  if (*line == "error") failed(doing, tr("an exception that is not a std::exception"));
  if (line->rfind("fault ", 0) == 0) failed(doing, {}, line->substr(6));
  return *line;
}

BuiltRope RopeProcess::build(const RopeRequest& r) {
  return construct("build", format_text(tr("the constructor, Rope(..., %d nodes, ...),"), r.nodes),
                   r);
}

BuiltRope RopeProcess::build_exercise(const RopeRequest& r) {
  return construct("make", tr("building springlab's rope through Rope(masses, springs)"), r);
}

BuiltRope RopeProcess::construct(const std::string& verb, const std::string& doing,
                                 const RopeRequest& r) {
  std::string command = verb + " " + hex(r.start.x()) + " " + hex(r.start.y()) + " " +
                        hex(r.end.x()) + " " + hex(r.end.y()) + " " + std::to_string(r.nodes) +
                        " " + hex(r.node_mass) + " " + hex(r.k) + " " +
                        std::to_string(r.pinned.size());
  for (int p : r.pinned) command += " " + std::to_string(p);
  if (!child().write_line(command)) failed(doing);
  const auto deadline = std::chrono::steady_clock::now() + limit_;
  std::istringstream head(next(doing, deadline));
  std::string word;
  size_t masses = 0, springs = 0;
  head >> word >> masses >> springs;
  if (word != "rope" || masses > 1000000 || springs > 1000000) failed(doing);
  BuiltRope rope;
  for (size_t i = 0; i < masses; ++i) {
    std::istringstream in(next(doing, deadline));
    BuiltMass m;
    in >> word;
    m.start.x() = number(in), m.start.y() = number(in);
    int pinned = 0;
    in >> pinned;
    m.pinned = pinned != 0;
    m.mass = number(in);
    m.state = parse_state(in);
    rope.masses.push_back(m);
  }
  for (size_t i = 0; i < springs; ++i) {
    std::istringstream in(next(doing, deadline));
    BuiltSpring s;
    in >> word >> s.m1 >> s.m2;
    s.k = number(in);
    s.rest = number(in);
    rope.springs.push_back(s);
  }
  next(doing, deadline);  // ok
  masses_ = static_cast<int>(masses);
  return rope;
}

void RopeProcess::set_state(const RopeState& state) {
  std::string command = "set " + std::to_string(state.size());
  for (const MassState& m : state)
    command += "\n" + hex(m.x.x()) + " " + hex(m.x.y()) + " " + hex(m.x_last.x()) + " " +
               hex(m.x_last.y()) + " " + hex(m.v.x()) + " " + hex(m.v.y()) + " " + hex(m.f.x()) +
               " " + hex(m.f.y());
  const std::string doing = tr("setting the masses' state");
  if (!child().write_line(command)) failed(doing);
  next(doing, std::chrono::steady_clock::now() + limit_);
}

std::vector<RopeState> RopeProcess::simulate(Step step, double dt, const Vec2& gravity, int steps) {
  const std::string name = step_name(step);
  if (!child().write_line("sim " + std::string(step == Step::Euler ? "euler " : "verlet ") +
                          hex(dt) + " " + hex(gravity.x()) + " " + hex(gravity.y()) + " " +
                          std::to_string(steps)))
    failed(name);
  // Each step has its own share of the limit, beyond a fixed allowance.
  const auto deadline =
      std::chrono::steady_clock::now() + limit_ + std::chrono::microseconds(200) * steps;
  std::vector<RopeState> states;
  for (int n = 1; n <= steps; ++n) {
    const std::string doing = call_text(step, n, steps, dt);
    next(doing, deadline);  // state n
    RopeState s;
    for (int i = 0; i < masses_; ++i) {
      std::istringstream in(next(doing, deadline));
      s.push_back(parse_state(in));
    }
    states.push_back(std::move(s));
  }
  next(name, deadline);  // ok
  return states;
}

}  // namespace springlab::app
