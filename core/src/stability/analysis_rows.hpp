// How the stability analysis searches a built-in row's limit: its own business, not what a method
// says of itself (MethodInfo, springlab/methods.hpp). A small table keyed by the built-in rows'
// ids; every other row, and a row added at run time (add_method, add_tableau_method), has the
// defaults: a grid with a margin for the quick bound, no shift of the damping.
#pragma once

#include <utility>

#include "springlab/methods.hpp"

namespace springlab {

struct AnalysisRow {
  /// Its mode limit is least at a corner of any box of (gamma, kappa) (monotone closed forms):
  /// the quick bound (quick_limit) takes the corners, exact; otherwise a grid, with a margin.
  bool corner_bound = false;
  /// A partitioned row whose limit is not a definite form: the least over the scene's numerical
  /// range, the damping seen as C^ + damping_shift h K^ (modified Euler, explicit Euler on that
  /// damping: 1/2).
  double damping_shift = 0.0;
};

/// The built-in rows that differ from the defaults (their closed forms' monotonicity: proven,
/// stability.hpp's quick bound).
inline constexpr std::pair<Method, AnalysisRow> kAnalysisRows[] = {
    {Method::Euler, {.corner_bound = true}},
    {Method::SymplecticEuler, {.corner_bound = true}},
    {Method::ModifiedEuler, {.corner_bound = true, .damping_shift = 0.5}},
    {Method::Verlet, {.corner_bound = true}},
};

/// The row's entry in kAnalysisRows, or the defaults.
inline AnalysisRow analysis_row(Method method) {
  for (const auto& [id, row] : kAnalysisRows)
    if (id == method) return row;
  return {};
}

}  // namespace springlab
