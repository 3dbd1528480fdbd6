// Headless rendering (Google Benchmark): one 1280x720 frame of a cloth, from the simulation's
// state to pixels read back (building the frame, drawing it multisampled, reading it), which is
// what `springlab render` does per frame before the encoder; and the scene's frame alone.
// Run: build/bench/springlab_bench --benchmark_filter=Render
#include <benchmark/benchmark.h>

#include <string>

#include "draw/scene_frame.hpp"
#include "gfx/offscreen.hpp"
#include "session/session.hpp"
#include "springlab/scene.hpp"

namespace springlab {
namespace {

app::Session cloth_session(int side) {
  Scene scene =
      load_scene(std::string(SPRINGLAB_SOURCE_DIR) + "/assets/scenes/cloth.json",
                 {"cloth.width=" + std::to_string(side), "cloth.height=" + std::to_string(side)});
  SimulationSettings settings;
  settings.dt = 5e-4 * 64 / side;  // stable: the step a cloth allows shrinks with its spacing
  app::Session session(std::move(scene), settings, 30.0);
  session.advance_frame();  // in motion, as in a video
  return session;
}

// Frame and pixels: arg = the cloth's side.
void BM_RenderFrame(benchmark::State& state) {
  app::Session session = cloth_session(static_cast<int>(state.range(0)));
  const draw::ViewOptions view = draw::ViewOptions::for_scene(session.scene());
  gfx::Offscreen offscreen(false, 1280, 720, 0.0f);
  app::Image image;
  for (auto _ : state) {
    const draw::Frame frame = draw::build_frame(session, view, draw::Viewport{0, 0, 1280, 720});
    offscreen.render(
        frame, [] {}, image);
    benchmark::DoNotOptimize(image);
  }
  state.SetLabel(offscreen.renderer_name());
  state.counters["frames_per_s"] =
      benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_RenderFrame)->Arg(64)->Arg(128)->UseRealTime()->Unit(benchmark::kMillisecond);

// Building the frame only (the geometry the renderer uploads): arg = the cloth's side.
void BM_BuildFrame(benchmark::State& state) {
  app::Session session = cloth_session(static_cast<int>(state.range(0)));
  const draw::ViewOptions view = draw::ViewOptions::for_scene(session.scene());
  for (auto _ : state)
    benchmark::DoNotOptimize(draw::build_frame(session, view, draw::Viewport{0, 0, 1280, 720}));
}
BENCHMARK(BM_BuildFrame)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace springlab
