#include "util/atomic_file.hpp"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <mutex>

#include "springlab/error.hpp"
#include "util/worker.hpp"

namespace springlab::app {

namespace {
// Temporary files not yet committed. Creating, committing and removing one all hold g_mutex, and
// the interrupt thread takes it for good before removing them: a writer on another thread cannot
// create a file after the removal, nor rename half of one.
constexpr int kMaxPending = 64;
char g_pending[kMaxPending][4096];
std::mutex g_mutex;

void add_pending(const std::string& path) {
  for (auto& slot : g_pending)
    if (slot[0] == '\0') {
      std::strncpy(slot, path.c_str(), sizeof slot - 1);
      return;
    }
}

void drop_pending(const std::string& path) {
  for (auto& slot : g_pending)
    if (path == slot) slot[0] = '\0';
}

void remove_pending_outputs() {
  for (auto& slot : g_pending)
    if (slot[0] != '\0') ::unlink(slot);
}

sigset_t interrupt_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  sigaddset(&set, SIGHUP);
  return set;
}
}  // namespace

void remove_pending_outputs_on_interrupt() {
  // Blocked here, before any other thread exists, so every thread (the frame writer, OpenMP's,
  // the window system's) inherits the mask and only the thread below ever takes these signals.
  const sigset_t set = interrupt_signals();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  Worker::detach([set] {
    int signal = 0;
    while (sigwait(&set, &signal) != 0) {
    }
    g_mutex.lock();  // never released: no output is created or committed from here on
    remove_pending_outputs();
    // Die of the signal, as without a handler, so that the shell and the parent see it.
    std::signal(signal, SIG_DFL);
    sigset_t one;
    sigemptyset(&one);
    sigaddset(&one, signal);
    pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
    ::raise(signal);
  });
}

void unblock_interrupts_in_child(posix_spawnattr_t& attributes) {
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
}

TemporaryPath::TemporaryPath(const std::filesystem::path& final_path, std::string what)
    : final_(final_path), what_(std::move(what)) {
  const std::filesystem::path dir = final_.has_parent_path() ? final_.parent_path() : ".";
  std::string name = ".";
  name += final_.filename().string();
  name += ".tmp-";
  name += std::to_string(::getpid());
  temp_ = dir / name;
  if (::access(dir.c_str(), W_OK) != 0)
    throw InputError(what_ + " '" + final_.string() + "': cannot write in folder '" + dir.string() +
                     "' (" + std::strerror(errno) + ")");
  std::lock_guard lock(g_mutex);
  add_pending(temp_.string());
}

TemporaryPath::~TemporaryPath() {
  std::lock_guard lock(g_mutex);
  if (!done_) std::remove(temp_.c_str());
  drop_pending(temp_.string());
}

void TemporaryPath::commit() {
  std::lock_guard lock(g_mutex);
  std::error_code ec;
  std::filesystem::rename(temp_, final_, ec);
  if (ec)
    throw std::runtime_error("writing " + what_ + " '" + final_.string() +
                             "' failed: " + ec.message());
  done_ = true;
  drop_pending(temp_.string());
}

std::FILE* TemporaryPath::create() const {
  std::lock_guard lock(g_mutex);
  return std::fopen(temp_.c_str(), "wb");
}

AtomicFile::AtomicFile(const std::filesystem::path& final_path, const char* what)
    : path_(final_path, what) {
  file_ = path_.create();
  if (!file_)
    throw InputError(path_.what() + " '" + final_path.string() + "': cannot be written (" +
                     std::strerror(errno) + ")");
}

AtomicFile::~AtomicFile() {
  if (file_) std::fclose(file_);
}

void AtomicFile::commit() {
  const bool written = std::fflush(file_) == 0 && !std::ferror(file_);
  const int error = errno;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!written || !closed)
    throw std::runtime_error("writing " + path_.what() + " '" + path_.final_path().string() +
                             "' failed (" + std::strerror(written ? errno : error) +
                             "); nothing was left behind");
  path_.commit();
}

}  // namespace springlab::app
