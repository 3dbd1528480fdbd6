// Local-global's global matrix on Liu's curtain (cloth 81 x 81, h = 1/30 s): Eigen's SimplicialLDLT
// (AMD, as springlab uses) against CHOLMOD's supernodal LLT and simplicial LDLT (SuiteSparse), each
// factorised once and solved for three right sides (x, y, z) through Eigen's wrappers. Built only
// where CHOLMOD is installed (libsuitesparse-dev; bench/CMakeLists.txt):
// build/bench/cholmod_compare.
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <chrono>
#include <cstdio>
#include <string>

#include "springlab/scene.hpp"

#ifndef SPRINGLAB_SOURCE_DIR
#define SPRINGLAB_SOURCE_DIR "."
#endif
using namespace springlab;
int main() {
  Scene s = load_scene(std::string(SPRINGLAB_SOURCE_DIR) + "/assets/scenes/cloth.json",
                       {"cloth.width=81", "cloth.height=81"});
  const Model& m = s.model;
  const double h = 1.0 / 30;
  std::vector<int> row(m.particle_count(), -1);
  int rows = 0;
  for (int i = 0; i < m.particle_count(); ++i)
    if (!m.pinned(i)) row[i] = rows++;
  std::vector<Eigen::Triplet<double>> e;
  for (int i = 0; i < m.particle_count(); ++i)
    if (row[i] >= 0) e.emplace_back(row[i], row[i], m.mass[i] + h * m.drag);
  for (int k = 0; k < m.spring_count(); ++k) {
    const double w = h * h * m.ks(k) + h * m.kd(k);
    const int a = row[m.spring_a[k]], b = row[m.spring_b[k]];
    if (a >= 0) e.emplace_back(a, a, w);
    if (b >= 0) e.emplace_back(b, b, w);
    if (a >= 0 && b >= 0) {
      e.emplace_back(a, b, -w);
      e.emplace_back(b, a, -w);
    }
  }
  Eigen::SparseMatrix<double> A(rows, rows);
  A.setFromTriplets(e.begin(), e.end());
  Eigen::MatrixXd B = Eigen::MatrixXd::Random(rows, 3), X;
  using C = std::chrono::steady_clock;
  auto time = [&](auto& solver, const char* name) {
    auto t0 = C::now();
    solver.compute(A);
    auto t1 = C::now();
    const int reps = 200;
    for (int r = 0; r < reps; ++r) X = solver.solve(B);
    auto t2 = C::now();
    std::printf("%s: factor %.2f ms, solve (3 columns) %.1f us, residual %.2e\n", name,
                std::chrono::duration<double, std::milli>(t1 - t0).count(),
                std::chrono::duration<double, std::micro>(t2 - t1).count() / reps,
                (A * X - B).norm() / B.norm());
  };
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  time(ldlt, "Eigen SimplicialLDLT (AMD)");
  std::printf("  L nonzeros %ld\n", (long)ldlt.matrixL().nestedExpression().nonZeros());
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> super;
  time(super, "CHOLMOD supernodal LLT");
  Eigen::CholmodSimplicialLDLT<Eigen::SparseMatrix<double>> simp;
  time(simp, "CHOLMOD simplicial LDLT");
}
