// springlab list: the shipped scenes and the methods, one a line.
#include <cmath>
#include <cstdio>

#include "cli/commands.hpp"
#include "springlab/error.hpp"
#include "springlab/methods.hpp"
#include "springlab/scene.hpp"
#include "util/data_dir.hpp"

namespace springlab::app {

Command add_list_command(CLI::App& app) {
  app.add_subcommand("list", "list the shipped scenes and the methods, one a line");
  return [] {
    for (const std::string& name : shipped_scenes()) {
      std::string description;
      try {
        description = load_scene(resolve_scene(name)).description;
      } catch (const InputError& e) {
        description = std::string("(does not load: ") + e.what() + ")";
      }
      std::printf("scene   %-18s %s\n", name.c_str(), description.c_str());
    }
    for (const MethodInfo& m : methods()) {
      char limit[64];
      if (std::isnan(m.undamped_limit))
        std::snprintf(limit, sizeof limit, "adaptive step");
      else if (std::isinf(m.undamped_limit))
        std::snprintf(limit, sizeof limit, "stable at any step");
      else if (m.undamped_limit == 0.0)
        std::snprintf(limit, sizeof limit, "unstable undamped");
      else
        std::snprintf(limit, sizeof limit, "stable for h w <= %.3g", m.undamped_limit);
      std::printf(
          "method  %-18s %s: order %d, force evaluations per step: %s, %s; keeps on a free body: "
          "%s\n",
          m.name, m.label, m.order, m.evaluations, limit, kept_summary(m).c_str());
    }
    return kOk;
  };
}

}  // namespace springlab::app
