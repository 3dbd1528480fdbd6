// libFuzzer target: the script loader (parse_script) on any bytes, against a small scene with a
// rope and a cloth named like the shipped scenes' generators ("rope:-1", "cloth:0" resolve).
// A loaded script is then described and played through path_position, as the app does. Any
// outcome but that or an InputError is a bug (see scene_fuzz.cpp).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "loader_checks.hpp"
#include "springlab/error.hpp"
#include "springlab/script.hpp"

namespace {

const springlab::Scene& scene() {
  static const springlab::Scene s = springlab::parse_scene(R"({
    "particles": [{"position": [0, 0, 0], "pinned": true}, {"position": [1.5, 0, 0]}],
    "springs": [{"a": 0, "b": 1, "ks": 100, "rest_length": 1}],
    "generators": [
      {"type": "rope", "name": "rope", "start": [0, 0, 0], "end": [4, 0, 0], "nodes": 16, "stiffness": 2000},
      {"type": "cloth", "name": "cloth", "width": 6, "height": 6, "stretch": 400}]})",
                                                           "fuzz-scene.json");
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using springlab::fuzz::require;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const springlab::Script script = springlab::parse_script(text, "fuzz-script.json", scene());
    const double end = script.end_time();
    require(std::isfinite(end) && end >= 0, "a finite end time");
    for (const springlab::ScriptEvent& e : script.events) {
      require(!e.describe().empty(), "every event describes itself");
      require(e.particle >= -1 && e.particle < scene().model.particle_count(),
              "grabs index particles");
      if (e.path.empty()) continue;
      for (double t : {-1.0, 0.0, 0.5 * e.path.back().first, e.path.back().first + 1.0})
        require(springlab::path_position(e.path, t).allFinite(), "paths finite");
    }
  } catch (const springlab::InputError&) {
  }
  return 0;
}
