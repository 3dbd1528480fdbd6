// Scenes: every shipped scene loads and runs its default method for a few seconds without
// diverging; the generators build what they say (counts, rest lengths, outward surfaces, a finer
// rope is the same rope); bad files fail with the file and the field named.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>

#include "springlab/error.hpp"
#include "springlab/momentum.hpp"
#include "springlab/stability.hpp"
#include "support.hpp"

namespace springlab {
namespace {

std::vector<std::string> shipped_names() {
  std::vector<std::string> names;
  for (const auto& e :
       std::filesystem::directory_iterator(std::string(SPRINGLAB_SOURCE_DIR) + "/assets/scenes"))
    if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(Scenes, TheShippedSetIsComplete) {
  const auto names = shipped_names();
  for (const char* required :
       {"spring", "damped-spring", "rope", "chain", "cloth", "cloth-sphere", "jelly", "stiff"})
    EXPECT_NE(std::find(names.begin(), names.end(), required), names.end()) << required;
}

TEST(Scenes, EveryShippedSceneRunsItsDefaultForThreeSeconds) {
  for (const std::string& name : shipped_names()) {
    const Scene scene = test::shipped(name);
    EXPECT_FALSE(scene.description.empty()) << name;
    Simulation sim = test::simulation(scene, scene.methods.front(), scene.dt, scene.substeps);
    const auto steps = static_cast<std::int64_t>(std::ceil(3.0 / scene.dt));
    EXPECT_EQ(sim.advance(steps), steps)
        << name << ": " << (sim.diverged() ? sim.divergence()->message() : "");
  }
}

TEST(Scenes, SpringIsExactlyTheReference) {
  const Scene s = test::shipped("spring");
  ASSERT_EQ(s.model.particle_count(), 2);
  ASSERT_EQ(s.model.spring_count(), 1);
  EXPECT_TRUE(s.model.pinned(0));
  EXPECT_EQ(s.model.mass[1], 1.0);
  EXPECT_EQ(s.state.x.row(0), Eigen::RowVector3d(0, 0, 0));
  EXPECT_EQ(s.state.x.row(1), Eigen::RowVector3d(1.5, 0, 0));
  EXPECT_EQ(s.model.rest_length[0], 1.0);
  EXPECT_EQ(s.model.ks(0), 100.0);
  EXPECT_EQ(s.model.kd(0), 0.0);
  EXPECT_EQ(s.model.gravity, Vec3::Zero());
  EXPECT_EQ(s.model.drag, 0.0);
  EXPECT_FALSE(s.model.has_colliders());
}

TEST(Scenes, StiffDefeatsExplicitMethodsAtItsDefaultStep) {
  const Scene s = test::shipped("stiff");
  const StabilityAnalysis a(s.model, s.state);
  EXPECT_GT(s.dt, a.limit(Method::RK4).h);
  EXPECT_GT(s.dt, a.limit(Method::SymplecticEuler).h);
  EXPECT_EQ(s.methods.front(), Method::ImplicitEuler);
}

TEST(Scenes, RopeShowsExplicitEulerBesideVerlet) {
  const Scene s = test::shipped("rope");
  ASSERT_EQ(s.methods.size(), 2u);
  EXPECT_EQ(s.methods[0], Method::Euler);
  EXPECT_EQ(s.methods[1], Method::Verlet);
}

TEST(Generators, ClothHasItsSpringsAndTwoPinnedCorners) {
  const Scene s = test::shipped("cloth", {"cloth.width=5", "cloth.height=4"});
  const int W = 5, H = 4;
  EXPECT_EQ(s.model.particle_count(), W * H);
  const int structural = (W - 1) * H + W * (H - 1), shear = 2 * (W - 1) * (H - 1),
            bend = (W - 2) * H + W * (H - 2);
  EXPECT_EQ(s.model.spring_count(), structural + shear + bend);
  int pinned = 0;
  for (int i = 0; i < s.model.particle_count(); ++i) pinned += s.model.pinned(i);
  EXPECT_EQ(pinned, 2);
  EXPECT_TRUE(s.model.pinned(0));
  EXPECT_TRUE(s.model.pinned(W - 1));
  // Every spring starts at rest; a cloth's vertical springs form a single span.
  for (int k = 0; k < s.model.spring_count(); ++k)
    EXPECT_NEAR((s.state.x.row(s.model.spring_b[k]) - s.state.x.row(s.model.spring_a[k])).norm(),
                s.model.rest_length[k], 1e-12);
  EXPECT_LT(s.model.spans.size(), static_cast<std::size_t>(structural));
}

// A cloth thrown spinning: P = M v, and about its centre L = I w, I of a thin square plate of
// side a and mass M: M a^2 / 12 about each in-plane axis and M a^2 / 6 about its normal (the
// nodes' lattice, n per side, gives M a^2 (n + 1) / (12 (n - 1)) each way instead).
TEST(Generators, AClothSpinsAsAPlate) {
  const int n = 9;
  const Scene s = test::shipped(
      "cloth", {"cloth.width=" + std::to_string(n), "cloth.height=" + std::to_string(n),
                "cloth.pinned=[]", "cloth.velocity=[0.5,-1,2]", "cloth.spin=[3,-2,1.5]"});
  const Vec3 v(0.5, -1, 2), w(3, -2, 1.5), center(0, 2, 1);  // (cloth.json's centre, 2 m wide)
  const Momentum m = momentum(s.model, s.state);
  EXPECT_LT((m.linear - 1.0 * v).norm(), 1e-12);
  const double a = 2.0, in_plane = a * a * (n + 1) / (12.0 * (n - 1));
  const Vec3 plate_l(in_plane * w.x(), 2 * in_plane * w.y(), in_plane * w.z());  // normal: y
  const Vec3 about_center = m.angular - center.cross(m.linear);
  EXPECT_LT((about_center - plate_l).norm(), 1e-12 * plate_l.norm()) << about_center.transpose();
}

TEST(Generators, BoxSurfaceFacesOutward) {
  const Scene s = test::shipped("jelly");
  const Vec3 center = s.state.x.colwise().mean().transpose();
  ASSERT_EQ(s.surfaces.size(), 1u);
  EXPECT_EQ(s.surfaces[0].triangles.size(), 6u * 4 * 4 * 2);
  for (const auto& t : s.surfaces[0].triangles) {
    const Vec3 a = s.state.x.row(t[0]).transpose(), b = s.state.x.row(t[1]).transpose(),
               c = s.state.x.row(t[2]).transpose();
    EXPECT_GT((b - a).cross(c - a).dot((a + b + c) / 3 - center), 0.0);
  }
}

TEST(Generators, AFinerRopeIsTheSameRope) {
  // Same total mass and the same static stretch under gravity (E A constant): hang it straight
  // down and compare the length it settles to.
  const auto settled_length = [](int nodes) {
    Scene s = test::shipped("rope", {"rope.nodes=" + std::to_string(nodes), "rope.end=[0,-4,0]"});
    double mass = 0;
    for (double m : s.model.mass) mass += m;
    EXPECT_NEAR(mass, 1.6, 1e-12);
    Simulation sim = test::simulation(s, Method::ImplicitEuler, 1e-3);
    sim.advance(4000);
    const int last = s.model.particle_count() - 1;
    return -sim.state().x(last, 1);
  };
  const double coarse = settled_length(8), fine = settled_length(32);
  EXPECT_GT(coarse, 4.0);  // it stretches
  // Continuous rope: stretch = rho g L^2 / (2 E A) = 0.4 * 9.81 * 16 / 4000 = 0.0157 m.
  EXPECT_NEAR(fine - 4.0, 0.0157, 0.0157 * 0.05);
  EXPECT_NEAR(coarse - 4.0, fine - 4.0, 0.0157 * 0.15);
}

TEST(Generators, AChainThroughAViaPointStartsAtRest) {
  const Scene s =
      test::shipped("chain");  // a V: (-2, 0), (0, -1.5), (2, 0); 41 nodes, 2.5 m a side
  EXPECT_NEAR(s.state.x(20, 1), -1.5, 1e-12);  // the middle node is the V's corner
  EXPECT_NEAR(s.model.rest_length[0], 5.0 / 40, 1e-12);
  for (int k = 0; k < s.model.spring_count(); ++k)
    EXPECT_NEAR((s.state.x.row(s.model.spring_b[k]) - s.state.x.row(s.model.spring_a[k])).norm(),
                s.model.rest_length[k], 1e-12);
}

std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parse_scene(text, "bad.json", overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneErrors, NameTheFileTheFieldAndTheAllowedRange) {
  const std::string p =
      R"("particles": [{"position": [0,0,0], "pinned": true}, {"position": [1,0,0]}])";
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {"{", "bad.json': not valid JSON: parse error at line 1"},
      {"[]", "bad.json': /: must be an object"},
      {R"({"particles": [{"position": [0,0,"a"]}]})", "/particles/0/position/2: must be a number"},
      {R"({"particles": [{"position": [0,0,0], "mass": -1}]})",
       "/particles/0/mass: must be in [1e-09, 1e+09], got -1"},
      {R"({"particles": [{"position": [0,0,0], "mass": 0}]})",
       "/particles/0/mass: must be in [1e-09, 1e+09], got 0"},
      {R"({"particles": [{"position": [0,0,1e999]}]})",
       "bad.json': not valid JSON: number overflow parsing '1e999'"},
      {"{" + p + R"(, "springs": [{"a": 0, "b": 5, "ks": 1}]})",
       "/springs/0/b: must be an integer in [0, 1], got 5"},
      {"{" + p + R"(, "springs": [{"a": 1, "b": 1, "ks": 1}]})",
       "/springs/0/b: is the same particle as \"a\""},
      {"{" + p + R"(, "springs": [{"a": 0, "b": 1}]})", "/springs/0/ks: is required"},
      {"{" + p + R"(, "springs": [{"a": 0, "b": 1, "ks": 1, "rest_length": -2}]})",
       "/springs/0/rest_length: must be in [0, 1e+09], got -2"},
      {"{" + p + R"(, "dt": 0})", "/dt: must be in (0, 1], got 0"},
      {"{" + p + R"(, "dt": -0.1})", "/dt: must be in (0, 1], got -0.1"},
      {"{" + p + R"(, "methods": ["rk5"]})",
       "/methods/0: unknown method \"rk5\"; did you mean \"rk4\"?"},
      {R"({"particle": [{"position": [0,0,0]}]})",
       "/particle: unknown field; did you mean \"particles\"?"},
      {"{" + p + R"(, "springs": [{"a": 0, "b": 1, "stifness": 3}]})",
       "/springs/0/ks: is required"},
      {"{" + p + R"(, "gravty": [0,-9.8,0]})", "/gravty: unknown field; did you mean \"gravity\"?"},
      {R"({"generators": [{"type": "rope", "start": [0,0,0], "end": [1,0,0], "nodes": 1e9, "stiffness": 1}]})",
       "/generators/0/nodes: must be an integer in [2, 4194304], got 1e+09"},
      {"{" + p +
           R"(, "generators": [{"type": "cloth", "width": 2048, "height": 2048, "stretch": 1}]})",
       "/generators/0: would make the scene 4194306 particles; the limit is 4194304"},
      {R"({"generators": [{"type": "rop"}]})",
       "/generators/0/type: unknown value \"rop\"; did you mean \"rope\"?"},
      {R"({"generators": [{"type": "rope", "start": [0,0,0], "end": [1,0,0], "nodes": 4, "stiffness": 1, "pinned": [7]}]})",
       "/generators/0/pinned/0: must be an integer in [-4, 3], got 7"},
      {"{" + p + R"(, "colliders": [{"type": "plane", "normal": [0,0,0]}]})",
       "/colliders/0/normal: must not be zero"},
      {"{" + p + R"(, "colliders": [{"type": "sphere", "center": [0,0,0], "radius": 0}]})",
       "/colliders/0/radius: must be in (0, 1e+06], got 0"},
      {R"({"particles": [{"position": [0,0,0]}, {"position": [0,0,0]}], "springs": [{"a": 0, "b": 1, "ks": 5, "rest_length": 1}]})",
       "/springs/0: its ends start at the same point"},
      {"{}", "declares no particles"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(c.text);
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << "expected: " << c.expected << "\n     got: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
  }
}

TEST(SceneErrors, OverridesAreCheckedLikeTheFile) {
  const std::string text = test::shipped("cloth").file;
  EXPECT_NE(error_of(R"({"generators": [{"type": "cloth", "stretch": 1}]})", {"cloth.width=0"})
                .find("/generators/0/width: must be an integer in [2, 2048], got 0"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"generators": [{"type": "cloth", "stretch": 1}]})", {"nothing.width=3"})
                .find("--set nothing.width=3: scene 'bad.json' has no field 'nothing'"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"generators": [{"type": "cloth", "stretch": 1}]})", {"width"})
                .find("expected KEY=VALUE"),
            std::string::npos);
  // Values: JSON, or a comma-separated list of numbers.
  const Scene s = test::shipped("rope", {"gravity=0,-1,0", "rope.nodes=5", "methods=[\"rk4\"]"});
  EXPECT_EQ(s.model.gravity, Vec3(0, -1, 0));
  EXPECT_EQ(s.model.particle_count(), 5);
  EXPECT_EQ(s.methods.front(), Method::RK4);
}

}  // namespace
}  // namespace springlab
