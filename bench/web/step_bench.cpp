// ns per spring-step of the core compiled to WebAssembly (one thread), measured as `springlab
// bench` measures it natively: the same prepare(), a tenth of the steps to warm up, then the
// fastest of `repeat` timed runs of `steps` steps. Run in Chromium by scripts/web-bench.sh
// through bench.html, with arguments as key=value words:
//   scene=cloth method=symplectic-euler dt=5e-4 steps=4000 repeat=5 set=cloth.width=64 ...
#include <emscripten.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>

#include "options/scene_options.hpp"

int main(int argc, char** argv) {
  using namespace springlab;
  std::string scene = "rope";
  app::SimOptions options;
  int repeat = 5;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      const std::size_t eq = arg.find('=');
      const std::string key = arg.substr(0, eq),
                        value = eq == std::string::npos ? "" : arg.substr(eq + 1);
      if (key == "scene")
        scene = value;
      else if (key == "method")
        options.method = value;
      else if (key == "dt")
        options.dt = std::stod(value);
      else if (key == "steps")
        options.steps = std::stoll(value);
      else if (key == "repeat")
        repeat = std::max(1, std::stoi(value));
      else if (key == "set")
        options.sets.push_back(value);
      else
        throw std::invalid_argument("unknown argument '" + arg + "'");
    }
    app::Prepared p = app::prepare(scene, options);
    Simulation s(std::move(p.scene.model), std::move(p.scene.state), p.settings);
    s.advance(std::max<std::int64_t>(1, p.steps / 10));
    double fastest = 1e300;
    std::int64_t taken = 0;
    for (int run = 0; run < repeat; ++run) {
      const auto start = std::chrono::steady_clock::now();
      taken = s.advance(p.steps);
      fastest = std::min(
          fastest, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    const double springs = s.model().spring_count();
    std::printf(
        "springs=%g\nsteps=%lld\nsubsteps=%d\nseconds=%.6g\nns_per_spring_step=%.4g\ndiverged=%d\n",
        springs, static_cast<long long>(taken), s.settings().substeps, fastest,
        1e9 * fastest / (static_cast<double>(taken) * s.settings().substeps * springs),
        s.diverged() ? 1 : 0);
    EM_ASM({ window.benchFinished(0); });
    return 0;
  } catch (const std::exception& e) {
    std::printf("error=%s\n", e.what());
    EM_ASM({ window.benchFinished(1); });
    return 1;
  }
}
