// The command line (docs/command-line.md): parses, dispatches to a subcommand, and turns what goes
// wrong into one clear message and the exit status: 0 done, 2 bad input, 3 diverged, 1 anything
// else. Here among the subcommands rather than in main.cpp: one unit parses CLI11 for all of them.
#include "cli/command_line.hpp"

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <exception>
#include <map>
#include <string>

#include "cli/commands.hpp"
#include "session/stability_job.hpp"
#include "springlab/error.hpp"
#include "springlab/version.hpp"
#include "util/atomic_file.hpp"

namespace springlab::app {

int run_command_line(int argc, char** argv) {
  remove_pending_outputs_on_interrupt();
  std::signal(SIGPIPE, SIG_IGN);

  CLI::App app("springlab: mass-spring and particle simulation for teaching", "springlab");
  app.set_version_flag("--version", std::string("springlab ") + springlab::kVersion);
  app.require_subcommand(0, 1);
  std::map<std::string, Command> commands;
  commands["run"] = add_run_command(app);
  commands["list"] = add_list_command(app);
  commands["render"] = add_render_command(app);
  commands["view"] = add_view_command(app);
  commands["compare"] = add_compare_command(app);
  commands["bench"] = add_bench_command(app);
  commands["lesson"] = add_lesson_command(app);
  commands["tableau"] = add_tableau_command(app);
  commands["homework"] = add_homework_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "springlab: %s (see springlab --help)\n", e.what());
    return kBadInput;
  }

  // Every stability analysis the app left running is cancelled and joined before main returns.
  struct Shutdown {
    ~Shutdown() { StabilityJob::shutdown(); }
  } shutdown;
  try {
    for (const auto& [name, command] : commands)
      if (app.got_subcommand(name)) return command();
    return default_view_command()();
  } catch (const springlab::InputError& e) {
    std::fprintf(stderr, "springlab: %s\n", e.what());
    return kBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "springlab: %s\n", e.what());
    return kFailure;
  }
}

}  // namespace springlab::app
