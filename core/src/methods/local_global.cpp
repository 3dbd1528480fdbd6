// The local-global solver of Liu, Bargteil, O'Brien and Kavan 2013 ("Fast simulation of
// mass-spring systems"; for springs, projective dynamics: Bouaziz et al. 2014): the
// backward-Euler step of iterative.hpp minimised by alternating two exact minimisations.
//
//   local:   each spring's target  d_s = L u_s,  u_s = (x_b - x_a) / |x_b - x_a|
//   global:  (M~ + sum_s w_s A_s A_s^T) x = M~ y + sum_s w_s A_s t_s        w_s = h^2 k_s + h k_d
//            w_s t_s = h^2 k_s d_s + h k_d (e_s(x0) + P_s (e_s(x) - e_s(x0)))
//
// with e_s(x) = x_b - x_a, A_s the spring's +1 / -1 incidence, P_s = I - u_s u_s^T. The matrix is
// the same for x, y and z and for every iteration: factorised once (Eigen's SimplicialLDLT) and
// again only when h, a mass, a pin, k_s, k_d or the drag change. Iterations start from y.
//
// The notes' damping, k_d (u . (v_b - v_a)) u with v = (x1 - x0) / h, enters as the dissipation
// potential k_d / (2h) (u . de)^2 (iterative.hpp). Its matrix depends on u, which changes every
// iteration; so the constant matrix holds its isotropic part k_d / (2h) |de|^2, and the part across
// the spring, which the notes' model does not damp, is taken back on the right side with the
// current iterate's u (the P_s term). That part is at most the isotropic one, so the lagged
// iteration still contracts; converged, the step is the backward-Euler step of the notes' model.
// Drag is in M~ (m + h k_drag), exactly.
//
// Chebyshev acceleration (Wang 2015), with rho = settings.chebyshev_rho > 0:
//   x^(k+1) = omega_(k+1) (x^ - x^(k-1)) + x^(k-1),  x^ the plain iteration's result from x^k.
#include "local_global.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "dynamics/threads.hpp"
#include "springlab/error.hpp"
#include "springlab/iterative_cost.hpp"
#include "springlab/spring_kernel.hpp"
#include "steps.hpp"

namespace springlab {

bool LocalGlobalSolver::Key::matches(const Model& model, double step) const {
  if (h != step || drag != model.drag || spans != model.spans.data() ||
      springs != model.spring_count() || mass != model.mass || inv_mass != model.inv_mass ||
      materials.size() != model.materials.size())
    return false;
  for (std::size_t m = 0; m < materials.size(); ++m)
    if (materials[m].ks != model.materials[m].ks || materials[m].kd != model.materials[m].kd)
      return false;
  return true;
}

void LocalGlobalSolver::Key::take(const Model& model, double step) {
  h = step;
  drag = model.drag;
  mass = model.mass;
  inv_mass = model.inv_mass;
  materials = model.materials;
  spans = model.spans.data();
  springs = model.spring_count();
}

namespace {

double spring_weight(const SpringMaterial& m, double h) {
  return h * h * m.ks + h * m.kd;
}

}  // namespace

namespace {

// The triangular solves' schedule (LocalGlobalSolver::SolvePlan) for a team of `team` threads.
// Column j's first entry below the diagonal is j's parent in the factor's elimination tree, and
// row i's entries are i's descendants (Liu 1990, "The role of elimination trees"): a subtree's
// rows are solved forward from its own rows alone and backward from its own and its ancestors'.
// Cutting the heaviest subtree (its root joins the top) frees its children to go to other
// threads; the cut kept is the one whose time, the top's work plus the heaviest thread's (the
// subtrees dealt heaviest first to the lightest thread, Graham's rule), is least. Measured on the
// 128 x 128 cloth (AMD's order): on 2 threads the top keeps 38 % of the work and each thread 31 %;
// the top's rows are the dense rows of the last separators, which one thread solves.
struct SolveCut {
  std::vector<char> in_top;
  std::vector<int> subtrees;  // roots, heaviest first
  double time = 0.0;
};

// The makespan of the subtrees dealt to `team` threads, heaviest first, and each root's thread.
double deal_subtrees(const std::vector<int>& roots, const std::vector<double>& subtree, int team,
                     std::vector<int>* thread_of) {
  std::vector<double> load(static_cast<std::size_t>(team), 0.0);
  for (int r : roots) {
    const auto k = std::min_element(load.begin(), load.end()) - load.begin();
    load[static_cast<std::size_t>(k)] += subtree[r];
    if (thread_of) (*thread_of)[r] = static_cast<int>(k);
  }
  return *std::max_element(load.begin(), load.end());
}

SolveCut cut_tree(const std::vector<int>& roots, const std::vector<std::vector<int>>& children,
                  const std::vector<double>& work, const std::vector<double>& subtree, int team) {
  const auto heavier = [&](int a, int b) {  // ties: the lower row (the same plan everywhere)
    return subtree[a] > subtree[b] || (subtree[a] == subtree[b] && a < b);
  };
  SolveCut cut{std::vector<char>(work.size(), 0), roots, 0.0};
  std::sort(cut.subtrees.begin(), cut.subtrees.end(), heavier);
  double top = 0.0;
  cut.time = deal_subtrees(cut.subtrees, subtree, team, nullptr);
  std::vector<int> cuts, now = cut.subtrees;
  std::size_t best = 0;
  while (team > 1 && !now.empty() && top < cut.time) {
    const int r = now.front();  // the heaviest
    now.erase(now.begin());
    cuts.push_back(r);
    top += work[r];
    for (int c : children[r]) now.insert(std::lower_bound(now.begin(), now.end(), c, heavier), c);
    const double time = top + deal_subtrees(now, subtree, team, nullptr);
    if (time < cut.time) {
      cut.time = time;
      cut.subtrees = now;
      best = cuts.size();
    }
  }
  for (std::size_t k = 0; k < best; ++k) cut.in_top[cuts[k]] = 1;
  return cut;
}

void plan_solves(LocalGlobalSolver& S, int team) {
  const auto& L = S.factor.matrixL().nestedExpression();
  const int rows = static_cast<int>(L.cols());
  const int* begin = L.outerIndexPtr();
  const int* index = L.innerIndexPtr();
  LocalGlobalSolver::SolvePlan& P = S.plan;
  const Eigen::SparseMatrix<double, Eigen::RowMajor> by_rows = L;  // (columns ascending a row)
  const int* row_begin = by_rows.outerIndexPtr();

  std::vector<int> parent(rows, -1);
  std::vector<double> work(rows), subtree(rows);
  std::vector<std::vector<int>> children(rows);
  std::vector<int> roots;
  for (int j = 0; j < rows; ++j) {
    if (begin[j] < begin[j + 1]) parent[j] = index[begin[j]];
    work[j] = 1.0 + (begin[j + 1] - begin[j]) + (row_begin[j + 1] - row_begin[j]);
    (parent[j] >= 0 ? children[parent[j]] : roots).push_back(j);
  }
  subtree = work;
  for (int j = 0; j < rows; ++j)  // a parent's index is above its children's
    if (parent[j] >= 0) subtree[parent[j]] += subtree[j];
  const SolveCut cut = cut_tree(roots, children, work, subtree, team);
  const std::vector<char>& in_top = cut.in_top;
  std::vector<int> piece(rows, -1);
  deal_subtrees(cut.subtrees, subtree, team, &piece);
  for (int j = rows - 1; j >= 0; --j)  // a subtree's rows join its root's piece
    if (!in_top[j] && piece[j] < 0) piece[j] = piece[parent[j]];
  // Each row's place in the solves' storage: the pieces' rows in turn, each piece's ascending,
  // then the top's. A piece's rows are then one run of memory its thread alone writes.
  std::vector<int> place(rows), group(rows), first(team + 2, 0);
  for (int j = 0; j < rows; ++j) {  // group team: the top
    group[j] = in_top[j] ? team : piece[j];
    ++first[group[j] + 1];
  }
  for (int k = 0; k <= team; ++k) first[k + 1] += first[k];
  P.piece_first.assign(first.begin(), first.begin() + team + 1);
  P.top_first = first[team];
  P.piece_work = 0.0;
  for (int j = 0; j < rows; ++j) {
    place[j] = first[group[j]]++;
    if (!in_top[j]) P.piece_work += work[j];
  }
  // L by rows (forward) and by columns (backward) at their places, each row's or column's
  // entries in their own order (ascending in the factor's): the sums' order, and so their bits,
  // are the factor's.
  const auto copy_at_places = [&](const int* outer, const int* inner, const double* value,
                                  std::vector<int>& first, std::vector<int>& at,
                                  std::vector<double>& values) {
    first.assign(rows + 1, 0);
    for (int j = 0; j < rows; ++j) first[place[j] + 1] = outer[j + 1] - outer[j];
    for (int q = 0; q < rows; ++q) first[q + 1] += first[q];
    at.resize(static_cast<std::size_t>(first[rows]));
    values.resize(at.size());
    for (int j = 0; j < rows; ++j)
      for (int p = outer[j], to = first[place[j]]; p < outer[j + 1]; ++p, ++to) {
        at[to] = place[inner[p]];
        values[to] = value[p];
      }
  };
  copy_at_places(by_rows.outerIndexPtr(), by_rows.innerIndexPtr(), by_rows.valuePtr(), P.row_begin,
                 P.row_index, P.row_value);
  copy_at_places(begin, index, L.valuePtr(), P.col_begin, P.col_index, P.col_value);
  const Eigen::VectorXd d = S.factor.vectorD();  // (a copy: vectorD() returns one)
  S.inv_d.resize(rows);
  for (int j = 0; j < rows; ++j) S.inv_d[place[j]] = 1.0 / d[j];
  S.row.resize(S.factor_row.size());
  for (std::size_t i = 0; i < S.row.size(); ++i)
    S.row[i] = S.factor_row[i] >= 0 ? place[S.factor_row[i]] : -1;
  P.team = team;
}

// Each row's springs, for the right side's sums (LocalGlobalSolver::row_springs): spring s as s
// at its b end's row, ~s at its a end's, springs ascending.
void plan_row_springs(const Model& model, LocalGlobalSolver& S) {
  const int rows = static_cast<int>(S.inv_d.size());
  S.row_springs_first.assign(rows + 1, 0);
  for (int s = 0; s < model.spring_count(); ++s) {
    if (const int rb = S.row[model.spring_b[s]]; rb >= 0) ++S.row_springs_first[rb + 1];
    if (const int ra = S.row[model.spring_a[s]]; ra >= 0) ++S.row_springs_first[ra + 1];
  }
  for (int r = 0; r < rows; ++r) S.row_springs_first[r + 1] += S.row_springs_first[r];
  S.row_springs.assign(S.row_springs_first[rows], 0);
  std::vector<int> next(S.row_springs_first.begin(), S.row_springs_first.end() - 1);
  for (int s = 0; s < model.spring_count(); ++s) {
    if (const int rb = S.row[model.spring_b[s]]; rb >= 0) S.row_springs[next[rb]++] = s;
    if (const int ra = S.row[model.spring_a[s]]; ra >= 0) S.row_springs[next[ra]++] = ~s;
  }
}

}  // namespace

namespace local_global_parts {

void factorise(const Model& model, double h, const std::vector<double>& mass,
               LocalGlobalSolver& S) {
  const int n = model.particle_count();
  std::vector<int> row(n, -1);
  int rows = 0;
  for (int i = 0; i < n; ++i)
    if (!model.pinned(i)) row[i] = rows++;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(rows + 4 * model.spring_count());
  for (int i = 0; i < n; ++i)
    if (row[i] >= 0) entries.emplace_back(row[i], row[i], mass[i]);
  for (int s = 0; s < model.spring_count(); ++s) {
    const double w = spring_weight(model.materials[model.spring_material[s]], h);
    if (w == 0.0) continue;
    const int ra = row[model.spring_a[s]], rb = row[model.spring_b[s]];
    if (ra >= 0) entries.emplace_back(ra, ra, w);
    if (rb >= 0) entries.emplace_back(rb, rb, w);
    if (ra >= 0 && rb >= 0) {
      entries.emplace_back(ra, rb, -w);
      entries.emplace_back(rb, ra, -w);
    }
  }
  Eigen::SparseMatrix<double> matrix(rows, rows);
  matrix.setFromTriplets(entries.begin(), entries.end());
  S.factor.compute(matrix);
  if (S.factor.info() != Eigen::Success)  // M~ > 0 makes it definite: only a bad mass gets here
    throw StepFailure(
        "local-global: the global matrix could not be factorised (a zero or negative mass?)");
  // Rows in the factor's own (fill-reducing) order, so that the solve needs no permutation:
  // Eigen's P b puts row r at P.indices()[r].
  const auto& order = S.factor.permutationP().indices();
  S.factor_row.assign(n, -1);
  for (int i = 0; i < n; ++i)
    if (row[i] >= 0) S.factor_row[i] = order.size() ? order[row[i]] : row[i];
  S.factored = true;
  ++S.factorisations;
  S.rhs.assign(3 * rows, 0.0);
  plan(model, S);
}

void plan(const Model& model, LocalGlobalSolver& S) {
  plan_solves(S, std::max(1, threads::max_team()));
  plan_row_springs(model, S);
}

namespace {

// Forward, L y = b, for the rows at places [from, to) (ascending), each its row's sum over the
// rows before it: y_i = b_i - sum_j L_ij y_j, j ascending (the subtractions in the order the
// column-by-column solve makes them: the same bits).
void forward_rows(const LocalGlobalSolver::SolvePlan& P, int from, int to, double* Z) {
  const int* begin = P.row_begin.data();
  const int* index = P.row_index.data();
  const double* value = P.row_value.data();
  for (int i = from; i < to; ++i) {
    double s0 = Z[3 * i], s1 = Z[3 * i + 1], s2 = Z[3 * i + 2];
    for (int p = begin[i]; p < begin[i + 1]; ++p) {
      const double* r = Z + 3 * index[p];
      s0 -= value[p] * r[0], s1 -= value[p] * r[1], s2 -= value[p] * r[2];
    }
    Z[3 * i] = s0, Z[3 * i + 1] = s1, Z[3 * i + 2] = s2;
  }
}

// Then D w = y and L^T z = w for the rows at places [from, to), descending: z_j = y_j / D_j -
// sum_i L_ij z_i over the rows below j in the factor (its ancestors), i ascending.
void backward_rows(const LocalGlobalSolver& S, int from, int to, double* Z) {
  const LocalGlobalSolver::SolvePlan& P = S.plan;
  const int* begin = P.col_begin.data();
  const int* index = P.col_index.data();
  const double* value = P.col_value.data();
  for (int j = to - 1; j >= from; --j) {
    const double inv = S.inv_d[j];
    double s0 = Z[3 * j] * inv, s1 = Z[3 * j + 1] * inv, s2 = Z[3 * j + 2] * inv;
    for (int p = begin[j]; p < begin[j + 1]; ++p) {
      const double* r = Z + 3 * index[p];
      s0 -= value[p] * r[0], s1 -= value[p] * r[1], s2 -= value[p] * r[2];
    }
    Z[3 * j] = s0, Z[3 * j + 1] = s1, Z[3 * j + 2] = s2;
  }
}

}  // namespace

// The pieces in parallel, the top rows on the caller: forward the pieces then the top, backward
// the top then the pieces. Each row's arithmetic is the same whichever thread does it.
void solve_in_place(const LocalGlobalSolver& S, std::vector<double>& z) {
  const LocalGlobalSolver::SolvePlan& P = S.plan;
  double* Z = z.data();
  const int pieces = static_cast<int>(P.piece_first.size()) - 1;
  const int rows = static_cast<int>(S.inv_d.size());
  threads::for_each_piece(pieces, P.piece_work, [&](int k) {
    forward_rows(P, P.piece_first[k], P.piece_first[k + 1], Z);
  });
  forward_rows(P, P.top_first, rows, Z);
  backward_rows(S, P.top_first, rows, Z);
  threads::for_each_piece(pieces, P.piece_work, [&](int k) {
    backward_rows(S, P.piece_first[k], P.piece_first[k + 1], Z);
  });
}

// The local step for `count` springs of a span (spring k joins a0 + k and b0 + k), from the
// iterate x and the start x0: each spring's w t (the file's header), x y z in wx, wy, wz. Plain
// arrays along the span, without branches, so that it vectorises.
void span_targets(const double* const x[3], const double* const x0[3], int a0, int b0, int count,
                  double ks, double kd, double rest, double h, double* __restrict wx,
                  double* __restrict wy, double* __restrict wz) {
  const double k_s = h * h * ks, k_d = h * kd, near = coincident_length(rest);
  SPRINGLAB_VECTORISE
  for (int k = 0; k < count; ++k) {
    const double ex = x[0][b0 + k] - x[0][a0 + k], ey = x[1][b0 + k] - x[1][a0 + k],
                 ez = x[2][b0 + k] - x[2][a0 + k];
    const double fx = x0[0][b0 + k] - x0[0][a0 + k], fy = x0[1][b0 + k] - x0[1][a0 + k],
                 fz = x0[2][b0 + k] - x0[2][a0 + k];
    const double l = std::sqrt(ex * ex + ey * ey + ez * ez);
    // Coincident ends have no direction: no force (d = e) and no damping (P de = de).
    const bool none = l <= near;
    const double inv = none ? 0.0 : 1.0 / l;
    const double ux = ex * inv, uy = ey * inv, uz = ez * inv;
    const double along = ux * (ex - fx) + uy * (ey - fy) + uz * (ez - fz);  // u . de
    const double target = none ? 1.0 : rest * inv;                          // d = target e
    wx[k] = k_s * target * ex + k_d * (ex - ux * along);  // e0 + P de = e - u (u . de)
    wy[k] = k_s * target * ey + k_d * (ey - uy * along);
    wz[k] = k_s * target * ez + k_d * (ez - uz * along);
  }
}

// The right side of the global step for the correction z = x - y from the prediction y (the
// file's header with x = y + z):
//   (M~ + sum_s w_s A_s A_s^T) z = sum_s A_s (w_s t_s - w_s e_s(y)),
// each spring's term made from its own differences and added to one end's row and taken from
// the other's. Its rows sum to zero to rounding of the springs' terms, not of the positions:
// solved for x itself, a body 2 m from the origin lost 1e-8 of its momentum over a throw to the
// solve's rounding of |x| (a free body keeps sum M~ x = sum M~ y exactly, momentum.hpp). From the
// iterate X (pinned rows hold their positions, which are y's), into S.rhs in the factor's order:
// each spring's w t - w e(y) (span by span, in parallel: each spring's own numbers), then each
// row's sum of its springs' terms, in the springs' order (rows in parallel: the same bits for any
// thread count, and as the springs added one by one to their ends' rows).
void global_rhs(const Model& model, const State& in, double h, const Points& X, const Points& y,
                LocalGlobalSolver& S) {
  const int springs = model.spring_count();
  double* B = S.rhs.data();
  const double* x[3] = {X.col(0).data(), X.col(1).data(), X.col(2).data()};
  const double* x0[3] = {in.x.col(0).data(), in.x.col(1).data(), in.x.col(2).data()};
  S.wt.resize(3 * static_cast<std::size_t>(springs));
  double *wx = S.wt.data(), *wy = wx + springs, *wz = wy + springs;
  // Pieces of kPiece springs (a span cut where a piece ends), claimed by whichever thread of the
  // team is running (dynamics/threads.hpp), at least kPerThread springs a thread: a pass this
  // short (a tenth of an iteration on the 128 x 128 cloth) does not pay for waking many threads.
  constexpr int kPiece = 2048, kPerThread = 16384;
  threads::for_each_piece(
      (springs + kPiece - 1) / kPiece, springs,
      [&](int p) {
        const int lo = p * kPiece, hi = std::min(springs, lo + kPiece);
        auto span = std::upper_bound(model.spans.begin(), model.spans.end(), lo,
                                     [](int s, const SpringSpan& sp) { return s < sp.first; }) -
                    1;
        for (; span < model.spans.end() && span->first < hi; ++span) {
          const SpringMaterial& material = model.materials[span->material];
          const int from = std::max(lo - span->first, 0),
                    to = std::min(hi - span->first, span->count);
          if (from >= to) continue;
          const int at = span->first + from;
          span_targets(x, x0, span->a0 + from, span->b0 + from, to - from, material.ks, material.kd,
                       span->rest, h, wx + at, wy + at, wz + at);
        }
        for (int s = lo; s < hi; ++s) {  // the spring's term g = w t - w e(y)
          const int a = model.spring_a[s], b = model.spring_b[s];
          const double w = h * h * model.ks(s) + h * model.kd(s);
          wx[s] = wx[s] - w * (y(b, 0) - y(a, 0));
          wy[s] = wy[s] - w * (y(b, 1) - y(a, 1));
          wz[s] = wz[s] - w * (y(b, 2) - y(a, 2));
        }
      },
      kPerThread);
  // Each row its springs' terms, in the springs' order, pieces of rows in parallel.
  const int rows = static_cast<int>(S.inv_d.size());
  constexpr int kRowPiece = 2048;
  threads::for_each_piece(
      (rows + kRowPiece - 1) / kRowPiece, static_cast<double>(S.row_springs.size()),
      [&](int p) {
        const int lo = p * kRowPiece, hi = std::min(rows, lo + kRowPiece);
        for (int r = lo; r < hi; ++r) {
          double b0 = 0.0, b1 = 0.0, b2 = 0.0;
          for (int e = S.row_springs_first[r]; e < S.row_springs_first[r + 1]; ++e) {
            const int s = S.row_springs[e];
            if (s >= 0)
              b0 += wx[s], b1 += wy[s], b2 += wz[s];
            else
              b0 -= wx[~s], b1 -= wy[~s], b2 -= wz[~s];
          }
          B[3 * r] = b0, B[3 * r + 1] = b1, B[3 * r + 2] = b2;
        }
      },
      kPerThread);
}

}  // namespace local_global_parts

namespace steps {

using namespace local_global_parts;

void local_global(const Model& model, const State& in, State& out, double h,
                  const StepSettings& settings, Workspace& ws) {
  if (!ws.iterative) ws.iterative = std::make_unique<IterativeSolvers>();
  IterativeSolvers& I = *ws.iterative;
  LocalGlobalSolver& S = I.local_global;
  iterative::predict(model, in, h, I.y, I.mass);

  if (!S.factored || !S.key.matches(model, h)) {
    factorise(model, h, I.mass, S);
    S.key.take(model, h);
  } else if (S.plan.team != std::max(1, threads::max_team())) {
    plan(model, S);  // the team changed: the solves' pieces for the new one (the same bits)
  }

  out.resize(in.particle_count());
  out.x = I.y;  // the first iterate; pinned rows stay at x + h v
  const double rho = settings.chebyshev_rho;
  if (rho > 0.0) S.previous = out.x;
  double omega = 1.0;
  const int iterations = iterations_for(Method::LocalGlobal, settings);
  const int n = in.particle_count();
  for (int k = 1; k <= iterations; ++k) {
    global_rhs(model, in, h, out.x, I.y, S);
    solve_in_place(S, S.rhs);  // the correction z from y
    if (rho > 0.0) {
      omega = chebyshev_omega(k, rho, omega);
      S.current = out.x;
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < n; ++i)
          if (S.row[i] >= 0)
            out.x(i, c) =
                omega * (I.y(i, c) + S.rhs[3 * S.row[i] + c] - S.previous(i, c)) + S.previous(i, c);
      S.previous.swap(S.current);
    } else {
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < n; ++i)
          if (S.row[i] >= 0) out.x(i, c) = I.y(i, c) + S.rhs[3 * S.row[i] + c];
    }
  }
  ws.counters.solver_iterations += iterations;
  ++ws.counters.linear_solves;
  iterative::finish(model, in, out, h);
}

}  // namespace steps

// The plain iteration's contraction an iteration near its fixed point, as a power method finds a
// spectral radius: successive updates |x_k - x_(k-1)| shrink by it, measured over the last 8 of
// `iterations` from y.
double local_global_radius(const Model& model, const State& state, double h, int iterations) {
  using namespace local_global_parts;
  IterativeSolvers I;
  LocalGlobalSolver& S = I.local_global;
  iterative::predict(model, state, h, I.y, I.mass);
  factorise(model, h, I.mass, S);
  Points x = I.y;
  std::vector<double> updates;
  for (int k = 0; k < iterations; ++k) {
    global_rhs(model, state, h, x, I.y, S);
    solve_in_place(S, S.rhs);
    double squared = 0.0;
    for (int i = 0; i < model.particle_count(); ++i)
      for (int c = 0; c < 3 && S.row[i] >= 0; ++c) {
        const double next = I.y(i, c) + S.rhs[3 * S.row[i] + c];
        squared += (next - x(i, c)) * (next - x(i, c));
        x(i, c) = next;
      }
    updates.push_back(std::sqrt(squared));
  }
  const int tail = std::min(8, iterations / 2), last = iterations - 1;
  if (tail < 1 || !(updates[last - tail] > 0.0)) return 0.0;
  return std::pow(updates[last] / updates[last - tail], 1.0 / tail);
}

}  // namespace springlab
