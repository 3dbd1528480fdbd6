// Local-global's global matrix (local_global.cpp's header): factorised once in a fill-reducing
// order (AMD, then a postorder of its elimination tree), and its triangular solves shared by the
// team's threads.
//
// The factor's blocks (solve_tree.hpp) say which rows are independent: a subtree's rows have
// entries of L only in that subtree. The plan cuts the tree of blocks for the team: the blocks at
// the top (solved by the calling thread) and the subtrees below them (dealt to the threads, a
// piece each). Backward, L^T z = w, each column's sum reads only rows above it (its ancestors):
// the top's columns first, then the pieces', in parallel. Forward, L y = b, a top row's entries
// are mostly in the pieces below it (on the 128 x 128 cloth, the 671 rows above two threads'
// subtrees hold 39 % of the factor's entries, 15 % in their own columns); so each row's sum is a
// tree of sums, the blocks': b less each child block's sum (its children's sums, added in order,
// then its own entries, in order), then less the row's own block's terms, in order. The pieces'
// threads sum the top's rows over their own subtrees, in parallel, and the top adds what they left.
// The tree is the factor's, not the team's, so every sum is the same arithmetic, and the same bits,
// for any team: one thread makes the same sums in the same order.
#include <Eigen/OrderingMethods>
#include <algorithm>
#include <vector>

#include "dynamics/threads.hpp"
#include "local_global.hpp"
#include "solve_tree.hpp"
#include "springlab/error.hpp"

namespace springlab::local_global_parts {

namespace {

using Node = SolveTree::Node;
using SolvePlan = LocalGlobalSolver::SolvePlan;
using SumStep = LocalGlobalSolver::SumStep;

double spring_weight(const SpringMaterial& m, double h) {
  return h * h * m.ks + h * m.kd;
}

// The makespan of the subtrees dealt to `team` threads, heaviest first to the least loaded
// (Graham's rule), and each root's thread.
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

// The top for a team: the heaviest subtree's node cut (its own rows join the top, its children
// become subtrees) while it pays; the cut kept is the one whose time, the top's work plus the
// heaviest thread's, is least. A leaf is never cut. `pieces`: the subtrees' nodes, heaviest first.
struct Cut {
  std::vector<char> in_top;
  std::vector<int> pieces;
};

Cut cut_tree(const std::vector<Node>& nodes, const std::vector<double>& own,
             const std::vector<double>& subtree, int team) {
  const auto heavier = [&](int a, int b) {  // ties: the lower node (the same plan everywhere)
    return subtree[a] > subtree[b] || (subtree[a] == subtree[b] && a < b);
  };
  const int root = static_cast<int>(nodes.size()) - 1;
  Cut cut{std::vector<char>(nodes.size(), 0), {root}};
  double best = deal_subtrees(cut.pieces, subtree, team, nullptr), top = 0.0;
  std::vector<int> now = cut.pieces, cuts;
  std::size_t kept = 0;
  while (team > 1 && !now.empty() && !nodes[now.front()].children.empty() && top < best) {
    const int d = now.front();
    now.erase(now.begin());
    cuts.push_back(d);
    top += own[d];
    for (int c : nodes[d].children)
      now.insert(std::lower_bound(now.begin(), now.end(), c, heavier), c);
    if (const double time = top + deal_subtrees(now, subtree, team, nullptr); time < best) {
      best = time;
      cut.pieces = now;
      kept = cuts.size();
    }
  }
  for (std::size_t k = 0; k < kept; ++k) cut.in_top[cuts[k]] = 1;
  return cut;
}

// The solves' time for a team by the work model: the top's work and the heaviest thread's.
double solve_time(const std::vector<Node>& nodes, const std::vector<double>& own,
                  const std::vector<double>& subtree, int team) {
  const Cut cut = cut_tree(nodes, own, subtree, team);
  double top = 0.0;
  for (std::size_t d = 0; d < nodes.size(); ++d)
    if (cut.in_top[d]) top += own[d];
  return top + deal_subtrees(cut.pieces, subtree, team, nullptr);
}

// The fewest threads whose solves take at most kSlack longer, by the work model, than `asked`
// threads': a thread that gains nothing (the top and the heaviest piece left as they were) is
// only one more to wake and to wait for. The 128 x 128 cloth gains 2.61 times from 5 threads on
// (its top and its heaviest subtree set the time), so 16 asked use 5.
int useful_team(const std::vector<Node>& nodes, const std::vector<double>& own,
                const std::vector<double>& subtree, int asked) {
  constexpr double kSlack = 0.03;
  const double best = solve_time(nodes, own, subtree, asked);
  for (int team = 1; team < asked; ++team)
    if (solve_time(nodes, own, subtree, team) <= (1.0 + kSlack) * best) return team;
  return asked;
}

// Writes the steps of a row's forward sum (SumStep): its entries [p, q) of L by rows, all in
// node d's subtree, summed child by child, each child's sum its own steps, then d's own entries.
// For a top row a child in a piece is summed by the piece's thread: a slot, and a job to fill it.
struct SumWriter {
  const std::vector<Node>& nodes;
  const int* column;  // L by rows, in the factor's rows
  SolvePlan& P;
  struct Pending {
    int node, p, q, slot, offset;
  };
  std::vector<Pending> pending;

  // offset: the entries' place in the plan's arrays less theirs in L by rows; in_top: the cut
  // (none for a piece's rows, whose sums are their piece's alone).
  void write(int d, int p, int q, int offset, const std::vector<char>* in_top) {
    int children = 0;
    for (int c : nodes[d].children) {
      int e = p;
      while (e < q && column[e] < nodes[c].end) ++e;
      if (e == p) continue;
      if (in_top && !(*in_top)[c]) {
        pending.push_back({c, p, e, P.slots, offset});
        P.sums.push_back({0, 0, 0, P.slots++});
      } else {
        write(c, p, e, offset, in_top);
      }
      ++children;
      p = e;
    }
    P.sums.push_back({p + offset, q + offset, children, -1});
  }
};

// The most values a sum's steps leave pending at once, over every sum in the plan.
int most_pending(const SolvePlan& P) {
  int most = 1;
  const auto scan = [&](int first, int last) {
    int height = 0;
    for (int k = first; k < last; ++k) {
      const SumStep& s = P.sums[k];
      height = s.slot >= 0 ? height + 1 : height - s.children + 1;
      most = std::max(most, height);
    }
  };
  for (std::size_t i = 0; i + 1 < P.sum_first.size(); ++i) scan(P.sum_first[i], P.sum_first[i + 1]);
  for (const SolvePlan::Job& job : P.jobs) scan(job.first, job.last);
  return most;
}

// Each row's sum's steps by place, then the pieces' jobs for the top's rows.
void plan_sums(const LocalGlobalSolver& S, const Eigen::SparseMatrix<double, Eigen::RowMajor>& L,
               const std::vector<int>& owner, const std::vector<int>& at, const Cut& cut,
               const std::vector<int>& piece_of, SolvePlan& P) {
  const int rows = static_cast<int>(at.size());
  SumWriter w{S.nodes, L.innerIndexPtr(), P, {}};
  P.sums.clear();
  P.slots = 0;
  P.sum_first.assign(rows + 1, 0);
  for (int q = 0; q < rows; ++q) {
    const int r = at[q], d = owner[r];
    const int offset = P.row_begin[q] - L.outerIndexPtr()[r];
    w.write(d, L.outerIndexPtr()[r], L.outerIndexPtr()[r + 1], offset,
            cut.in_top[d] ? &cut.in_top : nullptr);
    P.sum_first[q + 1] = static_cast<int>(P.sums.size());
  }
  std::vector<std::vector<SolvePlan::Job>> by_piece(P.team);
  for (const SumWriter::Pending& j : w.pending) {
    const int first = static_cast<int>(P.sums.size());
    w.write(j.node, j.p, j.q, j.offset, nullptr);
    by_piece[piece_of[j.node]].push_back({first, static_cast<int>(P.sums.size()), j.slot});
  }
  P.jobs.clear();
  P.job_first.assign(1, 0);
  for (const auto& jobs : by_piece) {
    P.jobs.insert(P.jobs.end(), jobs.begin(), jobs.end());
    P.job_first.push_back(static_cast<int>(P.jobs.size()));
  }
  P.most_pending = most_pending(P);
}

// L by rows (forward) and by columns (backward) at the rows' places, each row's or column's
// entries in the factor's order.
void copy_at_places(int rows, const std::vector<int>& place, const int* outer, const int* inner,
                    const double* value, std::vector<int>& first, std::vector<int>& at,
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
}

// The solves' plan for a team of at most `asked` threads (LocalGlobalSolver::SolvePlan): as many
// as pay (useful_team). A row's work is its column's: each entry L_ij is used once forward (by
// row i's thread, or, for a top row, by column j's piece) and once backward (by column j's
// thread).
void plan_solves(LocalGlobalSolver& S, int asked) {
  const auto& L = S.factor.matrixL().nestedExpression();
  const int rows = static_cast<int>(L.cols());
  const int* begin = L.outerIndexPtr();
  const std::vector<Node>& nodes = S.nodes;
  SolvePlan& P = S.plan;
  std::vector<int> owner(rows);
  std::vector<double> own(nodes.size(), 0.0);
  for (std::size_t d = 0; d < nodes.size(); ++d)
    for (int j = nodes[d].own; j < nodes[d].end; ++j) {
      owner[j] = static_cast<int>(d);
      own[d] += 1.0 + 2.0 * (begin[j + 1] - begin[j]);
    }
  std::vector<double> subtree = own;
  for (std::size_t d = 0; d < nodes.size(); ++d)  // children before parents
    if (nodes[d].parent >= 0) subtree[nodes[d].parent] += subtree[d];
  const int team = useful_team(nodes, own, subtree, asked);
  P.asked = asked;
  P.team = team;
  const Cut cut = cut_tree(nodes, own, subtree, team);
  std::vector<int> piece_of(nodes.size(), -1);
  deal_subtrees(cut.pieces, subtree, team, &piece_of);
  for (int d = static_cast<int>(nodes.size()) - 1; d >= 0; --d)  // parents before children
    if (!cut.in_top[d] && piece_of[d] < 0) piece_of[d] = piece_of[nodes[d].parent];
  // Each row's place: the pieces' rows in turn, each piece's ascending, then the top's. A piece's
  // rows are then one run of memory its thread alone writes.
  std::vector<int> place(rows), at(rows), group(rows), first(team + 2, 0);
  for (int j = 0; j < rows; ++j) {  // group team: the top
    group[j] = cut.in_top[owner[j]] ? team : piece_of[owner[j]];
    ++first[group[j] + 1];
  }
  for (int k = 0; k <= team; ++k) first[k + 1] += first[k];
  P.piece_first.assign(first.begin(), first.begin() + team + 1);
  P.top_first = first[team];
  P.piece_work = 0.0;
  for (int d : cut.pieces) P.piece_work += subtree[d];
  for (int j = 0; j < rows; ++j) at[place[j] = first[group[j]]++] = j;
  const Eigen::SparseMatrix<double, Eigen::RowMajor> by_rows = L;  // (columns ascending a row)
  copy_at_places(rows, place, by_rows.outerIndexPtr(), by_rows.innerIndexPtr(), by_rows.valuePtr(),
                 P.row_begin, P.row_index, P.row_value);
  copy_at_places(rows, place, begin, L.innerIndexPtr(), L.valuePtr(), P.col_begin, P.col_index,
                 P.col_value);
  plan_sums(S, by_rows, owner, at, cut, piece_of, P);
  const Eigen::VectorXd d = S.factor.vectorD();  // (a copy: vectorD() returns one)
  S.inv_d.resize(rows);
  for (int j = 0; j < rows; ++j) S.inv_d[place[j]] = 1.0 / d[j];
  S.row.resize(S.factor_row.size());
  for (std::size_t i = 0; i < S.row.size(); ++i)
    S.row[i] = S.factor_row[i] >= 0 ? place[S.factor_row[i]] : -1;
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

// The graph of the matrix's rows (the unpinned particles), an edge for each spring of nonzero
// weight between two of them, in compressed rows: the ordering's input.
void row_graph(const Model& model, double h, const std::vector<int>& row, int rows,
               std::vector<int>& begin, std::vector<int>& index) {
  begin.assign(rows + 1, 0);
  const auto each_edge = [&](auto&& f) {
    for (int s = 0; s < model.spring_count(); ++s) {
      const int ra = row[model.spring_a[s]], rb = row[model.spring_b[s]];
      if (ra >= 0 && rb >= 0 && ra != rb &&
          spring_weight(model.materials[model.spring_material[s]], h) != 0.0)
        f(ra, rb);
    }
  };
  each_edge([&](int a, int b) { ++begin[a + 1], ++begin[b + 1]; });
  for (int r = 0; r < rows; ++r) begin[r + 1] += begin[r];
  index.resize(static_cast<std::size_t>(begin[rows]));
  std::vector<int> next(begin.begin(), begin.end() - 1);
  each_edge([&](int a, int b) { index[next[a]++] = b, index[next[b]++] = a; });
}

}  // namespace

// The factor's order: Eigen's minimum degree order (AMD) of the rows' graph, then a postorder of
// its elimination tree (its blocks' rows consecutive: solve_tree.hpp), which fills in the same and
// keeps each block's rows consecutive; the tree and the columns' work from Eigen's symbolic
// factorisation.
FactorOrder factor_order(const std::vector<int>& begin, const std::vector<int>& index) {
  const int rows = static_cast<int>(begin.size()) - 1;
  std::vector<Eigen::Triplet<double>> pattern;
  pattern.reserve(index.size() + rows);
  for (int r = 0; r < rows; ++r) {
    pattern.emplace_back(r, r, 1.0);
    for (int p = begin[r]; p < begin[r + 1]; ++p) pattern.emplace_back(index[p], r, 1.0);
  }
  Eigen::SparseMatrix<double> A(rows, rows);
  A.setFromTriplets(pattern.begin(), pattern.end());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> amd;
  Eigen::AMDOrdering<int>()(A, amd);  // amd.indices()[k]: the row eliminated k-th
  Eigen::SparseMatrix<double> B(rows, rows);
  B = A.twistedBy(amd.inverse());
  struct Symbolic : LocalGlobalSolver::Factor {  // the tree and column counts, by AMD's place
    int parent(int j) const { return m_parent[j]; }
    double work(int j) const {
      return 1.0 + 2.0 * (m_matrix.outerIndexPtr()[j + 1] - m_matrix.outerIndexPtr()[j]);
    }
  } symbolic;
  symbolic.analyzePattern(B);
  std::vector<int> parent(rows);
  std::vector<double> work(rows);
  for (int j = 0; j < rows; ++j) parent[j] = symbolic.parent(j), work[j] = symbolic.work(j);
  const std::vector<int> post = postorder(parent, work);
  FactorOrder out{std::vector<int>(rows), std::vector<int>(rows, -1), std::vector<double>(rows)};
  std::vector<int> at_post(rows);
  for (int q = 0; q < rows; ++q) at_post[post[q]] = q;
  for (int q = 0; q < rows; ++q) {
    out.place[amd.indices()[post[q]]] = q;
    out.parent[q] = parent[post[q]] >= 0 ? at_post[parent[post[q]]] : -1;
    out.work[q] = work[post[q]];
  }
  return out;
}

void factorise(const Model& model, double h, const std::vector<double>& mass,
               LocalGlobalSolver& S) {
  const int n = model.particle_count();
  std::vector<int> row(n, -1);
  int rows = 0;
  for (int i = 0; i < n; ++i)
    if (!model.pinned(i)) row[i] = rows++;
  std::vector<int> begin, index;
  row_graph(model, h, row, rows, begin, index);
  const FactorOrder order = factor_order(begin, index);
  const std::vector<int>& place = order.place;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(rows + 4 * model.spring_count());
  for (int i = 0; i < n; ++i)
    if (row[i] >= 0) entries.emplace_back(place[row[i]], place[row[i]], mass[i]);
  for (int s = 0; s < model.spring_count(); ++s) {
    const double w = spring_weight(model.materials[model.spring_material[s]], h);
    if (w == 0.0) continue;
    const int ra = row[model.spring_a[s]] >= 0 ? place[row[model.spring_a[s]]] : -1;
    const int rb = row[model.spring_b[s]] >= 0 ? place[row[model.spring_b[s]]] : -1;
    if (ra >= 0) entries.emplace_back(ra, ra, w);
    if (rb >= 0) entries.emplace_back(rb, rb, w);
    if (ra >= 0 && rb >= 0) {
      entries.emplace_back(ra, rb, -w);
      entries.emplace_back(rb, ra, -w);
    }
  }
  Eigen::SparseMatrix<double> matrix(rows, rows);
  matrix.setFromTriplets(entries.begin(), entries.end());
  S.factor.compute(matrix);  // in factor_order's order (NaturalOrdering: no permutation)
  if (S.factor.info() != Eigen::Success)  // M~ > 0 makes it definite: only a bad mass gets here
    throw StepFailure(
        "local-global: the global matrix could not be factorised (a zero or negative mass?)");
  S.nodes = solve_tree(order.parent, order.work).nodes;
  S.factor_row.assign(n, -1);
  for (int i = 0; i < n; ++i)
    if (row[i] >= 0) S.factor_row[i] = place[row[i]];
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

// The solves below, for N coordinates at once: 3 (x y z, a row's three together: the solver's
// layout) or 1 (one coordinate alone: solve_top's). Row r's coordinate k is at Z[N r + k], a
// pending sum's at stack[N h + k], and a piece's sum for a top row at partial[3 slot + k] (for
// one coordinate, `partial` points at its own). Each coordinate's arithmetic is the same, in the
// same order, whatever N: the same bits.

// Steps of a sum (SumStep): each step's value left on `stack` until its parent's step adds it.
// Returns how many values are left (the next step's children).
template <int N>
int push_steps(const SolvePlan& P, const SumStep* step, int count, const double* Z,
               const double* partial, double* stack) {
  const int* index = P.row_index.data();
  const double* value = P.row_value.data();
  int height = 0;
  for (const SumStep* end = step + count; step < end; ++step) {
    double s[N] = {};
    if (step->slot >= 0) {
      for (int k = 0; k < N; ++k) s[k] = partial[3 * step->slot + k];
    } else {
      for (int c = height - step->children; c < height; ++c)
        for (int k = 0; k < N; ++k) s[k] += stack[N * c + k];
      height -= step->children;
      for (int p = step->first; p < step->last; ++p) {
        const double* r = Z + N * index[p];
        for (int k = 0; k < N; ++k) s[k] += value[p] * r[k];
      }
    }
    for (int k = 0; k < N; ++k) stack[N * height + k] = s[k];
    ++height;
  }
  return height;
}

// Forward, L y = b, for the rows at places [from, to) (ascending): y_i = b_i less its children's
// sums (their steps), in order, less its own entries' terms, in order. Most rows have no
// children: y_i = b_i - L_ij y_j - ..., j ascending.
template <int N>
void forward_rows(const SolvePlan& P, int from, int to, double* Z, const double* partial,
                  double* stack) {
  const int* index = P.row_index.data();
  const double* value = P.row_value.data();
  const int* sums = P.sum_first.data();
  const int* begin = P.row_begin.data();
  for (int i = from; i < to; ++i) {
    double s[N];
    for (int k = 0; k < N; ++k) s[k] = Z[N * i + k];
    int first = begin[i], last = begin[i + 1];
    if (const int steps = sums[i + 1] - sums[i]; steps > 1) {
      const SumStep& own = P.sums[sums[i + 1] - 1];
      const int children = push_steps<N>(P, &P.sums[sums[i]], steps - 1, Z, partial, stack);
      for (int c = 0; c < children; ++c)
        for (int k = 0; k < N; ++k) s[k] -= stack[N * c + k];
      first = own.first, last = own.last;
    }
    for (int p = first; p < last; ++p) {
      const double* r = Z + N * index[p];
      for (int k = 0; k < N; ++k) s[k] -= value[p] * r[k];
    }
    for (int k = 0; k < N; ++k) Z[N * i + k] = s[k];
  }
}

// Then D w = y and L^T z = w for the rows at places [from, to), descending: z_j = y_j / D_j -
// sum_i L_ij z_i over the rows below j in the factor (its ancestors), i ascending.
template <int N>
void backward_rows(const LocalGlobalSolver& S, int from, int to, double* Z) {
  const SolvePlan& P = S.plan;
  const int* begin = P.col_begin.data();
  const int* index = P.col_index.data();
  const double* value = P.col_value.data();
  for (int j = to - 1; j >= from; --j) {
    const double inv = S.inv_d[j];
    double s[N];
    for (int k = 0; k < N; ++k) s[k] = Z[N * j + k] * inv;
    for (int p = begin[j]; p < begin[j + 1]; ++p) {
      const double* r = Z + N * index[p];
      for (int k = 0; k < N; ++k) s[k] -= value[p] * r[k];
    }
    for (int k = 0; k < N; ++k) Z[N * j + k] = s[k];
  }
}

// The top's rows, forward then backward: a coordinate a thread (forward_rows<1>) where the team
// has three threads for it and the work is worth them, else x y z at once on the caller. One
// coordinate's solve takes 0.82 to 0.89 of x y z's time, not a third (the 128 x 128 cloth's top,
// one thread, here and on a lent 16-core machine): its time goes to reading L's entries (an index
// and a value each) and the rows they name, as much for one coordinate as for three (two sums a
// row, to break the chain of subtractions, gained 1 to 3 % on one thread). So the top gains
// at most 1 / 0.85 from its three threads, and on two (one coordinate, then two) it lost: the
// 128 x 128 cloth ran 42 steps a second against 49 on 2 cores. The 16-core machine's step at 3 and
// 4 threads: 8 to 44 % faster in 6 alternating pairs of runs (docs/performance.md).
void solve_top(LocalGlobalSolver& S, double* Z, const double* partial, double* stack) {
  const SolvePlan& P = S.plan;
  const int top = P.top_first, rows = static_cast<int>(S.inv_d.size());
  const double work =
      (P.row_begin[rows] - P.row_begin[top]) + (P.col_begin[rows] - P.col_begin[top]);
  if (top == rows || threads::max_team() < 3 || !threads::worth_threads(work)) {
    forward_rows<3>(P, top, rows, Z, partial, stack);
    backward_rows<3>(S, top, rows, Z);
    return;
  }
  // A top row's sum reads only the top's rows and the pieces' sums for it (its entries in a
  // piece's rows are that piece's job), and a top column's only its ancestors, in the top too: so
  // the three coordinates are independent solves. Each coordinate's rows (by row; the top's
  // filled) and its stack on cache lines of their own.
  const std::size_t line = 8, length = (static_cast<std::size_t>(rows) + line - 1) / line * line,
                    height = (static_cast<std::size_t>(P.most_pending) + line - 1) / line * line;
  S.top.resize(3 * (length + height));
  const auto coordinate = [&](int c) { return S.top.data() + c * (length + height); };
  threads::for_each_piece(3, work, [&](int c) {
    double* T = coordinate(c);
    for (int i = top; i < rows; ++i) T[i] = Z[3 * i + c];
    forward_rows<1>(P, top, rows, T, partial + c, T + length);
    backward_rows<1>(S, top, rows, T);
  });
  for (int i = top; i < rows; ++i)
    for (int c = 0; c < 3; ++c) Z[3 * i + c] = coordinate(c)[i];
}

}  // namespace

// The pieces in parallel, each its rows and then its sums for the top's rows; the top's rows next
// (solve_top): forward the pieces then the top, backward the top then the pieces.
void solve_in_place(LocalGlobalSolver& S, std::vector<double>& z) {
  const SolvePlan& P = S.plan;
  double* Z = z.data();
  const int pieces = static_cast<int>(P.piece_first.size()) - 1;
  // A stack's cache lines its own (8 doubles a line): the pieces' threads write them at once.
  const std::size_t stack_size = (3 * static_cast<std::size_t>(P.most_pending) + 7) / 8 * 8;
  S.partial.resize(3 * static_cast<std::size_t>(P.slots));
  S.stacks.resize(stack_size * (pieces + 1));
  double* partial = S.partial.data();
  threads::for_each_piece(pieces, P.piece_work, [&](int k) {
    double* stack = S.stacks.data() + stack_size * k;
    forward_rows<3>(P, P.piece_first[k], P.piece_first[k + 1], Z, partial, stack);
    for (int j = P.job_first[k]; j < P.job_first[k + 1]; ++j) {
      const SolvePlan::Job& job = P.jobs[j];
      push_steps<3>(P, &P.sums[job.first], job.last - job.first, Z, partial, stack);
      std::copy_n(stack, 3, partial + 3 * job.slot);
    }
  });
  solve_top(S, Z, partial, S.stacks.data() + stack_size * pieces);
  threads::for_each_piece(pieces, P.piece_work, [&](int k) {
    backward_rows<3>(S, P.piece_first[k], P.piece_first[k + 1], Z);
  });
}

}  // namespace springlab::local_global_parts
