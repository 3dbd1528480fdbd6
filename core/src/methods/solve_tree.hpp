// A sparse Cholesky factor's rows as a tree of blocks whose triangular solves are independent
// (Liu 1990, "The role of elimination trees in sparse factorization"): row j's parent in the
// elimination tree is the first row below the diagonal in L's column j, and an entry L_ij of row
// i lies in a column j of i's subtree. With the rows in a postorder of that tree, every subtree's
// rows are consecutive, ending at its root; so a block that gathers whole subtrees has entries
// only in itself and below (local_global_solves.cpp deals such blocks to threads).
//
// The blocks (nodes here), by subtree: one of less than 1/16 of the factor's work is small, of
// less than 1/256 tiny (solve_tree.cpp). A block is a chain of rows above the rest of their
// subtrees, each row with one child not small and none other but tiny ones (their rows join the
// chain's block), and below it a block for each child of its lowest row that is not tiny: a small
// one whole, a larger one a chain again. So there are at most 31 chains and 256 small blocks,
// whatever the tree. In postorder (below), a row's children that are not small come before its
// small ones, then its tiny ones, and each block's own rows are consecutive.
#pragma once

#include <vector>

namespace springlab {

struct SolveTree {
  // Node d covers the rows [first, end): its children's, consecutive in the children's order,
  // then its own, [own, end). Nodes are listed children first; the last is the root (which owns
  // no row where the factor is a forest of several trees).
  struct Node {
    int first = 0, own = 0, end = 0;
    int parent = -1;
    std::vector<int> children;
  };
  std::vector<Node> nodes;
};

// A postorder of the forest of `parent` (parent[j] > j, or -1) that visits each row's children
// (and the roots) those not small first, then the small, then the tiny (by their rows' `work`),
// each class in the order of their rows: order[k] is the row at place k. (Children by weight,
// heaviest first, made local-global's solves 5 % slower on one thread, its rows further from
// AMD's order.)
std::vector<int> postorder(const std::vector<int>& parent, const std::vector<double>& work);

// The blocks of a factor's rows in such a postorder: each row's parent and work.
SolveTree solve_tree(const std::vector<int>& parent, const std::vector<double>& work);

}  // namespace springlab
