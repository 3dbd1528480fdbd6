// The student's rope, run in a child process (the runner that RopeBuild made): the homework
// checker's RopeCode over the runner's line protocol (assets/homework/runner/runner.cpp). A
// crash, an exception or a call that does not return in time becomes a CodeFailure saying what
// happened and when; the next call starts a fresh runner, so one failure ends one check only.
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>

#include "homework/child_process.hpp"
#include "springlab/homework.hpp"

namespace springlab::app {

class RopeProcess : public homework::RopeCode {
 public:
  /// `limit`: how long one call (a constructor, or a run of steps) may take.
  RopeProcess(std::filesystem::path runner, std::filesystem::path folder,
              std::chrono::milliseconds limit = std::chrono::milliseconds(3000));

  homework::BuiltRope build(const homework::RopeRequest& request) override;
  homework::BuiltRope build_exercise(const homework::RopeRequest& request) override;
  void set_state(const homework::RopeState& state) override;
  std::vector<homework::RopeState> simulate(homework::Step step, double dt,
                                            const homework::Vec2& gravity, int steps) override;

 private:
  ChildProcess& child();
  homework::BuiltRope construct(const std::string& verb, const std::string& doing,
                                const homework::RopeRequest& r);
  std::string next(const std::string& doing, std::chrono::steady_clock::time_point deadline);
  /// `error`: the student's exception; `fault`: what the runner could not read of what the code
  /// built.
  [[noreturn]] void failed(const std::string& doing, const std::string& error = {},
                           const std::string& fault = {});

  std::filesystem::path runner_, folder_, output_;
  std::chrono::milliseconds limit_;
  std::unique_ptr<ChildProcess> child_;
  int masses_ = 0;
};

}  // namespace springlab::app
