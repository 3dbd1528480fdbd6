#include "runge_kutta.hpp"

namespace springlab::rk {

void stages(const Model& model, const Points& x, const Points& v, double h, const Tableau& tableau,
            Workspace& ws, bool first_known) {
  if (ws.stage_dx.size() < static_cast<std::size_t>(tableau.stages)) {
    ws.stage_dx.resize(static_cast<std::size_t>(tableau.stages));
    ws.stage_dv.resize(static_cast<std::size_t>(tableau.stages));
  }
  if (!first_known) {
    ws.stage_dx[0] = v;
    accelerations(model, x, v, ws.stage_dv[0], ws);
  }
  for (int i = 1; i < tableau.stages; ++i) {
    ws.stage_x = x;
    ws.stage_v = v;
    for (int j = 0; j < i; ++j) {
      const double w = h * tableau.A(i, j);
      if (w == 0.0) continue;
      ws.stage_x += w * ws.stage_dx[j];
      ws.stage_v += w * ws.stage_dv[j];
    }
    ws.stage_dx[i] = ws.stage_v;
    accelerations(model, ws.stage_x, ws.stage_v, ws.stage_dv[i], ws);
  }
}

void combine(const Points& x, const Points& v, double h, const std::vector<double>& weights,
             const Workspace& ws, Points& x1, Points& v1) {
  x1 = x;
  v1 = v;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    const double w = h * weights[i];
    if (w == 0.0) continue;
    x1 += w * ws.stage_dx[i];
    v1 += w * ws.stage_dv[i];
  }
}

}  // namespace springlab::rk
