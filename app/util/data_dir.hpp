// Where the shipped data is: assets/ (scenes, scripts, fonts) and shaders/. Looked up, in order:
// $SPRINGLAB_DATA, <executable>/../share/springlab (installed), the source tree the executable
// was built from; so the executable runs from any working folder.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace springlab::app {

const std::filesystem::path& data_dir();

// The scene named on the command line: a path to a JSON file, or the name of a shipped scene
// ("rope" is assets/scenes/rope.json). Throws InputError naming the shipped scenes.
std::string resolve_scene(const std::string& name_or_path);

// Names of the shipped scenes, sorted.
std::vector<std::string> shipped_scenes();

// The same for tableaux (assets/tableaux/NAME.json): "rk4", or a path to a JSON file.
std::string resolve_tableau(const std::string& name_or_path);
std::vector<std::string> shipped_tableaux();

}  // namespace springlab::app
