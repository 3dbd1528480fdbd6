// springlab homework check FILE: the rope exercise (Homework 8) checked. The student's rope.cpp is
// compiled with the exercise's headers and run in a child process (app/homework/), and the
// checker (springlab/homework.hpp) says, measured, what each part of it does.
// springlab homework kit FOLDER: the starter kit (assets/homework/rope) copied out to work in.
// Exit status: 0 every check passed, 1 some failed, 2 bad input (a file that does not compile).
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "cli/commands.hpp"
#include "homework/rope_build.hpp"
#include "homework/rope_process.hpp"
#include "springlab/error.hpp"
#include "springlab/homework.hpp"
#include "util/data_dir.hpp"

namespace springlab::app {

namespace fs = std::filesystem;

namespace {

int check(const std::string& file, double limit) {
  const auto start = std::chrono::steady_clock::now();
  RopeBuild build(file);
  const double compiled = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RopeProcess code(build.runner(), build.folder(), std::chrono::milliseconds(static_cast<long long>(limit * 1000)));
  const homework::Report report = homework::check_rope(code);
  const double checked = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - compiled;
  std::printf("springlab homework check %s (compiled in %.1f s, checked in %.1f s)\n\n%s", file.c_str(), compiled,
              checked, homework::format_report(report).c_str());
  return report.failed() == 0 && report.passed() > 0 ? kOk : kFailure;
}

int kit(const std::string& folder) {
  const fs::path from = data_dir() / "assets" / "homework" / "rope";
  std::error_code ec;
  if (fs::exists(fs::path(folder) / "rope.cpp", ec))
    throw InputError(folder + "/rope.cpp exists already: name a new folder (the kit never writes over your work)");
  fs::create_directories(folder, ec);
  if (ec) throw InputError("cannot make " + folder + ": " + ec.message());
  for (const char* name : {"rope.cpp", "README.md"}) {
    fs::copy_file(from / name, fs::path(folder) / name, ec);
    if (ec) throw std::runtime_error("cannot copy " + (from / name).string() + ": " + ec.message());
  }
  std::printf("the rope exercise is in %s: write the TODOs in %s/rope.cpp, then\n  springlab homework check %s/rope.cpp\n",
              folder.c_str(), folder.c_str(), folder.c_str());
  return kOk;
}

}  // namespace

Command add_homework_command(CLI::App& app) {
  CLI::App* homework = app.add_subcommand("homework", "Homework 8, the rope exercise: your own code, checked");
  homework->require_subcommand(1);
  struct Options {
    std::string file, folder;
    double limit = 3.0;
  };
  auto options = std::make_shared<Options>();
  CLI::App* check_command = homework->add_subcommand(
      "check", "Compile your rope.cpp with the exercise's headers, run it apart, and say what each part does");
  check_command->add_option("file", options->file, "your rope.cpp")->required();
  check_command->add_option("--time-limit", options->limit, "seconds one call of your code may take (default 3)")
      ->check(CLI::Range(0.1, 600.0));
  CLI::App* kit_command = homework->add_subcommand("kit", "Copy the exercise's starter rope.cpp and its README into FOLDER");
  kit_command->add_option("folder", options->folder, "a new folder for your work")->required();
  return [=] {
    if (check_command->parsed()) return check(options->file, options->limit);
    return kit(options->folder);
  };
}

}  // namespace springlab::app
