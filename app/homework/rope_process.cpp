#include "homework/rope_process.hpp"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>

namespace springlab::app {

using namespace homework;

namespace {

std::string hex(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%a", v);
  return text;
}

// "0.5 s", "3 s": a limit as the report writes it.
std::string step_text_seconds(std::chrono::milliseconds limit) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g s", static_cast<double>(limit.count()) / 1000.0);
  return text;
}

double number(std::istringstream& in) {
  std::string word;
  in >> word;
  return std::strtod(word.c_str(), nullptr);
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
    what = doing + " " + fault;
  else if (!error.empty())
    what = doing + " threw an exception: " + error;
  else if (child_ && child_->timed_out())
    what = doing + " did not return within " + step_text_seconds(limit_) +
           " and was stopped (an endless loop?)";
  else {
    const std::string how = child_ ? child_->wait() : "";
    what = doing + (how.empty() ? " ended the program" : " " + how);
  }
  const std::string printed = last_lines(output_, 3);
  if (!printed.empty()) what += "; it printed: " + printed;
  child_.reset();  // the next call starts afresh
  throw CodeFailure(what);
}

std::string RopeProcess::next(const std::string& doing,
                              std::chrono::steady_clock::time_point deadline) {
  std::optional<std::string> line = child_->read_line(deadline);
  if (!line) failed(doing);
  if (line->rfind("error ", 0) == 0) failed(doing, line->substr(6));
  if (line->rfind("fault ", 0) == 0) failed(doing, {}, line->substr(6));
  return *line;
}

BuiltRope RopeProcess::build(const RopeRequest& r) {
  return construct("build",
                   "the constructor, Rope(..., " + std::to_string(r.nodes) + " nodes, ...),", r);
}

BuiltRope RopeProcess::build_exercise(const RopeRequest& r) {
  return construct("make", "building springlab's rope through Rope(masses, springs)", r);
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
  if (!child().write_line(command)) failed("setting the masses' state");
  next("setting the masses' state", std::chrono::steady_clock::now() + limit_);
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
    const std::string doing = name + " (step " + std::to_string(n) + " of " +
                              std::to_string(steps) + ", h = " + step_text(dt) + ")";
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
