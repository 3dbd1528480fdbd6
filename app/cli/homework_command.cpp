// springlab homework check FILE|DIR: the rope exercise (Homework 8) checked. The student's rope.cpp
// is compiled with their own headers where they are beside it (the exercise's otherwise) and run
// in a child process (app/homework/), and the checker (springlab/homework.hpp) says, measured,
// what each part of it does, in the student's language (--lang, else the environment's, as the
// window's), or as JSON for a course's grader (--json).
// springlab homework kit FOLDER: the starter kit (assets/homework/rope) copied out to work in.
// Exit status: 0 every check passed, 1 some failed, 2 bad input (a file that does not compile).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli/commands.hpp"
#include "homework/rope_build.hpp"
#include "homework/rope_process.hpp"
#include "springlab/error.hpp"
#include "springlab/homework.hpp"
#include "springlab/text.hpp"
#include "util/data_dir.hpp"
#include "util/language.hpp"

namespace springlab::app {

namespace fs = std::filesystem;

namespace {

struct CheckOptions {
  std::string file, lang;
  double limit = 3.0;
  bool json = false;
};

// "with your rope.h and mass.h": the headers the build took from beside rope.cpp.
std::string headers_text(const RopeBuild& build) {
  if (build.own_headers().empty()) return tr("with the exercise's headers");
  std::string names;
  for (size_t i = 0; i < build.own_headers().size(); ++i)
    names += (i == 0                                ? ""
              : i + 1 == build.own_headers().size() ? tr(" and ")
                                                    : ", ") +
             build.own_headers()[i];
  return format_text(tr("with your %s (the exercise's for the rest)"), names.c_str());
}

int check(const CheckOptions& o) {
  // The report is text, shown in the terminal's own font (no CJK font needed).
  if (!o.lang.empty())
    use_language(check_language(o.lang, "--lang"), false);
  else {
    try {
      use_language(environment_language(), false);
    } catch (const InputError&) {
      use_language("en");  // a catalog that cannot be read: English, as the window does
    }
  }
  const auto start = std::chrono::steady_clock::now();
  // Bad input is said on standard error (exit 2); with --json also as JSON, for a grader that
  // reads only standard output: {"error": "...", "bad_input": true}.
  std::optional<RopeBuild> made;
  try {
    made.emplace(o.file);
  } catch (const InputError& e) {
    if (o.json)
      std::fputs((nlohmann::json{{"error", e.what()}, {"bad_input", true}}.dump(2) + "\n").c_str(),
                 stdout);
    throw;
  }
  RopeBuild& build = *made;
  const double compiled =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RopeProcess code(build.runner(), build.folder(),
                   std::chrono::milliseconds(static_cast<long long>(o.limit * 1000)));
  const homework::Report report = homework::check_rope(code);
  const double checked =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - compiled;
  if (o.json)
    std::fputs(homework::report_json(report).c_str(), stdout);
  else
    std::printf(
        "%s\n\n%s",
        format_text(tr("springlab homework check %s, %s (compiled in %.1f s, checked in %.1f s)"),
                    build.source().c_str(), headers_text(build).c_str(), compiled, checked)
            .c_str(),
        homework::format_report(report).c_str());
  return report.failed() == 0 && report.passed() > 0 ? kOk : kFailure;
}

int kit(const std::string& folder) {
  const fs::path from = data_dir() / "assets" / "homework" / "rope";
  std::error_code ec;
  if (fs::exists(fs::path(folder) / "rope.cpp", ec))
    throw InputError(
        folder +
        "/rope.cpp exists already: name a new folder (the kit never writes over your work)");
  fs::create_directories(folder, ec);
  if (ec) throw InputError("cannot make " + folder + ": " + ec.message());
  for (const char* name : {"rope.cpp", "README.md"}) {
    fs::copy_file(from / name, fs::path(folder) / name, ec);
    if (ec) throw std::runtime_error("cannot copy " + (from / name).string() + ": " + ec.message());
  }
  std::printf(
      "the rope exercise is in %s: write the TODOs in %s/rope.cpp, then\n  springlab homework "
      "check %s/rope.cpp\n",
      folder.c_str(), folder.c_str(), folder.c_str());
  return kOk;
}

}  // namespace

Command add_homework_command(CLI::App& app) {
  CLI::App* homework =
      app.add_subcommand("homework", "Homework 8, the rope exercise: your own code, checked");
  homework->require_subcommand(1);
  auto options = std::make_shared<CheckOptions>();
  auto folder = std::make_shared<std::string>();
  CLI::App* check_command =
      homework->add_subcommand("check",
                               "Compile your rope.cpp (with your own rope.h, mass.h, spring.h "
                               "where they are beside it), run it apart, and say "
                               "what each part does");
  check_command
      ->add_option("file", options->file,
                   "your rope.cpp, or the folder that holds it (or its src/)")
      ->required();
  check_command
      ->add_option("--time-limit", options->limit,
                   "seconds one call of your code may take (default 3)")
      ->check(CLI::Range(0.1, 600.0));
  check_command->add_option(
      "--lang", options->lang,
      "language of the report: " + language_list() + " (default: LANG, LC_MESSAGES)");
  check_command->add_flag("--json", options->json,
                          "the report as JSON (each line's kind, key and text), for a grader");
  CLI::App* kit_command = homework->add_subcommand(
      "kit", "Copy the exercise's starter rope.cpp and its README into FOLDER");
  kit_command->add_option("folder", *folder, "a new folder for your work")->required();
  return [=] {
    if (check_command->parsed()) return check(*options);
    return kit(*folder);
  };
}

}  // namespace springlab::app
