// A method added as its row and its step alone, and run through every consumer of the table: the
// lookups and the table's contract, the step at its order, the stability analysis, the measured
// limit and the divergence report at the limit its tableau gives, the colour and the mark, and the
// command line's list, run and compare (in this process, where the row exists), and a lane in
// the app's compare mode. Nothing outside this file names the row: what it is, it says.
//
// The row is Heun's method, the explicit trapezoidal rule (Hairer, Norsett and Wanner, Solving
// Ordinary Differential Equations I, II.1): y~ = y + h F(y), y1 = y + h/2 (F(y) + F(y~)). Order 2;
// its stability function is midpoint's, R(z) = 1 + z + z^2 / 2, so its limit on any damped mode is
// exactly midpoint's, and it is never stable undamped: |R(i h w)|^2 = 1 + (h w)^4 / 4.
#include <gtest/gtest.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "draw/marks.hpp"
#include "draw/palette.hpp"
#include "session/session.hpp"
#include "springlab/butcher.hpp"
#include "springlab/error.hpp"
#include "springlab/stability.hpp"
#include "support.hpp"
#include "util/data_dir.hpp"

namespace springlab {
namespace {

namespace fs = std::filesystem;

void heun_step(const Model& model, const State& in, State& out, double h, const StepSettings&,
               Workspace& ws) {
  Points a0, a1;
  accelerations(model, in.x, in.v, a0, ws);
  const Points x1 = in.x + h * in.v, v1 = in.v + h * a0;
  accelerations(model, x1, v1, a1, ws);
  out.x = in.x + 0.5 * h * (in.v + v1);
  out.v = in.v + 0.5 * h * (a0 + a1);
  out.t = in.t + h;
}

Method heun() {
  if (const auto m = find_method("own-heun")) return *m;
  static const Tableau tableau({{0.0}, {1.0}}, {0.5, 0.5});
  MethodInfo row{};
  row.name = "own-heun";  // (not "heun": the shipped tableau of the same method has that name)
  row.label = "Heun";
  row.order = 2;
  row.evaluations = "2";
  row.undamped_limit = 0.0;
  row.stability = "Heun gains energy at any step without damping: sqrt(1 + (h w)^4 / 4) a step";
  row.family = MethodFamily::RungeKutta;
  row.step = heun_step;
  row.tableau = &tableau;
  row.audited = true;
  return add_method(row);
}

// The command line in this process: the subcommand's exit status and what it printed.
struct CliRun {
  int status = -1;
  std::string out;
};
CliRun springlab(std::vector<std::string> args) {
  CLI::App cli("springlab", "springlab");
  std::map<std::string, app::Command> commands{{"run", app::add_run_command(cli)},
                                               {"list", app::add_list_command(cli)},
                                               {"compare", app::add_compare_command(cli)}};
  args.insert(args.begin(), "springlab");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  cli.parse(static_cast<int>(argv.size()), argv.data());
  CliRun r;
  testing::internal::CaptureStdout();
  try {
    r.status = commands.at(args[1])();
  } catch (const InputError& e) {
    r.status = app::kBadInput;
    std::printf("%s\n", e.what());
  }
  r.out = testing::internal::GetCapturedStdout();
  return r;
}

TEST(NewRow, IsFoundShownAndDescribedFromItsRowAlone) {
  const Method m = heun();
  EXPECT_EQ(heun(), m);  // (found again by its name, not added twice)
  const MethodInfo& row = method_info(m);
  EXPECT_STREQ(row.name, "own-heun");
  EXPECT_GE(static_cast<std::size_t>(m), static_cast<std::size_t>(Method::VBD) + 1);
  // A row of its own: in the table, and listed apart from the built-in ones in messages.
  const auto added = added_methods();
  EXPECT_TRUE(std::any_of(added.begin(), added.end(),
                          [](const MethodInfo& r) { return std::string(r.name) == "own-heun"; }));
  EXPECT_EQ(method_names().find("own-heun"), std::string::npos);
  EXPECT_NE(app::method_choices().find("; yours: own-heun"), std::string::npos)
      << app::method_choices();
  EXPECT_EQ(tableau_source(m), nullptr);
  EXPECT_EQ(kept_summary(row), "P");
  EXPECT_EQ(iterations_for(m, {}), 1);
  // A colour and a mark of its own: neither black nor any other row's colour.
  EXPECT_NE(draw::method_style(m).colour, (std::array<float, 3>{}));
  EXPECT_NE(draw::method_mark(m), draw::Mark::None);
  for (const MethodInfo& other : methods()) {
    if (other.id == m) continue;
    EXPECT_NE(draw::hex(draw::method_color(other.id)), draw::hex(draw::method_color(m)))
        << other.name;
  }
  // The same name again, or a row without a step, is refused.
  MethodInfo again = row;
  EXPECT_THROW(add_method(again), InputError);
  MethodInfo stepless{};
  stepless.name = "stepless";
  EXPECT_THROW(add_method(stepless), InputError);
  // A tableau file of a taken name is refused, saying whose the name is.
  const ButcherTableau heun_tableau = load_tableau_file(app::resolve_tableau("heun"));
  const auto refusal = [&](const std::string& name) {
    try {
      add_tableau_method(heun_tableau, name);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(refusal("own-heun"),
            "method 'own-heun': a row added by the program has this name; give the tableau's file "
            "another name");
  EXPECT_EQ(refusal("rk4"),
            "method 'rk4': a built-in method has this name; give the tableau's file another name");
}

TEST(NewRow, StepsAtItsOrderAndHoldsExactlyToTheLimitItsTableauGives) {
  const Method m = heun();
  // Second order on the oscillator's exact solution: halving h quarters the error.
  const Scene spring = test::oscillator();
  const double coarse = test::error_against_exact(spring, m, 0.01, 1.0);
  const double fine = test::error_against_exact(spring, m, 0.005, 1.0);
  EXPECT_NEAR(std::log2(coarse / fine), 2.0, 0.1);
  // Its limit is midpoint's, whose R(z) it shares: never undamped; with damping c, the same.
  const double w = 10.0;
  EXPECT_EQ(stable_step(m, w, 0.0), 0.0);
  for (double c : {0.5, 2.0, 8.0})
    EXPECT_NEAR(stable_step(m, w, c), stable_step(Method::Midpoint, w, c), 1e-12) << c;
  // Its own runs hold just inside the limit and diverge, reported, just past it.
  const double c = 2.0;
  const double limit = stable_step(m, w, c);
  const Scene scene = test::linear_oscillator(w * w, c);
  for (const double fraction : {0.9, 1.1}) {
    Simulation sim = test::simulation(scene, m, fraction * limit);
    sim.advance(20000);
    EXPECT_EQ(sim.diverged(), fraction > 1.0) << fraction;
  }
  // On a scene (the damped spring, at its stretched balance), the analysis finds it from R(z)
  // on the scene's modes: midpoint's, exactly. The measured limit (the method's own runs,
  // bisected) agrees within its resolution.
  const Scene damped = test::shipped("damped-spring");
  const StabilityAnalysis analysis(damped.model, damped.state);
  const StabilityLimit& own = analysis.limit(m);
  EXPECT_TRUE(own.exact);
  EXPECT_NEAR(own.h, analysis.limit(Method::Midpoint).h, 1e-12 * own.h);
  const MeasuredLimit measured =
      measured_limit(m, damped.model, damped.state, own, analysis.w_max());
  EXPECT_LE(measured.resolution, 0.01);
  EXPECT_NEAR(measured.h, own.h, (measured.resolution + 1e-3) * own.h);
}

TEST(NewRow, IsListedRunAndComparedByTheCommandLine) {
  const Method m = heun();
  const CliRun list = springlab({"list"});
  EXPECT_EQ(list.status, 0);
  EXPECT_NE(list.out.find("method  own-heun "), std::string::npos) << list.out;

  const CliRun run = springlab({"run", "damped-spring", "--method", "own-heun", "--steps", "200"});
  EXPECT_EQ(run.status, 0) << run.out;
  EXPECT_NE(run.out.find("own-heun: "), std::string::npos) << run.out;  // its limit, stated

  const fs::path dir =
      fs::temp_directory_path() / ("springlab-new-row-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const CliRun compare =
      springlab({"compare", "spring", "--methods", "own-heun,midpoint", "--points", "3",
                 "--drift-duration", "0", "--software", "--out", dir.string()});
  EXPECT_EQ(compare.status, 0) << compare.out;
  std::ifstream results(dir / "summary.csv");
  std::stringstream text;
  text << results.rdbuf();
  EXPECT_NE(text.str().find("own-heun"), std::string::npos) << text.str();
  // Drawn in its row's colour on the charts.
  bool coloured = false;
  for (const auto& file : fs::directory_iterator(dir)) {
    if (file.path().extension() != ".svg") continue;
    std::ifstream svg(file.path());
    std::stringstream s;
    s << svg.rdbuf();
    coloured = coloured || s.str().find(draw::hex(draw::method_color(m))) != std::string::npos;
  }
  EXPECT_TRUE(coloured);
  fs::remove_all(dir);
}

// In the app: a lane of its own beside midpoint's, its automatic sub-steps the same as
// midpoint's (the same limit), both holding at them and both diverging at one step a frame.
TEST(NewRow, IsALaneInTheAppsCompareMode) {
  const Method m = heun();
  Scene scene = test::shipped("stiff");
  SimulationSettings settings = settings_for(scene);
  settings.method = Method::Midpoint;
  app::Session session(std::move(scene), settings, 60.0);
  session.set_compare_rows(test::method_rows({m, Method::Midpoint}));
  ASSERT_EQ(session.lanes().size(), 2u);
  session.set_auto_substeps();
  session.advance_frame();
  const auto& lanes = session.lanes();
  EXPECT_EQ(lanes[0].sim.settings().method, m);
  EXPECT_EQ(lanes[0].sim.h(), lanes[1].sim.h());
  EXPECT_LT(lanes[0].sim.h(), lanes[0].sim.settings().dt);
  for (int k = 0; k < 30; ++k) session.advance_frame();
  for (const app::Lane& lane : lanes)
    EXPECT_FALSE(lane.sim.trouble()) << method_info(lane.sim.settings().method).name;
  session.set_substeps(1);
  for (int k = 0; k < 120; ++k) session.advance_frame();
  for (const app::Lane& lane : lanes)
    EXPECT_TRUE(lane.sim.diverged()) << method_info(lane.sim.settings().method).name;
}

}  // namespace
}  // namespace springlab
