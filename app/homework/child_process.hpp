// A program run as a child process, kept apart from springlab: the student's rope runner (and the
// compiler that builds it). springlab writes lines on the child's standard input and reads its
// replies on the child's descriptor 3, each read with a deadline; the child's own standard output
// and error go to a file, so nothing it prints can be mistaken for a reply. Limits set in the
// child (memory, file size, CPU time) keep a runaway child from taking the machine with it.
// When the child dies, how it died (a signal, an exit status) is said in words. The child leads a
// process group of its own, and the whole group is killed when the child ends or is given up:
// nothing the child starts (a student's fork() in a step, the compiler's own programs) outlives it.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace springlab::app {

class ChildProcess {
 public:
  /// Starts argv[0] (an absolute path) with argv; `output` receives its standard output and error.
  ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& output);
  ~ChildProcess();  // kills it if it still runs
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// Writes a line to its standard input; false if it has gone.
  bool write_line(const std::string& line);
  /// The next line from descriptor 3, without its newline: nullopt when the child closed it
  /// (exited or died) or `deadline` passed (then timed_out() is true and the child is killed).
  std::optional<std::string> read_line(std::chrono::steady_clock::time_point deadline);
  bool timed_out() const { return timed_out_; }

  /// Waits for it to end (killing it after `grace`) and says how it ended: "exited with status 1",
  /// "was killed by signal 11 (Segmentation fault)"; empty for a clean exit with status 0.
  std::string wait(std::chrono::milliseconds grace = std::chrono::milliseconds(500));
  /// Runs to the end, for a program that needs no input (the compiler): how it ended, as wait().
  std::string run_to_end(std::chrono::seconds limit);

 private:
  void kill_now();
  void kill_group();

  pid_t pid_ = -1;
  int to_child_ = -1, from_child_ = -1;
  std::string pending_;
  bool timed_out_ = false;
  std::optional<std::string> ended_;
};

/// The last `lines` lines of a text file (what a child printed), joined with " | "; empty if none.
std::string last_lines(const std::filesystem::path& file, int lines);

/// The full path of a program found on PATH; nullopt if none.
std::optional<std::filesystem::path> find_program(const std::string& name);

}  // namespace springlab::app
