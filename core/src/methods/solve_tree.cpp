// The factor's tree of blocks (solve_tree.hpp).
#include "solve_tree.hpp"

namespace springlab {

namespace {

// A subtree of less than this share of the factor's work is one block. Each block a row's sum
// passes through is a step of it (local_global_solves.cpp), about 10 ns of a mispredicted loop
// end each: on the 128 x 128 cloth, shares of 8, 16, 32 and 64 make 23, 40, 63 and 98 blocks and
// 5.0, 7.5, 10.3 and 14.1 thousand steps, and every one lets 2, 4 and 8 threads gain as much
// (at most 1.72, 2.50 and 2.61 times: the top, AMD's last rows, is the floor); on the 256 x 256
// cloth 16 lets 16 threads gain 3.01 times, 8 2.96.
constexpr double kLeafShare = 16.0;

}  // namespace

std::vector<int> elimination_tree(const std::vector<int>& begin, const std::vector<int>& index) {
  const int n = static_cast<int>(begin.size()) - 1;
  std::vector<int> parent(n, -1), ancestor(n, -1);
  for (int k = 0; k < n; ++k)
    for (int p = begin[k]; p < begin[k + 1]; ++p)
      for (int i = index[p], next; i != -1 && i < k; i = next) {
        next = ancestor[i];
        ancestor[i] = k;  // (path compression: i's way up now leads to k at once)
        if (next == -1) parent[i] = k;
      }
  return parent;
}

std::vector<int> postorder(const std::vector<int>& parent) {
  const int n = static_cast<int>(parent.size());
  std::vector<int> head(n, -1), next(n, -1), order, stack;
  order.reserve(n);
  for (int j = n - 1; j >= 0; --j)  // each row's children, ascending
    if (parent[j] >= 0) next[j] = head[parent[j]], head[parent[j]] = j;
  for (int root = 0; root < n; ++root) {
    if (parent[root] >= 0) continue;
    stack.push_back(root);
    while (!stack.empty()) {
      const int p = stack.back();
      if (const int child = head[p]; child >= 0) {
        head[p] = next[child];
        stack.push_back(child);
      } else {
        stack.pop_back();
        order.push_back(p);
      }
    }
  }
  return order;
}

SolveTree solve_tree(const std::vector<int>& parent, const std::vector<double>& work) {
  const int n = static_cast<int>(parent.size());
  std::vector<int> size(n, 1), children(n, 0), bottom(n), top_node(n, -1);
  std::vector<double> below = work;  // each subtree's work
  double total = 0.0;
  for (int j = 0; j < n; ++j) {  // a parent's index is above its children's
    total += work[j];
    if (parent[j] >= 0)
      size[parent[j]] += size[j], below[parent[j]] += below[j], ++children[parent[j]];
  }
  std::vector<std::vector<int>> child_nodes(n);  // each row's children's blocks, ascending
  const auto small = [&](int j) { return below[j] * kLeafShare < total; };
  SolveTree t;
  const auto add = [&](int first, int own, int end, std::vector<int> kids) {
    const int id = static_cast<int>(t.nodes.size());
    for (int c : kids) t.nodes[c].parent = id;
    t.nodes.push_back({first, own, end, -1, std::move(kids)});
    return id;
  };
  std::vector<int> roots;
  for (int j = 0; j < n; ++j) {
    const int first = j - size[j] + 1;
    // The top of a block: a small row under a row that is not, or a row whose parent has other
    // children (a chain ends below a branch).
    const bool top = parent[j] < 0 || (small(j) ? !small(parent[j]) : children[parent[j]] != 1);
    if (small(j)) {  // the whole subtree one block, at its largest small row
      if (top) top_node[j] = add(first, first, j + 1, {});
    } else {
      // A row of one child, not small, continues that child's chain (the child is j - 1 in a
      // postorder); any other row begins a chain, over its children's blocks.
      bottom[j] = children[j] == 1 && !small(j - 1) ? bottom[j - 1] : j;
      if (top) top_node[j] = add(first, bottom[j], j + 1, std::move(child_nodes[bottom[j]]));
    }
    if (top) (parent[j] >= 0 ? child_nodes[parent[j]] : roots).push_back(top_node[j]);
  }
  if (roots.size() != 1) add(0, n, n, std::move(roots));  // a forest (or nothing): one root
  return t;
}

}  // namespace springlab
