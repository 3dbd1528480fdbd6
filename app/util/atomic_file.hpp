// Output that appears whole or not at all: written under a temporary name in the same folder
// and renamed over the final name only when complete. Destroyed without commit() (an error, an
// exception), or on SIGINT/SIGTERM/SIGHUP (remove_pending_outputs_on_interrupt), the temporary
// file is removed.
#pragma once

#include <spawn.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace springlab::app {

// A temporary name for a final path, for writers that open the file themselves (ffmpeg).
class TemporaryPath {
 public:
  // Throws InputError naming the folder if it cannot be written.
  TemporaryPath(const std::filesystem::path& final_path, std::string what);
  ~TemporaryPath();
  TemporaryPath(const TemporaryPath&) = delete;
  TemporaryPath& operator=(const TemporaryPath&) = delete;

  const std::filesystem::path& path() const { return temp_; }
  const std::filesystem::path& final_path() const { return final_; }
  const std::string& what() const { return what_; }
  // Renames the temporary file to the final name. Throws std::runtime_error on failure.
  void commit();
  // Opens the temporary file for writing (nullptr on failure, errno set); never after an interrupt.
  std::FILE* create() const;

 private:
  std::filesystem::path final_, temp_;
  std::string what_;
  bool done_ = false;
};

class AtomicFile {
 public:
  explicit AtomicFile(const std::filesystem::path& final_path, const char* what = "output");
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::FILE* file() { return file_; }
  // Flushes, checks every write succeeded (a full disk fails here), renames. Throws on failure.
  void commit();

 private:
  TemporaryPath path_;
  std::FILE* file_ = nullptr;
};

// Call first thing in main: from then on SIGINT, SIGTERM and SIGHUP are taken by one thread that
// removes every temporary file not yet committed and then lets the signal end the process.
void remove_pending_outputs_on_interrupt();

// For a child spawned after the call above (ffmpeg): it starts with no signal blocked, so that
// Ctrl-C stops it too.
void unblock_interrupts_in_child(posix_spawnattr_t& attributes);

}  // namespace springlab::app
