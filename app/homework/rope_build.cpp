#include "homework/rope_build.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include "homework/child_process.hpp"
#include "springlab/error.hpp"
#include "util/data_dir.hpp"

namespace springlab::app {

namespace fs = std::filesystem;

std::string first_error(const std::string& compiler_output) {
  std::istringstream in(compiler_output);
  std::string first, line;
  while (std::getline(in, line)) {
    if (first.empty() && !line.empty()) first = line;
    if (line.find("error:") != std::string::npos || line.find("undefined reference") != std::string::npos) {
      // A linker's line names the object file it was in; what is missing is what matters.
      const size_t ref = line.find("undefined reference");
      if (ref != std::string::npos) return line.substr(ref);
      return line;
    }
  }
  return first;
}

RopeBuild::RopeBuild(const fs::path& source) {
  std::error_code ec;
  if (!fs::is_regular_file(source, ec))
    throw InputError("cannot read " + source.string() + ": no such file (give the path to your rope.cpp)");
  const char* cxx = std::getenv("CXX");
  const auto compiler = find_program(cxx && *cxx ? cxx : "c++");
  if (!compiler)
    throw InputError(std::string("no C++ compiler: ") + (cxx && *cxx ? cxx : "c++") +
                     " is not on PATH (apt-get install g++, or set CXX)");
  std::string pattern = (fs::temp_directory_path() / "springlab-homework-XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot make a folder in " + fs::temp_directory_path().string());
  folder_ = pattern;
  runner_ = folder_ / "rope-runner";

  const fs::path kit = data_dir() / "assets" / "homework";
  const fs::path absolute = fs::absolute(source);
  const std::vector<std::string> argv = {compiler->string(), "-std=c++17", "-O1", "-fdiagnostics-color=never",
                                         "-I" + (kit / "include").string(), "-I" + absolute.parent_path().string(),
                                         absolute.string(), (kit / "runner" / "runner.cpp").string(), "-o", runner_.string()};
  const fs::path log = folder_ / "compiler.txt";
  std::string how;
  {
    ChildProcess compile(argv, log);
    how = compile.run_to_end(std::chrono::seconds(120));
  }
  if (!how.empty()) {
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    const std::string error = first_error(text.str());
    fs::remove_all(folder_, ec);
    throw InputError(source.string() + " does not compile: " + (error.empty() ? "the compiler " + how : error));
  }
}

RopeBuild::~RopeBuild() {
  std::error_code ec;
  fs::remove_all(folder_, ec);
}

}  // namespace springlab::app
