// Loads a scene file, steps it with two methods for a second, and prints each one's energy:
// springlab's core as a library. Usage: consumer SCENE.json
#include <cstdio>
#include <exception>

#include "springlab/scene.hpp"
#include "springlab/simulation.hpp"
#include "springlab/version.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer SCENE.json\n");
    return 2;
  }
  try {
    const springlab::Scene scene = springlab::load_scene(argv[1]);
    std::printf("springlab %s: %d particles, %d springs\n", springlab::kVersion,
                scene.model.particle_count(), scene.model.spring_count());
    for (springlab::Method method : {springlab::Method::SymplecticEuler, springlab::Method::RK4}) {
      springlab::SimulationSettings settings;
      settings.method = method;
      settings.dt = scene.dt;
      springlab::Simulation sim(scene.model, scene.state, settings);
      const double start = sim.energy().total();
      const auto steps = static_cast<std::int64_t>(1.0 / scene.dt + 0.5);
      sim.advance(steps);
      // As `springlab run` prints it ("total %g J").
      std::printf("%s: energy total %g J after %lld steps (initially %g J)\n",
                  springlab::method_info(method).name, sim.energy().total(),
                  static_cast<long long>(steps), start);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
  return 0;
}
