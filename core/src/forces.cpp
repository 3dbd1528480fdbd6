#include "springlab/forces.hpp"

#include <omp.h>

#include "force_pass.hpp"

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
  omp_set_num_threads(threads > 0 ? threads : omp_get_num_procs());
}

int thread_count() { return omp_get_max_threads(); }

}  // namespace springlab
