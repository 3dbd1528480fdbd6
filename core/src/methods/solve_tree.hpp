// A sparse Cholesky factor's rows as a tree of blocks whose triangular solves are independent
// (Liu 1990, "The role of elimination trees in sparse factorization"): row j's parent in the
// elimination tree is the first row below the diagonal in L's column j, and an entry L_ij of row
// i lies in a column j of i's subtree. With the rows in a postorder of that tree, every subtree's
// rows are consecutive, ending at its root; so a block that gathers whole subtrees has entries
// only in itself and below (local_global_solves.cpp deals such blocks to threads).
//
// A block (a node here) is a chain of rows that each have one child (their entries nest), with
// the blocks of its lowest row's children below it; a subtree of less than 1/kLeafShare of the
// factor's work is one block whole (a leaf), so that the tree stays as small as a team needs.
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

// The elimination tree of a symmetric matrix's pattern (Liu's algorithm, with path compression:
// Davis 2006, "Direct methods for sparse linear systems", cs_etree), its rows in the order to
// factor them: vertex v's neighbours index[begin[v] .. begin[v + 1]). parent[j] > j, or -1.
std::vector<int> elimination_tree(const std::vector<int>& begin, const std::vector<int>& index);

// A postorder of the forest (children in ascending order, each subtree before its parent):
// order[k] is the row at place k.
std::vector<int> postorder(const std::vector<int>& parent);

// The blocks of a postordered factor's rows: each row's parent (parent[j] > j, or -1) and work.
SolveTree solve_tree(const std::vector<int>& parent, const std::vector<double>& work);

}  // namespace springlab
