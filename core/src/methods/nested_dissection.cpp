// Nested dissection (nested_dissection.hpp): separators from breadth-first level structures,
// leaves by minimum degree.
#include "nested_dissection.hpp"

#include <Eigen/OrderingMethods>
#include <algorithm>
#include <utility>

namespace springlab {

namespace {

// Parts of at most this many vertices are leaves, ordered by minimum degree. Measured on the
// 128 x 128 cloth's local-global matrix (its factor's entries; AMD alone: 1.129e6): leaves of 32,
// 128, 256 and 1024 vertices, 1.208e6, 1.225e6, 1.211e6 and 1.193e6. The largest leaves fill in
// least (AMD sees more at once) and still leave 16 of them, a subtree for each of 16 threads.
constexpr int kLeaf = 1024;

struct Graph {
  const std::vector<int>& begin;
  const std::vector<int>& index;
};

// The part's vertices in breadth-first levels from `root`: level[v] for each, the vertices level
// by level into `seen` (ascending within a level as found), and each level's first place in it.
struct Levels {
  std::vector<int> seen, first;
};

Levels level_structure(const Graph& g, int root, int part, const std::vector<int>& in,
                       std::vector<int>& level) {
  Levels L;
  L.seen.push_back(root);
  level[root] = 0;
  L.first.push_back(0);
  for (std::size_t head = 0; head < L.seen.size(); ++head) {
    const int v = L.seen[head];
    if (level[v] == static_cast<int>(L.first.size())) L.first.push_back(static_cast<int>(head));
    for (int p = g.begin[v]; p < g.begin[v + 1]; ++p)
      if (const int w = g.index[p]; in[w] == part && level[w] < 0) {
        level[w] = level[v] + 1;
        L.seen.push_back(w);
      }
  }
  L.first.push_back(static_cast<int>(L.seen.size()));
  return L;
}

// A pseudo-peripheral vertex of the component of `start` (George and Liu 1979): from a vertex,
// the deepest level's vertex of least degree (ties: the lower index), while the depth grows.
Levels peripheral_levels(const Graph& g, int start, int part, const std::vector<int>& in,
                         std::vector<int>& level) {
  const auto reset = [&](const Levels& L) {
    for (int v : L.seen) level[v] = -1;
  };
  Levels L = level_structure(g, start, part, in, level);
  for (int tries = 0; tries < 8; ++tries) {
    const int depth = static_cast<int>(L.first.size()) - 1;
    int best = -1;
    for (int k = L.first[depth - 1]; k < L.first[depth]; ++k) {
      const int v = L.seen[k];
      const int degree = g.begin[v + 1] - g.begin[v];
      if (best < 0 || degree < g.begin[best + 1] - g.begin[best] ||
          (degree == g.begin[best + 1] - g.begin[best] && v < best))
        best = v;
    }
    reset(L);
    Levels next = level_structure(g, best, part, in, level);
    if (next.first.size() <= L.first.size()) {
      reset(next);
      L = level_structure(g, start, part, in, level);
      break;
    }
    L = std::move(next);
    start = best;
  }
  return L;
}

}  // namespace

namespace {

class Dissection {
 public:
  explicit Dissection(const Graph& g)
      : g_(g), in_(g.begin.size() - 1, 0), level_(g.begin.size() - 1, -1) {}

  // Orders the vertices v with in_[v] == part (listed in `vertices`) into the tree's order, and
  // returns their node.
  int order(const std::vector<int>& vertices, int part);
  DissectionTree take() { return std::move(tree_); }

 private:
  std::vector<std::vector<int>> components(const std::vector<int>& vertices, int part);
  int dissect(const std::vector<int>& vertices, int part);
  int leaf(const std::vector<int>& vertices);
  // The node over the places from `first` to the order's end, the last `own` of them its own.
  int node(int first, std::size_t own, std::vector<int> children);
  void as_part(const std::vector<int>& vertices, int part) {
    for (int v : vertices) in_[v] = part;
  }
  int new_part() { return ++parts_; }

  const Graph& g_;
  std::vector<int> in_, level_;
  DissectionTree tree_;
  int parts_ = 0;
};

int Dissection::node(int first, std::size_t own, std::vector<int> children) {
  const int id = static_cast<int>(tree_.nodes.size());
  for (int c : children) tree_.nodes[c].parent = id;
  DissectionTree::Node n;
  n.first = first;
  n.end = static_cast<int>(tree_.order.size());
  n.own = n.end - static_cast<int>(own);
  n.children = std::move(children);
  tree_.nodes.push_back(std::move(n));
  return id;
}

int Dissection::order(const std::vector<int>& vertices, int part) {
  if (static_cast<int>(vertices.size()) <= kLeaf) return leaf(vertices);
  const std::vector<std::vector<int>> pieces = components(vertices, part);
  if (pieces.size() == 1) return dissect(vertices, part);
  // Components are independent already: each its own node, the small ones together in leaves,
  // under a node of no rows of its own.
  const int first = static_cast<int>(tree_.order.size());
  std::vector<int> children, batch;
  const auto flush = [&] {
    as_part(batch, new_part());
    children.push_back(leaf(batch));
    batch.clear();
  };
  for (const std::vector<int>& piece : pieces) {
    if (!batch.empty() && batch.size() + piece.size() > kLeaf) flush();
    if (static_cast<int>(piece.size()) > kLeaf) {
      const int own = new_part();
      as_part(piece, own);
      children.push_back(order(piece, own));
    } else {
      batch.insert(batch.end(), piece.begin(), piece.end());
    }
  }
  if (!batch.empty()) flush();
  return node(first, 0, std::move(children));
}

// The part's connected components, each from its lowest vertex, each ascending.
std::vector<std::vector<int>> Dissection::components(const std::vector<int>& vertices, int part) {
  std::vector<std::vector<int>> pieces;
  for (int v : vertices)
    if (level_[v] < 0) {
      pieces.push_back(level_structure(g_, v, part, in_, level_).seen);
      std::sort(pieces.back().begin(), pieces.back().end());
    }
  for (int v : vertices) level_[v] = -1;
  return pieces;
}

// Minimum degree on the leaf's own graph (Eigen's AMD, which orders A + A^T's pattern).
int Dissection::leaf(const std::vector<int>& vertices) {
  const int n = static_cast<int>(vertices.size());
  const int first = static_cast<int>(tree_.order.size());
  if (n <= 2) {
    tree_.order.insert(tree_.order.end(), vertices.begin(), vertices.end());
    return node(first, vertices.size(), {});
  }
  const int part = in_[vertices.front()];
  for (int k = 0; k < n; ++k) level_[vertices[k]] = k;  // (level_ as each vertex's local index)
  std::vector<Eigen::Triplet<double>> entries;
  for (int k = 0; k < n; ++k) {
    entries.emplace_back(k, k, 1.0);
    for (int p = g_.begin[vertices[k]]; p < g_.begin[vertices[k] + 1]; ++p)
      if (const int w = g_.index[p]; in_[w] == part) entries.emplace_back(level_[w], k, 1.0);
  }
  for (int v : vertices) level_[v] = -1;
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> perm;
  Eigen::AMDOrdering<int>()(A, perm);
  for (int k = 0; k < n; ++k) tree_.order.push_back(vertices[perm.indices()[k]]);
  return node(first, vertices.size(), {});
}

// A connected part: its separator, the level where the count below reaches half, its vertices
// then moved to the side they alone touch (one with no neighbour above is below's, then one with
// none below is above's), which keeps the two sides apart; below, above, then the separator.
int Dissection::dissect(const std::vector<int>& vertices, int part) {
  Levels L = peripheral_levels(g_, vertices.front(), part, in_, level_);
  const int n = static_cast<int>(vertices.size());
  const int depth = static_cast<int>(L.first.size()) - 1;
  int middle = 1;
  while (middle + 1 < depth && 2 * L.first[middle + 1] <= n) ++middle;
  const int below = new_part(), above = new_part(), separator = new_part();
  for (int v : vertices) {
    const int l = level_[v];
    in_[v] = l < middle ? below : l > middle ? above : separator;
  }
  for (int v : L.seen) level_[v] = -1;
  const auto touches = [&](int v, int side) {
    for (int p = g_.begin[v]; p < g_.begin[v + 1]; ++p)
      if (in_[g_.index[p]] == side) return true;
    return false;
  };
  for (int v : vertices)
    if (in_[v] == separator && !touches(v, above)) in_[v] = below;
  for (int v : vertices)
    if (in_[v] == separator && !touches(v, below)) in_[v] = above;
  std::vector<int> lower, upper, cut;
  for (int v : vertices) (in_[v] == below ? lower : in_[v] == above ? upper : cut).push_back(v);
  if (lower.empty() || upper.empty()) {  // nothing cuts it (a clique, say): one leaf
    as_part(vertices, separator);
    return leaf(vertices);
  }
  const int first = static_cast<int>(tree_.order.size());
  std::vector<int> children{order(lower, below)};
  children.push_back(order(upper, above));
  tree_.order.insert(tree_.order.end(), cut.begin(), cut.end());
  return node(first, cut.size(), std::move(children));
}

}  // namespace

DissectionTree nested_dissection(const std::vector<int>& begin, const std::vector<int>& index) {
  const Graph g{begin, index};
  Dissection d(g);
  std::vector<int> all(begin.size() - 1);
  for (std::size_t v = 0; v < all.size(); ++v) all[v] = static_cast<int>(v);
  d.order(all, 0);
  return d.take();
}

}  // namespace springlab
