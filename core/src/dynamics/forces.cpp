#include "springlab/forces.hpp"

#include "dynamics/force_pass.hpp"
#include "dynamics/threads.hpp"

namespace springlab {

void evaluate_forces(const Model& model, const Points& x, const Points& v, Points& out,
                     SpringForces& buffer, ForceOutput what) {
  const int n = model.particle_count();
  out.resize(n, 3);
  double* const F[3] = {out.col(0).data(), out.col(1).data(), out.col(2).data()};
  const double* inv_mass = model.inv_mass.data();
  if (what == ForceOutput::Force) {
    force_pass(model, x, v, F, buffer, [](int, int, int) {});
    return;
  }
  force_pass(model, x, v, F, buffer, [&](int, int begin, int end) {
    for (int c = 0; c < 3; ++c)
      for (int i = begin; i < end; ++i) F[c][i] *= inv_mass[i];
  });
}

void set_thread_count(int threads) {
  threads::set_max_team(threads > 0 ? threads : threads::processors());
}

int thread_count() {
  return threads::max_team();
}

TeamCounts team_counts() {
  const threads::Team::Counts c = threads::Team::counts();
  return {c.team, c.alone, c.yields, c.stalls, c.shared, c.sleeps};
}

}  // namespace springlab
