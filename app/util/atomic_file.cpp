#include "util/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <mutex>

#include "springlab/error.hpp"

namespace springlab::app {

namespace {
// Temporary files not yet committed; a plain array so that the signal handler can walk it.
constexpr int kMaxPending = 64;
char g_pending[kMaxPending][4096];
std::mutex g_mutex;

void add_pending(const std::string& path) {
  std::lock_guard lock(g_mutex);
  for (auto& slot : g_pending)
    if (slot[0] == '\0') {
      std::strncpy(slot, path.c_str(), sizeof slot - 1);
      return;
    }
}

void drop_pending(const std::string& path) {
  std::lock_guard lock(g_mutex);
  for (auto& slot : g_pending)
    if (path == slot) slot[0] = '\0';
}
}  // namespace

void remove_pending_outputs() {
  for (auto& slot : g_pending)
    if (slot[0] != '\0') ::unlink(slot);
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
  add_pending(temp_.string());
}

TemporaryPath::~TemporaryPath() {
  if (!done_) std::remove(temp_.c_str());
  drop_pending(temp_.string());
}

void TemporaryPath::commit() {
  std::error_code ec;
  std::filesystem::rename(temp_, final_, ec);
  if (ec) throw std::runtime_error("writing " + what_ + " '" + final_.string() + "' failed: " + ec.message());
  done_ = true;
  drop_pending(temp_.string());
}

AtomicFile::AtomicFile(const std::filesystem::path& final_path, const char* what) : path_(final_path, what) {
  file_ = std::fopen(path_.path().c_str(), "wb");
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
    throw std::runtime_error("writing " + path_.what() + " '" + path_.final_path().string() + "' failed (" +
                             std::strerror(written ? errno : error) + "); nothing was left behind");
  path_.commit();
}

}  // namespace springlab::app
