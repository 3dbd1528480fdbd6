// springlab: the command line (docs/command-line.md; app/cli/command_line.cpp).
#include "cli/command_line.hpp"

int main(int argc, char** argv) {
  return springlab::app::run_command_line(argc, argv);
}
