// The stability gauge's verdicts (ui/gauge_verdict.hpp) for the rows stable at any step, read as a
// class reads them: what each pays (softness at rest, damping in motion) where it is defined,
// what it breaks (a free body's momentum, a box's cells), and nothing of either where it is not.
#include <gtest/gtest.h>

#include <memory>

#include "session/session.hpp"
#include "springlab/script.hpp"
#include "support.hpp"
#include "ui/gauge_verdict.hpp"

namespace springlab::test {
namespace {

using ui::Tone;

// A session of `scene` under `method` at dt, one step a frame's worth, played for `seconds`.
std::unique_ptr<app::Session> played(Scene scene, Method method, double dt, double seconds,
                                     int substeps = 1) {
  SimulationSettings settings = settings_for(scene);
  settings.method = method;
  settings.dt = dt;
  settings.substeps = substeps;
  settings.auto_substeps = false;
  auto session = std::make_unique<app::Session>(std::move(scene), settings, 60.0);
  for (int frame = 0; frame < static_cast<int>(seconds * 60.0); ++frame) session->advance_frame();
  return session;
}

ui::GaugeVerdict verdict(app::Session& session) {
  app::Lane& lane = session.lanes().front();
  return ui::gauge_verdict(lane, &lane.sim.stability(), true);
}

bool says(const ui::GaugeVerdict& v, const std::string& words) {
  return v.text.find(words) != std::string::npos;
}

constexpr double kFrame = 1.0 / 30.0;

// At rest on the chain (its load on its pins): the stiffness each acts as, `run`'s figures.
TEST(Gauge, AtRestTheStiffnessAnIterativeRowActsAs) {
  auto xpbd = played(shipped("chain"), Method::XPBD, kFrame, 25.0);
  const ui::GaugeVerdict soft = verdict(*xpbd);
  EXPECT_TRUE(says(soft, "bounded; at rest acts as k_s x0.00076")) << soft.text;  // run: 0.000761
  EXPECT_EQ(soft.tone, Tone::Near);
  auto lg = played(shipped("chain"), Method::LocalGlobal, kFrame, 25.0);
  const ui::GaugeVerdict firm = verdict(*lg);
  EXPECT_TRUE(says(firm, "bounded; at rest acts as k_s x1")) << firm.text;  // run: 1.02
  EXPECT_EQ(firm.tone, Tone::Safe);
}

// In motion, the energy it takes beyond the physics' damping (local-global), or puts into its
// springs' stretch, which a few passes or sweeps leave longer than k_s would (XPBD, and VBD too:
// `run` measures 394 J put in over the chain's first half second).
TEST(Gauge, InMotionTheDampingOrTheEnergyPutIn) {
  auto lg = played(shipped("chain"), Method::LocalGlobal, kFrame, 0.5);
  const ui::GaugeVerdict damps = verdict(*lg);
  EXPECT_TRUE(says(damps, "bounded; damps ")) << damps.text;
  EXPECT_EQ(damps.tone, Tone::Safe);
  for (Method method : {Method::XPBD, Method::VBD}) {
    auto session = played(shipped("chain"), method, kFrame, 0.5);
    const ui::GaugeVerdict in = verdict(*session);
    EXPECT_TRUE(says(in, "W into stretch")) << method_info(method).name << ": " << in.text;
    EXPECT_EQ(in.tone, Tone::Near);
  }
}

// The jelly at one step a frame: VBD turns cells inside out, on its ground (no load carried to
// pins, no stiffness to state; contacts take energy the account does not count, no damping
// figure). Implicit Euler's cells stay whole, and at the scene's own step symplectic Euler's
// verdict is its limit's and nothing more.
TEST(Gauge, InvertedCellsAndNothingUndefined) {
  auto vbd = played(shipped("jelly"), Method::VBD, kFrame, 8.0);
  const ui::GaugeVerdict v = verdict(*vbd);
  EXPECT_TRUE(says(v, "; 16 cells inverted")) << v.text;
  EXPECT_FALSE(says(v, "acts as") || says(v, "damps") || says(v, "into stretch")) << v.text;
  EXPECT_EQ(v.tone, Tone::Near);
  auto ie = played(shipped("jelly"), Method::ImplicitEuler, kFrame, 8.0);
  EXPECT_FALSE(says(verdict(*ie), "inverted")) << verdict(*ie).text;
  Scene jelly = shipped("jelly");
  const double dt = jelly.dt;
  auto se = played(std::move(jelly), Method::SymplecticEuler, dt, 2.0, 2);
  const ui::GaugeVerdict safe = verdict(*se);
  EXPECT_TRUE(says(safe, "safe: ")) << safe.text;
  EXPECT_FALSE(says(safe, ";")) << safe.text;
}

// A stiff cloth thrown in empty space (lesson 11's): VBD's momentum off, XPBD's kept and silent.
TEST(Gauge, AFreeBodysBrokenMomentum) {
  const auto thrown = [](Method method) {
    Scene cloth = shipped("cloth", {"cloth.width=12", "cloth.height=12", "cloth.pinned=[]",
                                    "gravity=[0,0,0]", "drag=0"});
    set_stiffness(cloth.model, 20000.0);
    SimulationSettings settings = settings_for(cloth);
    settings.method = method;
    settings.dt = 1.0 / 60.0;
    settings.auto_substeps = false;
    auto session = std::make_unique<app::Session>(std::move(cloth), settings, 60.0);
    session->play(parse_script(
        R"({"events": [{"t": 0.2, "grab": "cloth:0"}, {"t": 0.2, "move": [-1.0, 2.4, 0.4],
                                   "over": 0.25}, {"t": 0.45, "release": true}]})",
        "throw", session->scene()));
    for (int frame = 0; frame < 90; ++frame) session->advance_frame();
    return session;
  };
  auto vbd = thrown(Method::VBD);
  const ui::GaugeVerdict broken = verdict(*vbd);
  EXPECT_TRUE(says(broken, "; momentum off by ")) << broken.text;
  EXPECT_EQ(broken.tone, Tone::Near);
  EXPECT_NE(broken.momentum.find("P not kept"), std::string::npos) << broken.momentum;
  auto xpbd = thrown(Method::XPBD);
  const ui::GaugeVerdict kept = verdict(*xpbd);
  EXPECT_FALSE(says(kept, "momentum")) << kept.text;
  EXPECT_NE(kept.momentum.find("P kept"), std::string::npos) << kept.momentum;
}

}  // namespace
}  // namespace springlab::test
