// Where the shipped data is: assets/ (scenes, scripts, fonts) and shaders/. Looked up, in order:
// $SPRINGLAB_DATA, <executable>/../share/springlab (installed), the source tree the executable
// was built from; so the executable runs from any working folder.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "springlab/methods.hpp"

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

// A method as named on the command line: a built-in method ("rk4"), a shipped tableau ("heun",
// assets/tableaux) or a tableau file ("mine.json"), which is then added to the method table
// (add_tableau_method) under its name or its file's stem. nullopt when it is none of these; a
// tableau file with an error throws its InputError.
std::optional<Method> lookup_method(const std::string& name);
// "methods: euler, ...; tableaux: heun, ... or a tableau file" for messages.
std::string method_choices();

}  // namespace springlab::app
