// libFuzzer target: the scene loader (parse_scene) on any bytes. The input is a scene file,
// optionally followed by --set overrides, each after a NUL byte ("{...}\0cloth.width=3").
// Any outcome but a loaded scene that keeps its promises (loader_checks.hpp) or an InputError
// is a bug: a crash, a sanitizer report, another exception (the command line would exit 1
// instead of 2), a leak, or a run past the time and memory limits (tests/fuzz/README.md).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "loader_checks.hpp"
#include "springlab/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t nul; (nul = input.find('\0', start)) != std::string::npos; start = nul + 1)
    parts.push_back(input.substr(start, nul - start));
  parts.push_back(input.substr(start));
  const std::string text = parts.front();
  parts.erase(parts.begin());
  try {
    springlab::fuzz::check_scene(springlab::parse_scene(text, "fuzz.json", parts));
  } catch (const springlab::InputError&) {
  }
  return 0;
}
