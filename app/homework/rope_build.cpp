#include "homework/rope_build.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <vector>

#include "homework/child_process.hpp"
#include "springlab/error.hpp"
#include "util/data_dir.hpp"

namespace springlab::app {

namespace fs = std::filesystem;

namespace {

// The exercise's headers a student may have their own copy of.
const char* const kHeaders[] = {"rope.h",    "mass.h",         "spring.h",
                                "CGL/CGL.h", "CGL/vector2D.h", "CGL/misc.h"};

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// What the checker calls, as the exercise declares it, by the name a compiler's error mentions.
std::string declared(const std::string& error) {
  struct Declaration {
    const char* name;
    const char* exercise;
  };
  const Declaration declarations[] = {
      {"simulateEuler", "void simulateEuler(float delta_t, Vector2D gravity)"},
      {"simulateVerlet", "void simulateVerlet(float delta_t, Vector2D gravity)"},
      {"Rope",
       "Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, vector<int> "
       "pinned_nodes)"},
      {"Spring",
       "struct Spring { Spring(Mass *a, Mass *b, float k); float k; double rest_length; Mass *m1, "
       "*m2; }"},
      {"Mass",
       "struct Mass { Mass(Vector2D position, float mass, bool pinned); float mass; bool pinned; "
       "Vector2D "
       "start_position, position, last_position, velocity, forces; }"},
  };
  for (const Declaration& d : declarations)
    if (error.find(d.name) != std::string::npos)
      return std::string(" The exercise declares ") + d.exercise + ".";
  return " The checker calls the constructor and the two steps, and reads the masses and springs, "
         "as the exercise's "
         "rope.h, mass.h and spring.h declare them.";
}

std::string first_error_in(const fs::path& log) {
  return first_error(read_text(log));
}

// The user's cache for the runner's object: $XDG_CACHE_HOME/springlab, else ~/.cache/springlab;
// empty where there is none to be had.
fs::path cache_folder() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  const char* home = std::getenv("HOME");
  fs::path folder;
  if (xdg && *xdg)
    folder = fs::path(xdg) / "springlab" / "homework";
  else if (home && *home)
    folder = fs::path(home) / ".cache" / "springlab" / "homework";
  else
    return {};
  std::error_code ec;
  fs::create_directories(folder, ec);
  return ec ? fs::path() : folder;
}

// A key for everything the runner's object is built from: the compiler (its path, size and
// time), the flags, the runner's source and every header it can see (the student's folder's
// headers, whatever their names, and the exercise's).
std::string runner_key(const fs::path& compiler, const std::vector<std::string>& flags,
                       const fs::path& runner, const std::vector<fs::path>& include_dirs) {
  std::string all = compiler.string();
  std::error_code ec;
  all += std::to_string(fs::file_size(compiler, ec));
  all += std::to_string(fs::last_write_time(compiler, ec).time_since_epoch().count());
  for (const std::string& f : flags)
    if (f.rfind("-I", 0) != 0) all += "\n" + f;
  all += read_text(runner);
  for (size_t d = 0; d < include_dirs.size(); ++d)
    for (const fs::path& dir : {include_dirs[d], include_dirs[d] / "CGL"}) {
      std::vector<fs::path> headers;
      for (const auto& entry : fs::directory_iterator(dir, ec))
        if (entry.path().extension() == ".h" || entry.path().extension() == ".hpp")
          headers.push_back(entry.path());
      std::sort(headers.begin(), headers.end());
      for (const fs::path& file : headers)
        all += "\n" + std::to_string(d) + ":" + fs::relative(file, include_dirs[d], ec).string() +
               "\n" + read_text(file);
    }
  char text[32];
  std::snprintf(text, sizeof text, "%016zx", std::hash<std::string>{}(all));
  return text;
}

// The runner's object kept in the cache for the next build: written under a name of its own,
// then renamed (atomic); the part removed where either failed.
void keep_runner_object(const fs::path& runner_object, const fs::path& cached) {
  std::error_code ec;
  const fs::path part = cached.string() + "." + std::to_string(::getpid());
  if (fs::copy_file(runner_object, part, fs::copy_options::overwrite_existing, ec))
    fs::rename(part, cached, ec);
  if (ec) fs::remove(part, ec);
}

// The two objects linked into `runner` (its log, link.txt, in `folder`). Throws InputError where
// they do not link: a step declared but not defined said as such, else the linker's first error.
void link_rope_runner(const fs::path& compiler, const fs::path& rope_object,
                      const fs::path& runner_object, const fs::path& runner, const fs::path& folder,
                      const fs::path& source) {
  const std::vector<std::string> link = {compiler.string(), rope_object.string(),
                                         runner_object.string(), "-o", runner.string()};
  const std::string link_how =
      ChildProcess(link, folder / "link.txt").run_to_end(std::chrono::seconds(120));
  if (!link_how.empty()) {
    const std::string error = first_error_in(folder / "link.txt");
    if (error.find("undefined reference") != std::string::npos)
      throw InputError(source.string() + " compiles, but does not define what the checker calls: " +
                       error + " (rope.h declares it: write it in rope.cpp)");
    throw InputError(source.string() +
                     " does not link: " + (error.empty() ? "the linker " + link_how : error));
  }
}

}  // namespace

std::string first_error(const std::string& compiler_output) {
  std::istringstream in(compiler_output);
  std::string first, line;
  while (std::getline(in, line)) {
    if (first.empty() && !line.empty()) first = line;
    if (line.find("error:") != std::string::npos ||
        line.find("undefined reference") != std::string::npos) {
      // A linker's line names the object file it was in; what is missing is what matters.
      const size_t ref = line.find("undefined reference");
      if (ref != std::string::npos) return line.substr(ref);
      return line;
    }
  }
  return first;
}

fs::path find_rope_source(const fs::path& path) {
  std::error_code ec;
  if (fs::is_regular_file(path, ec)) {
    const std::string ext = path.extension().string();
    if (ext == ".h" || ext == ".hpp" || ext == ".hh")
      throw InputError(path.string() + " is a header: give your rope.cpp (its headers beside it " +
                       "are used with it), or the folder that holds it");
    return path;
  }
  if (fs::is_directory(path, ec)) {
    // A rope.cpp at the top and another in its src folder, not the same: which one is the work is
    // not ours to guess.
    const fs::path top = path / "rope.cpp", src = path / "src" / "rope.cpp";
    if (fs::is_regular_file(top, ec) && fs::is_regular_file(src, ec) &&
        read_text(top) != read_text(src))
      throw InputError("two different rope.cpp: " + top.string() + " and " + src.string() +
                       " (give the path to the one to check)");
    for (const fs::path& candidate : {top, src})
      if (fs::is_regular_file(candidate, ec)) return candidate;
    throw InputError("no rope.cpp in " + path.string() + " nor in " + (path / "src").string() +
                     " (give the path to your rope.cpp, or the folder that holds it)");
  }
  throw InputError("cannot read " + path.string() +
                   ": no such file (give the path to your rope.cpp)");
}

RopeBuild::RopeBuild(const fs::path& path) {
  source_ = find_rope_source(path);
  const char* cxx = std::getenv("CXX");
  const auto compiler = find_program(cxx && *cxx ? cxx : "c++");
  if (!compiler)
    throw InputError(std::string("no C++ compiler: ") + (cxx && *cxx ? cxx : "c++") +
                     " is not on PATH (apt-get install g++, or set CXX)");
  std::string pattern = (fs::temp_directory_path() / "springlab-homework-XXXXXX").string();
  if (!mkdtemp(pattern.data()))
    throw std::runtime_error("cannot make a folder in " + fs::temp_directory_path().string());
  folder_ = pattern;
  runner_ = folder_ / "rope-runner";
  // The folder goes if anything below throws (the destructor does not run for a constructor that
  // throws).
  std::unique_ptr<fs::path, void (*)(fs::path*)> cleanup(&folder_, [](fs::path* f) {
    std::error_code ec;
    fs::remove_all(*f, ec);
  });

  const fs::path kit = data_dir() / "assets" / "homework";
  const fs::path absolute = fs::absolute(source_);
  const fs::path own = absolute.parent_path();
  std::error_code ec;
  for (const char* header : kHeaders)
    if (fs::is_regular_file(own / header, ec)) own_headers_.push_back(header);
  // The student's headers first, for rope.cpp and the runner alike.
  const std::vector<fs::path> include_dirs = {own, kit / "include"};
  // The standard library's own checks on (_GLIBCXX_ASSERTIONS): an index past a vector's end
  // stops with a message instead of reading garbage (pinned_nodes read as a flag per node pinned
  // masses at random).
  std::vector<std::string> flags = {"-std=c++17", "-O1", "-fdiagnostics-color=never",
                                    "-D_GLIBCXX_ASSERTIONS"};
  for (const fs::path& dir : include_dirs) flags.push_back("-I" + dir.string());
  auto compile = [&](const fs::path& file, const fs::path& object, const fs::path& log) {
    std::vector<std::string> argv{compiler->string()};
    argv.insert(argv.end(), flags.begin(), flags.end());
    argv.insert(argv.end(), {"-c", file.string(), "-o", object.string()});
    return std::make_unique<ChildProcess>(argv, log);
  };

  const fs::path runner_source = kit / "runner" / "runner.cpp";
  const fs::path cache = cache_folder();
  const fs::path cached =
      cache.empty()
          ? fs::path()
          : cache / ("runner-" + runner_key(*compiler, flags, runner_source, include_dirs) + ".o");
  const fs::path rope_object = folder_ / "rope.o", runner_object = folder_ / "runner.o";
  const bool have_runner = !cached.empty() && fs::is_regular_file(cached, ec) &&
                           fs::copy_file(cached, runner_object, ec);
  // Both at once: the runner's object (unless cached) and the student's file.
  auto rope_compile = compile(absolute, rope_object, folder_ / "rope.txt");
  auto runner_compile =
      have_runner ? nullptr : compile(runner_source, runner_object, folder_ / "runner.txt");
  const std::string rope_how = rope_compile->run_to_end(std::chrono::seconds(120));
  const std::string runner_how =
      runner_compile ? runner_compile->run_to_end(std::chrono::seconds(120)) : "";
  if (!rope_how.empty()) {
    const std::string error = first_error_in(folder_ / "rope.txt");
    throw InputError(source_.string() +
                     " does not compile: " + (error.empty() ? "the compiler " + rope_how : error));
  }
  if (!runner_how.empty()) {
    const std::string error = first_error_in(folder_ / "runner.txt");
    std::string whose;
    for (const std::string& h : own_headers_) whose += (whose.empty() ? "" : ", ") + h;
    throw InputError(source_.string() + " compiles, but the checker cannot call it through " +
                     (whose.empty() ? std::string("the exercise's headers") : "your " + whose) +
                     ": " + (error.empty() ? "the compiler " + runner_how : error) + "." +
                     declared(error));
  }
  if (!cached.empty() && !have_runner) keep_runner_object(runner_object, cached);
  link_rope_runner(*compiler, rope_object, runner_object, runner_, folder_, source_);
  (void)cleanup.release();  // built: the folder stays
}

RopeBuild::~RopeBuild() {
  std::error_code ec;
  fs::remove_all(folder_, ec);
}

}  // namespace springlab::app
