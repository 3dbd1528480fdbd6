// The factor's tree of blocks (core/src/methods/solve_tree.hpp) and local-global's order for it
// (local_global_solves.cpp, factor_order), against what they must be: the elimination tree is
// the factor's own (each column's first entry below the diagonal, from Eigen's factorisation),
// the postorder fills in exactly as AMD's order does, and no entry of L joins two blocks of which
// neither is the other's ancestor (so that threads may take subtrees alone).
#include "methods/solve_tree.hpp"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "methods/local_global.hpp"
#include "support.hpp"

namespace springlab {
namespace {

struct Graph {
  std::vector<int> begin, index;
  int size() const { return static_cast<int>(begin.size()) - 1; }
};

Graph from_edges(int n, const std::vector<std::pair<int, int>>& edges) {
  std::vector<std::vector<int>> adjacent(n);
  for (auto [a, b] : edges) adjacent[a].push_back(b), adjacent[b].push_back(a);
  Graph g;
  g.begin.push_back(0);
  for (const auto& a : adjacent) {
    g.index.insert(g.index.end(), a.begin(), a.end());
    g.begin.push_back(static_cast<int>(g.index.size()));
  }
  return g;
}

// The particles' graph of shipped cloths (structural, shear and bending springs), side by side.
Graph cloth_graph(int side, int copies = 1) {
  const Scene s = test::shipped(
      "cloth", {"cloth.width=" + std::to_string(side), "cloth.height=" + std::to_string(side)});
  const int n = s.model.particle_count();
  std::vector<std::pair<int, int>> edges;
  for (int c = 0; c < copies; ++c)
    for (int k = 0; k < s.model.spring_count(); ++k)
      edges.emplace_back(c * n + s.model.spring_a[k], c * n + s.model.spring_b[k]);
  return from_edges(copies * n, edges);
}

// A definite matrix on the graph (each row's diagonal its degree + 1, each edge -1), its rows at
// `place`.
Eigen::SparseMatrix<double> matrix(const Graph& g, const std::vector<int>& place) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int v = 0; v < g.size(); ++v) {
    entries.emplace_back(place[v], place[v], 1.0 + g.begin[v + 1] - g.begin[v]);
    for (int p = g.begin[v]; p < g.begin[v + 1]; ++p)
      entries.emplace_back(place[v], place[g.index[p]], -1.0);
  }
  Eigen::SparseMatrix<double> A(g.size(), g.size());
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

// At most 2 x 16 blocks not small (1/16 of the work or more) and 256 small ones not tiny (1/256),
// and one over a forest.
void expect_blocks_of_the_factor(const Graph& g, const std::string& name,
                                 std::size_t most_blocks = 2 * 16 + 256 + 1) {
  const int n = g.size();
  const local_global_parts::FactorOrder order = local_global_parts::factor_order(g.begin, g.index);
  const std::vector<int>& place = order.place;
  ASSERT_EQ(static_cast<int>(place.size()), n) << name;
  std::vector<int> sorted = place;
  std::sort(sorted.begin(), sorted.end());
  for (int k = 0; k < n; ++k) ASSERT_EQ(sorted[k], k) << name << ": not a permutation";
  LocalGlobalSolver::Factor factor(matrix(g, place));
  ASSERT_EQ(factor.info(), Eigen::Success) << name;
  const auto& L = factor.matrixL().nestedExpression();
  // The same fill as AMD's own order (a postorder of a tree changes none).
  std::vector<int> identity(n);
  for (int v = 0; v < n; ++v) identity[v] = v;
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> amd(matrix(g, identity));
  EXPECT_EQ(L.nonZeros(), amd.matrixL().nestedExpression().nonZeros()) << name;

  // The tree and work the order says are the factor's, and the tree is postordered.
  std::vector<int> size(n, 1);
  for (int j = 0; j < n; ++j) {
    const int first = L.outerIndexPtr()[j], end = L.outerIndexPtr()[j + 1];
    ASSERT_EQ(order.parent[j], first < end ? L.innerIndexPtr()[first] : -1)
        << name << ": row " << j;
    ASSERT_EQ(order.work[j], 1.0 + 2.0 * (end - first)) << name << ": row " << j;
    if (order.parent[j] >= 0) size[order.parent[j]] += size[j];
  }
  for (int j = 0; j < n; ++j)  // postordered: each subtree's rows the ones just before its root
    if (const int p = order.parent[j]; p >= 0) {
      ASSERT_LT(j, p) << name;
      ASSERT_GE(j - size[j], p - size[p])
          << name << ": row " << j << "'s subtree outside its parent's";
    }

  const SolveTree t = solve_tree(order.parent, order.work);
  EXPECT_LE(t.nodes.size(), most_blocks) << name;
  ASSERT_FALSE(t.nodes.empty()) << name;
  EXPECT_EQ(t.nodes.back().first, 0) << name;
  EXPECT_EQ(t.nodes.back().end, n) << name;
  std::vector<int> owner(n, -1);
  for (int d = 0; d < static_cast<int>(t.nodes.size()); ++d) {
    const auto& node = t.nodes[d];
    int at_child = node.first;  // the children cover [first, own), in order
    for (int c : node.children) {
      ASSERT_LT(c, d) << name << ": a child after its parent";
      ASSERT_EQ(t.nodes[c].parent, d) << name;
      ASSERT_EQ(t.nodes[c].first, at_child) << name;
      at_child = t.nodes[c].end;
    }
    ASSERT_EQ(at_child, node.own) << name;
    for (int j = node.own; j < node.end; ++j) owner[j] = d;
  }
  for (int j = 0; j < n; ++j) ASSERT_GE(owner[j], 0) << name << ": row " << j << " in no block";
  const auto is_above = [&](int a, int d) {  // a is d or one of its ancestors
    for (; d >= 0; d = t.nodes[d].parent)
      if (d == a) return true;
    return false;
  };
  for (int j = 0; j < n; ++j)
    for (int p = L.outerIndexPtr()[j]; p < L.outerIndexPtr()[j + 1]; ++p)
      ASSERT_TRUE(is_above(owner[L.innerIndexPtr()[p]], owner[j]))
          << name << ": L's entry (" << L.innerIndexPtr()[p] << ", " << j
          << ") joins two separate blocks";
}

TEST(SolveTree, BlocksOfTheFactorAreIndependentSubtrees) {
  expect_blocks_of_the_factor(cloth_graph(64), "64 x 64 cloth");
  expect_blocks_of_the_factor(cloth_graph(24, 3), "three 24 x 24 cloths");
  std::vector<std::pair<int, int>> path, star, clique;
  for (int i = 0; i + 1 < 3000; ++i) path.emplace_back(i, i + 1);
  expect_blocks_of_the_factor(from_edges(3000, path), "a 3000-particle rope");
  std::vector<std::pair<int, int>> comb = path;  // a particle hanging from each of the rope's
  for (int i = 0; i < 3000; ++i) comb.emplace_back(i, 3000 + i);
  // Its tree has a branch at each of the rope's particles (its hanging one, eliminated first),
  // each a tiny subtree: the rope's rows one chain, not a block each.
  expect_blocks_of_the_factor(from_edges(6000, comb), "a rope with a particle from each", 4);
  for (int i = 1; i < 2000; ++i) star.emplace_back(0, i);
  expect_blocks_of_the_factor(from_edges(2000, star), "a star");
  for (int i = 0; i < 300; ++i)
    for (int j = i + 1; j < 300; ++j) clique.emplace_back(i, j);
  expect_blocks_of_the_factor(from_edges(300, clique), "a 300-particle clique");
  expect_blocks_of_the_factor(from_edges(500, {}), "500 lone particles");
  expect_blocks_of_the_factor(from_edges(0, {}), "no particle");
}

}  // namespace
}  // namespace springlab
