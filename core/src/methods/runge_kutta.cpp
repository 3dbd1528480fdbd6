#include "runge_kutta.hpp"

namespace springlab::rk {

void stages(const Model& model, const Points& x, const Points& v, double h, const Tableau& tableau,
            Workspace& ws, bool first_known) {
  StepScratch& s = scratch(ws);
  if (s.stage_dx.size() < static_cast<std::size_t>(tableau.stages)) {
    s.stage_dx.resize(static_cast<std::size_t>(tableau.stages));
    s.stage_dv.resize(static_cast<std::size_t>(tableau.stages));
  }
  if (!first_known) {
    s.stage_dx[0] = v;
    accelerations(model, x, v, s.stage_dv[0], ws);
  }
  for (int i = 1; i < tableau.stages; ++i) {
    s.stage_x = x;
    s.stage_v = v;
    for (int j = 0; j < i; ++j) {
      const double w = h * tableau.A(i, j);
      if (w == 0.0) continue;
      s.stage_x += w * s.stage_dx[j];
      s.stage_v += w * s.stage_dv[j];
    }
    s.stage_dx[i] = s.stage_v;
    accelerations(model, s.stage_x, s.stage_v, s.stage_dv[i], ws);
  }
}

void combine(const Points& x, const Points& v, double h, const std::vector<double>& weights,
             const StepScratch& s, Points& x1, Points& v1) {
  x1 = x;
  v1 = v;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    const double w = h * weights[i];
    if (w == 0.0) continue;
    x1 += w * s.stage_dx[i];
    v1 += w * s.stage_dv[i];
  }
}

}  // namespace springlab::rk
