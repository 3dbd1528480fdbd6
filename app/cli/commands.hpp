// The subcommands of springlab. Each registers its options on the parsed command line and
// returns the function that runs it; a run returns the process exit status (docs/command-line.md,
// "Exit status"): 0 done, 2 bad input, 3 the simulation diverged, 1 anything else.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace springlab::app {

enum ExitStatus { kOk = 0, kFailure = 1, kBadInput = 2, kDiverged = 3 };

using Command = std::function<int()>;

Command add_run_command(CLI::App& app);
Command add_list_command(CLI::App& app);
Command add_render_command(CLI::App& app);
Command add_view_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_bench_command(CLI::App& app);
Command add_lesson_command(CLI::App& app);
Command add_tableau_command(CLI::App& app);
Command add_homework_command(CLI::App& app);
// `springlab` with no subcommand: the app on the default scene.
Command default_view_command();

}  // namespace springlab::app
