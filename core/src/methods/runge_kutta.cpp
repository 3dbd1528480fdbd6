#include "runge_kutta.hpp"

namespace springlab::rk {

void stages(const Model& model, const Points& x, const Points& v, double h, const Tableau& tableau,
            Workspace& ws, bool first_known) {
  if (ws.kx.size() < static_cast<std::size_t>(tableau.stages)) {
    ws.kx.resize(static_cast<std::size_t>(tableau.stages));
    ws.kv.resize(static_cast<std::size_t>(tableau.stages));
  }
  if (!first_known) {
    ws.kx[0] = v;
    accelerations(model, x, v, ws.kv[0], ws);
  }
  for (int i = 1; i < tableau.stages; ++i) {
    ws.tx = x;
    ws.tv = v;
    for (int j = 0; j < i; ++j) {
      const double w = h * tableau.A(i, j);
      if (w == 0.0) continue;
      ws.tx += w * ws.kx[j];
      ws.tv += w * ws.kv[j];
    }
    ws.kx[i] = ws.tv;
    accelerations(model, ws.tx, ws.tv, ws.kv[i], ws);
  }
}

void combine(const Points& x, const Points& v, double h, const std::vector<double>& weights, const Workspace& ws,
             Points& x1, Points& v1) {
  x1 = x;
  v1 = v;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    const double w = h * weights[i];
    if (w == 0.0) continue;
    x1 += w * ws.kx[i];
    v1 += w * ws.kv[i];
  }
}

}  // namespace springlab::rk
