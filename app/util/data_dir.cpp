#include "util/data_dir.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>

#include "springlab/error.hpp"

namespace springlab::app {

namespace fs = std::filesystem;

const fs::path& data_dir() {
  static const fs::path dir = [] {
    std::vector<fs::path> candidates;
    if (const char* env = std::getenv("SPRINGLAB_DATA")) candidates.emplace_back(env);
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) candidates.push_back(exe.parent_path().parent_path() / "share" / "springlab");
    candidates.emplace_back(SPRINGLAB_SOURCE_DIR);
    for (const fs::path& c : candidates)
      if (fs::is_directory(c / "assets" / "scenes", ec)) return c;
    return fs::path(SPRINGLAB_SOURCE_DIR);
  }();
  return dir;
}

std::vector<std::string> shipped_scenes() {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(data_dir() / "assets" / "scenes", ec))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string resolve_scene(const std::string& name) {
  std::error_code ec;
  if (fs::is_regular_file(name, ec)) return name;
  const bool looks_like_name = name.find('/') == std::string::npos && !name.ends_with(".json");
  if (looks_like_name) {
    const fs::path shipped = data_dir() / "assets" / "scenes" / (name + ".json");
    if (fs::is_regular_file(shipped, ec)) return shipped.string();
  }
  const auto names = shipped_scenes();
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  const std::string near = looks_like_name ? closest_match(name, names.data(), names.size()) : "";
  throw InputError("scene '" + name + "': no such file" +
                   (looks_like_name ? ", and no shipped scene of that name" : "") +
                   (near.empty() ? "" : "; did you mean '" + near + "'?") + " (shipped: " + list + ")");
}

}  // namespace springlab::app
