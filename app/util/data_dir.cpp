#include "util/data_dir.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>

#include "springlab/butcher.hpp"
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

namespace {

// The names of assets/<folder>/*.json, sorted.
std::vector<std::string> shipped(const char* folder) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(data_dir() / "assets" / folder, ec))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A file, or a shipped one of this kind by name; else an InputError naming the shipped ones.
std::string resolve(const char* kind, const char* folder, const std::string& name) {
  std::error_code ec;
  if (fs::is_regular_file(name, ec)) return name;
  const bool looks_like_name = name.find('/') == std::string::npos && !name.ends_with(".json");
  if (looks_like_name) {
    const fs::path path = data_dir() / "assets" / folder / (name + ".json");
    if (fs::is_regular_file(path, ec)) return path.string();
  }
  const auto names = shipped(folder);
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  const std::string near = looks_like_name ? closest_match(name, names.data(), names.size()) : "";
  throw InputError(std::string(kind) + " '" + name + "': no such file" +
                   (looks_like_name ? std::string(", and no shipped ") + kind + " of that name"
                                    : std::string()) +
                   (near.empty() ? "" : "; did you mean '" + near + "'?") + " (shipped: " + list +
                   ")");
}

}  // namespace

std::vector<std::string> shipped_scenes() {
  return shipped("scenes");
}
std::string resolve_scene(const std::string& name) {
  return resolve("scene", "scenes", name);
}
std::vector<std::string> shipped_tableaux() {
  return shipped("tableaux");
}
std::string resolve_tableau(const std::string& name) {
  return resolve("tableau", "tableaux", name);
}

std::optional<Method> lookup_method(const std::string& name) {
  if (const auto m = find_method(name)) return m;
  std::error_code ec;
  fs::path path = name;
  if (!fs::is_regular_file(path, ec)) {
    if (name.find('/') != std::string::npos || name.ends_with(".json")) return std::nullopt;
    path = data_dir() / "assets" / "tableaux" / (name + ".json");
    if (!fs::is_regular_file(path, ec)) return std::nullopt;
  }
  return add_tableau_method(load_tableau_file(path.string()), path.stem().string());
}

std::string method_choices() {
  // The built-in rows, the shipped tableaux (added or not), and apart the user's own rows.
  std::string tableaux, yours;
  const std::vector<std::string> shipped = shipped_tableaux();
  const auto built_in = [](const std::string& n) {
    const auto rows = built_in_methods();
    return std::any_of(rows.begin(), rows.end(), [&](const MethodInfo& m) { return n == m.name; });
  };
  for (const std::string& n : shipped)
    if (!built_in(n)) tableaux += (tableaux.empty() ? "" : ", ") + n;
  for (const MethodInfo& m : added_methods())
    if (std::find(shipped.begin(), shipped.end(), m.name) == shipped.end())
      yours += (yours.empty() ? "" : ", ") + std::string(m.name);
  return "methods: " + method_names() + "; tableaux: " + tableaux +
         (yours.empty() ? "" : "; yours: " + yours) + "; or a tableau's JSON file";
}

}  // namespace springlab::app
