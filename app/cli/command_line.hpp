// springlab's command line as a function: main() is this call (app/main.cpp).
#pragma once

namespace springlab::app {

/// Parses argv, runs the subcommand it names and returns the process's exit status.
int run_command_line(int argc, char** argv);

}  // namespace springlab::app
