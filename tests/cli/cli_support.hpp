// Running the springlab executable as a user would, capturing its exit status and output.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace springlab::test {

struct Result {
  int status = -1;
  std::string out, err;
};

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fresh folder for one test, removed at the end.
// The shipped scenes' names (assets/scenes/*.json), sorted: the parameters of the tests that run
// every scene, named for GoogleTest by scene_test_name ("cloth-sphere" -> "cloth_sphere").
inline std::vector<std::string> shipped_scenes() {
  std::vector<std::string> names;
  for (const auto& e :
       std::filesystem::directory_iterator(std::string(SPRINGLAB_SOURCE_DIR) + "/assets/scenes"))
    if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}
inline std::string scene_test_name(std::string name) {
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

struct TempDir {
  std::filesystem::path path;
  TempDir() {
    path = std::filesystem::temp_directory_path() /
           ("springlab-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter()++));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  std::filesystem::path operator/(const std::string& name) const { return path / name; }
  static int& counter() {
    static int n = 0;
    return n;
  }
};

// Runs `PREFIX springlab ARGS` (ARGS already shell-quoted where needed) from `cwd`; PREFIX is a
// wrapper such as "xvfb-run -a ".
inline Result springlab_with(const std::string& prefix, const std::string& args,
                             const std::filesystem::path& cwd = ".") {
  TempDir io;
  const std::string command = "cd '" + cwd.string() + "' && " + prefix +
                              "'" SPRINGLAB_EXECUTABLE "' " + args + " > '" +
                              (io / "out").string() + "' 2> '" + (io / "err").string() + "'";
  const int raw = std::system(command.c_str());
  Result r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.out = read_file(io / "out");
  r.err = read_file(io / "err");
  return r;
}

inline Result springlab(const std::string& args, const std::filesystem::path& cwd = ".") {
  return springlab_with("", args, cwd);
}

inline void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// Runs `ENV springlab ARGS` in a window under Xvfb, as `xvfb-run -a` does, but with the X authority
// file in a folder of the test's own: xvfb-run then has no folder of its own to remove at its end,
// so its exit status is always springlab's. (CI once saw a clean run end with status 5, "xvfb-run:
// error: problem while cleaning up temporary directory".)
inline Result springlab_under_xvfb(const std::string& args, const std::filesystem::path& cwd = ".",
                                   const std::string& env = "") {
  TempDir auth;
  write_file(auth / "Xauthority", "");
  return springlab_with(
      env + "xvfb-run -a -f '" + (auth / "Xauthority").string() + "' -s '-screen 0 1280x720x24' ",
      args, cwd);
}

}  // namespace springlab::test
