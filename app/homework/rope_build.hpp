// Building a student's rope.cpp into the rope runner (assets/homework/runner/runner.cpp, with the
// exercise's headers in assets/homework/include): the machine's C++ compiler ($CXX, else c++),
// in a folder of its own that goes away with the Build.
#pragma once

#include <filesystem>
#include <string>

namespace springlab::app {

class RopeBuild {
 public:
  /// Compiles `source` with the runner. Throws InputError for a file that is missing or does not
  /// compile (the compiler's first error, with its file and line) and for a missing compiler.
  explicit RopeBuild(const std::filesystem::path& source);
  ~RopeBuild();
  RopeBuild(const RopeBuild&) = delete;
  RopeBuild& operator=(const RopeBuild&) = delete;

  const std::filesystem::path& runner() const { return runner_; }
  const std::filesystem::path& folder() const { return folder_; }

 private:
  std::filesystem::path folder_, runner_;
};

/// The line of a compiler's output that names the first error ("rope.cpp:12:5: error: ..."; a
/// linker's "undefined reference to ..."); the first line if none says error.
std::string first_error(const std::string& compiler_output);

}  // namespace springlab::app
