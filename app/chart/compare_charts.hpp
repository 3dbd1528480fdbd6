// The charts of a sweep (springlab compare, and the app's Compare panel), as chart::Chart data:
// work-precision (error against wall time, and against work: force evaluations plus linear-solver
// iterations, the same on every machine and every run), convergence (error against step, with the
// fitted orders and reference slopes), stability (measured against theoretical largest stable step)
// and energy drift over a long run. One colour per method, as everywhere in springlab.
#pragma once

#include <string>
#include <vector>

#include "chart/chart.hpp"
#include "springlab/sweep.hpp"

namespace springlab::chart {

enum class Cost { Time, Work };
// A run's work: force evaluations plus linear-solver iterations (each about one evaluation's).
double work(const Counters& counters);
Chart work_precision(const SweepResult& result, const std::string& scene, Cost cost);
Chart convergence(const SweepResult& result, const std::string& scene);
Chart stability(const SweepResult& result, const std::string& scene);
Chart energy_drift(const SweepResult& result, const std::string& scene);
// The iterative methods' solver error against iterations (solver_error.hpp), apart from their
// time-stepping error (the other charts).
Chart solver_convergence(const SweepResult& result, const std::string& scene);

struct NamedChart {
  std::string name;  // file stem: "work-precision", "work-precision-work", ...
  Chart chart;
};
std::vector<NamedChart> compare_charts(const SweepResult& result, const std::string& scene);

}  // namespace springlab::chart
