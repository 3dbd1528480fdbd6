// The factor's tree of blocks (solve_tree.hpp).
#include "solve_tree.hpp"

#include <algorithm>

namespace springlab {

namespace {

// A subtree of less than 1/kLeafShare of the factor's work is small: a block whole. One of less
// than 1/kTinyShare is tiny: in its parent's block, not one of its own (a rope with a particle
// hanging from each of its own: one block, not 3000). Each block a row's sum passes through is a
// step of it (local_global_solves.cpp), about 10 ns of a mispredicted loop end each. The 128 x 128
// cloth (AMD's tree), small below 1/8, 1/16, 1/32 and 1/64 of the work: 23, 40, 63 and 98 blocks,
// 5.0, 7.5, 10.3 and 14.1 thousand steps, and each lets 2, 4 and 8 threads gain as much (at most
// 1.72, 2.50 and 2.61 times: the top, AMD's last rows, is the floor); on the 256 x 256 cloth 1/16
// lets 16 threads gain 3.01 times, 1/8 2.96.
constexpr double kLeafShare = 16.0, kTinyShare = 256.0;

// Each subtree's work and rows, and its class: 0 not small, 1 small, 2 tiny.
struct Subtrees {
  std::vector<int> size;
  std::vector<double> below;
  double total = 0.0;
  Subtrees(const std::vector<int>& parent, const std::vector<double>& work)
      : size(parent.size(), 1), below(work) {
    for (std::size_t j = 0; j < parent.size(); ++j) {  // a parent's index is above its children's
      total += work[j];
      if (parent[j] >= 0) size[parent[j]] += size[j], below[parent[j]] += below[j];
    }
  }
  bool small(int j) const { return below[j] * kLeafShare < total; }
  bool tiny(int j) const { return below[j] * kTinyShare < total; }
  int size_class(int j) const { return small(j) + tiny(j); }
};

}  // namespace

std::vector<int> postorder(const std::vector<int>& parent, const std::vector<double>& work) {
  const int n = static_cast<int>(parent.size());
  const Subtrees sub(parent, work);
  std::vector<std::vector<int>> children(n);
  std::vector<int> roots, order, stack, next(n, 0);
  for (int j = 0; j < n; ++j) (parent[j] >= 0 ? children[parent[j]] : roots).push_back(j);
  const auto before = [&](int a, int b) {  // a class before the next, else the lower row
    return sub.size_class(a) < sub.size_class(b) ||
           (sub.size_class(a) == sub.size_class(b) && a < b);
  };
  for (auto& c : children) std::sort(c.begin(), c.end(), before);
  std::sort(roots.begin(), roots.end(), before);
  order.reserve(n);
  for (int root : roots) {
    stack.push_back(root);
    while (!stack.empty()) {
      const int p = stack.back();
      if (next[p] < static_cast<int>(children[p].size())) {
        stack.push_back(children[p][next[p]++]);
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
  const Subtrees sub(parent, work);
  const std::vector<int>& size = sub.size;
  std::vector<int> large(n, 0), blocks(n, 0), last_block(n, -1), bottom(n);
  const auto small = [&](int j) { return sub.small(j); };
  const auto tiny = [&](int j) { return sub.tiny(j); };
  for (int j = 0; j < n; ++j)  // each row's children that are blocks: how many, and the last
    if (const int p = parent[j]; p >= 0 && !small(p) && !tiny(j)) {
      large[p] += !small(j), ++blocks[p];
      last_block[p] = j;
    }
  const auto continues = [&](int p) { return large[p] == 1 && blocks[p] == 1; };
  std::vector<std::vector<int>> child_nodes(n);  // each row's children's blocks, in order
  SolveTree t;
  std::vector<int> roots;
  bool small_roots = false;  // whether the last root's block is small roots'
  const auto add = [&](int first, int own, int end, std::vector<int> children) {
    const int id = static_cast<int>(t.nodes.size());
    for (int c : children) t.nodes[c].parent = id;
    t.nodes.push_back({first, own, end, -1, std::move(children)});
    return id;
  };
  for (int j = 0; j < n; ++j) {
    const int first = j - size[j] + 1, p = parent[j];
    if (small(j)) {
      if (p >= 0 && !small(p) && !tiny(j)) child_nodes[p].push_back(add(first, first, j + 1, {}));
      if (p >= 0) continue;                                     // (else in its parent's block)
      if (small_roots && t.nodes[roots.back()].end == first) {  // one block for small roots
        t.nodes[roots.back()].end = j + 1;
      } else {
        roots.push_back(add(first, first, j + 1, {}));
        small_roots = true;
      }
      continue;
    }
    bottom[j] = continues(j) ? bottom[last_block[j]] : j;
    if (p >= 0 && continues(p)) continue;  // the chain goes on above
    const int b = bottom[j];
    const int id = add(first, blocks[b] ? last_block[b] + 1 : b - size[b] + 1, j + 1,
                       std::move(child_nodes[b]));
    (p >= 0 ? child_nodes[p] : roots).push_back(id);
    if (p < 0) small_roots = false;
  }
  if (roots.size() != 1) add(0, n, n, std::move(roots));  // a forest (or nothing): one root
  return t;
}

}  // namespace springlab
