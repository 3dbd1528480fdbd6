#include "util/atomic_file.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <mutex>
#include <vector>

#include "springlab/error.hpp"

namespace springlab::app {

namespace {
// Temporary files open now. Plain array so that the signal handler can walk it.
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
    if (slot[0] != '\0') ::unlink(slot);  // async-signal-safe
}

AtomicFile::AtomicFile(const std::filesystem::path& final_path, const char* what)
    : final_(final_path), what_(what) {
  const std::filesystem::path dir = final_.has_parent_path() ? final_.parent_path() : ".";
  std::string name = ".";
  name += final_.filename().string();
  name += ".tmp-";
  name += std::to_string(::getpid());
  temp_ = dir / name;
  file_ = std::fopen(temp_.c_str(), "wb");
  if (!file_)
    throw InputError(what_ + " '" + final_.string() + "': cannot write in folder '" + dir.string() +
                     "' (" + std::strerror(errno) + ")");
  add_pending(temp_.string());
}

AtomicFile::~AtomicFile() {
  if (file_) {
    std::fclose(file_);
    std::remove(temp_.c_str());
    drop_pending(temp_.string());
  }
}

void AtomicFile::commit() {
  const bool written = std::fflush(file_) == 0 && !std::ferror(file_);
  const int error = errno;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!written || !closed) {
    std::remove(temp_.c_str());
    drop_pending(temp_.string());
    throw std::runtime_error("writing " + what_ + " '" + final_.string() + "' failed (" +
                             std::strerror(written ? errno : error) + "); nothing was left behind");
  }
  std::error_code ec;
  std::filesystem::rename(temp_, final_, ec);
  drop_pending(temp_.string());
  if (ec) {
    std::remove(temp_.c_str());
    throw std::runtime_error("writing " + what_ + " '" + final_.string() + "' failed: " + ec.message());
  }
}

}  // namespace springlab::app
