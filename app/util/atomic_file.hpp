// Output that appears whole or not at all: written under a temporary name in the same folder
// and renamed over the final name only when complete. Destroyed without commit() (an error, an
// exception, Ctrl-C through the signal handler), it removes the temporary file.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

namespace springlab::app {

class AtomicFile {
 public:
  // Opens "<dir>/.<name>.tmp-<pid>" for writing; throws InputError if the folder cannot be
  // written, naming it.
  explicit AtomicFile(const std::filesystem::path& final_path, const char* what = "output");
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::FILE* file() { return file_; }
  // Flushes, checks every write succeeded (a full disk fails here), renames. Throws on failure.
  void commit();
  const std::filesystem::path& temporary_path() const { return temp_; }

 private:
  std::filesystem::path final_, temp_;
  std::string what_;
  std::FILE* file_ = nullptr;
};

// Removes every temporary file still open (for the SIGINT/SIGTERM handler).
void remove_pending_outputs();

}  // namespace springlab::app
