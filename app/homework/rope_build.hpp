// Building a student's rope.cpp into the rope runner (assets/homework/runner/runner.cpp): the
// machine's C++ compiler ($CXX, else c++), in a folder of its own that goes away with the Build.
// Both are compiled against the same headers: the student's own rope.h, mass.h, spring.h (and
// CGL/) where they are beside rope.cpp, the exercise's (assets/homework/include) otherwise, so
// that a changed header (an extra member, a destructor, a default initialiser) means the same in
// the student's code and in the runner that calls it. The two compile at once; the runner's object
// is kept between builds in the user's cache, keyed by everything it was built from.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace springlab::app {

class RopeBuild {
 public:
  /// Compiles `source` (a rope.cpp, or a folder holding one, or its src/) with the runner.
  /// Throws InputError for a file that is missing or does not compile (the compiler's first
  /// error, with its file and line), for headers of the student's that change what the checker
  /// calls (said with the exercise's declaration), for a step declared but not defined, and for a
  /// missing compiler.
  explicit RopeBuild(const std::filesystem::path& source);
  ~RopeBuild();
  RopeBuild(const RopeBuild&) = delete;
  RopeBuild& operator=(const RopeBuild&) = delete;

  const std::filesystem::path& runner() const { return runner_; }
  const std::filesystem::path& folder() const { return folder_; }
  /// The rope.cpp compiled (the file named, or the one found in the folder named).
  const std::filesystem::path& source() const { return source_; }
  /// The exercise's headers the student has their own copy of, beside rope.cpp ("rope.h", ...).
  const std::vector<std::string>& own_headers() const { return own_headers_; }

 private:
  std::filesystem::path folder_, runner_, source_;
  std::vector<std::string> own_headers_;
};

/// The rope.cpp a path names: the file itself, or rope.cpp in the folder or in its src/.
/// Throws InputError when there is none.
std::filesystem::path find_rope_source(const std::filesystem::path& path);

/// The line of a compiler's output that names the first error ("rope.cpp:12:5: error: ..."; a
/// linker's "undefined reference to ..."); the first line if none says error.
std::string first_error(const std::string& compiler_output);

}  // namespace springlab::app
