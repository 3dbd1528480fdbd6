#include "homework/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "springlab/text.hpp"

namespace springlab::app {

namespace {

// What the child may use: memory for a rope and far more, and output for any debugging print.
constexpr rlim_t kMemory = rlim_t(2) << 30;     // 2 GiB of address space
constexpr rlim_t kFileSize = rlim_t(64) << 20;  // 64 MiB a file
constexpr rlim_t kCpuSeconds = 120;

void limit(int resource, rlim_t value) {
  const rlimit r{value, value};
  setrlimit(resource, &r);
}

}  // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& argv,
                           const std::filesystem::path& output) {
  int in[2], reply[2];
  if (pipe2(in, O_CLOEXEC) != 0 || pipe2(reply, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  const int out = open(output.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (out < 0)
    throw std::runtime_error("cannot write " + output.string() + ": " + std::strerror(errno));
  std::vector<char*> args;
  args.reserve(argv.size() + 1);
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);

  pid_ = fork();
  if (pid_ == 0) {  // the child: only async-signal-safe calls until exec
    setpgid(0, 0);  // a group of its own, killed whole (kill_group)
    dup2(in[0], 0);
    dup2(out, 1);
    dup2(out, 2);
    dup2(reply[1], 3);
    limit(RLIMIT_AS, kMemory);
    limit(RLIMIT_FSIZE, kFileSize);
    limit(RLIMIT_CPU, kCpuSeconds);
    limit(RLIMIT_CORE, 0);
    execv(args[0], args.data());
    _exit(127);
  }
  close(in[0]);
  close(reply[1]);
  close(out);
  if (pid_ < 0) {
    close(in[1]);
    close(reply[0]);
    throw std::runtime_error(std::string("cannot start a process: ") + std::strerror(errno));
  }
  setpgid(pid_, pid_);  // as the child does: whichever runs first, the group exists before a kill
  to_child_ = in[1];
  from_child_ = reply[0];
}

ChildProcess::~ChildProcess() {
  if (!ended_) {
    kill_now();
    wait(std::chrono::milliseconds(0));
  }
  if (to_child_ >= 0) close(to_child_);
  if (from_child_ >= 0) close(from_child_);
}

bool ChildProcess::write_line(const std::string& line) {
  if (to_child_ < 0) return false;
  std::string text = line + "\n";
  const char* p = text.data();
  size_t left = text.size();
  while (left > 0) {
    const ssize_t n =
        ::write(to_child_, p, left);  // SIGPIPE is ignored (cli/command_line.cpp): EPIPE here
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    left -= static_cast<size_t>(n);
  }
  return true;
}

std::optional<std::string> ChildProcess::read_line(std::chrono::steady_clock::time_point deadline) {
  for (;;) {
    const size_t end = pending_.find('\n');
    if (end != std::string::npos) {
      std::string line = pending_.substr(0, end);
      pending_.erase(0, end + 1);
      return line;
    }
    if (from_child_ < 0) return std::nullopt;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out_ = true;
      kill_now();
      return std::nullopt;
    }
    pollfd p{from_child_, POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    char buffer[1 << 16];
    const ssize_t n = ::read(from_child_, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      close(from_child_);
      from_child_ = -1;
      continue;  // a last line without its newline is dropped: a reply always ends with one
    }
    pending_.append(buffer, static_cast<size_t>(n));
  }
}

void ChildProcess::kill_now() {
  if (pid_ > 0 && !ended_) {
    ::kill(pid_, SIGKILL);
    kill_group();
  }
}

// Whatever the child started and left running (it may have blocked every signal but SIGKILL).
// Called only while the child is unreaped, so its group's id is still its own.
void ChildProcess::kill_group() {
  if (pid_ > 0) ::kill(-pid_, SIGKILL);
}

std::string ChildProcess::wait(std::chrono::milliseconds grace) {
  if (ended_) return *ended_;
  if (to_child_ >= 0) {
    close(to_child_);  // end of input: a runner that is waiting for a command exits
    to_child_ = -1;
  }
  // Ended (seen without reaping it: a zombie keeps its pid and group), or killed after the grace;
  // then the group, and only then the child is reaped.
  const auto until = std::chrono::steady_clock::now() + grace;
  siginfo_t info{};
  while (waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
         info.si_pid == 0) {
    if (std::chrono::steady_clock::now() >= until) {
      ::kill(pid_, SIGKILL);
      break;
    }
    poll(nullptr, 0, 2);  // 2 ms
  }
  kill_group();
  int status = 0;
  pid_t done = 0;
  while ((done = waitpid(pid_, &status, 0)) < 0 && errno == EINTR) {
  }
  std::string how;
  if (done < 0)
    how = tr("could not be waited for");
  else if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    how = format_text(tr("was killed by signal %d (%s)"), sig, strsignal(sig));
    if (sig == SIGXCPU) how += tr(": it ran past its CPU time");
    if (sig == SIGXFSZ) how += tr(": it wrote more than 64 MiB of output");
  } else if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
    how = format_text(tr("exited with status %d"), WEXITSTATUS(status));
  ended_ = how;
  return how;
}

std::string ChildProcess::run_to_end(std::chrono::seconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (read_line(deadline)) {
  }
  if (timed_out_) {
    wait(std::chrono::milliseconds(0));
    return "ran past " + std::to_string(limit.count()) + " s and was stopped";
  }
  return wait(std::chrono::milliseconds(static_cast<long long>(std::max<long long>(
      0, std::chrono::duration_cast<std::chrono::milliseconds>(deadline -
                                                               std::chrono::steady_clock::now())
             .count()))));
}

std::string last_lines(const std::filesystem::path& file, int lines) {
  std::ifstream in(file);
  std::vector<std::string> all;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) all.push_back(line);
  std::string text;
  for (size_t i = all.size() > static_cast<size_t>(lines) ? all.size() - lines : 0; i < all.size();
       ++i)
    text += (text.empty() ? "" : " | ") + all[i];
  if (text.size() > 400) text = text.substr(0, 400) + "...";
  return text;
}

std::optional<std::filesystem::path> find_program(const std::string& name) {
  if (name.find('/') != std::string::npos) return std::filesystem::path(name);
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  size_t start = 0;
  while (start <= dirs.size()) {
    const size_t end = dirs.find(':', start);
    const std::string dir =
        dirs.substr(start, end == std::string::npos ? std::string::npos : end - start);
    const std::filesystem::path candidate = std::filesystem::path(dir.empty() ? "." : dir) / name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return std::nullopt;
}

}  // namespace springlab::app
