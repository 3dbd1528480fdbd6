// A fill-reducing order for a symmetric matrix whose elimination tree branches near its root:
// nested dissection (George 1973; George and Liu 1978, "An automatic nested dissection
// algorithm"). A small set of vertices, a separator, cuts the matrix's graph in two; each half is
// ordered first, the same way, and the separator last. The two halves' rows then never meet in
// the factor, so that their triangular solves are independent, and the tree of halves says which
// rows a thread may take alone (local_global_solves.cpp). A minimum-degree order's elimination
// tree ends in one long chain instead: on the 128 x 128 cloth 35 % of the solves' work, which no
// cut shares between threads.
//
// Each separator is the middle level of a breadth-first level structure from a pseudo-peripheral
// vertex, its vertices then moved to the side they only touch; the halves are dissected until
// they have at most kLeaf vertices, and each leaf is ordered by minimum degree (Eigen's AMD) for
// its fill. The order depends on the graph alone (ties: the lower index), never on a thread count,
// so that a factor's bits are the same on every machine and in the browser.
#pragma once

#include <vector>

namespace springlab {

// The dissection: the order of the graph's vertices and its tree. Node d covers the places
// [first, end) of the order: its children's places, consecutive in the children's order, then
// its own, [own, end): a separator's vertices, or all of a leaf's. No edge joins two children's
// vertices, so a matrix factorised in this order has no entry between them, and an entry below a
// node's own rows lies in its own rows or its ancestors'. Nodes are listed children first; the
// last is the root.
struct DissectionTree {
  struct Node {
    int first = 0, own = 0, end = 0;
    int parent = -1;
    std::vector<int> children;
  };
  std::vector<int> order;  // order[k]: the vertex at place k
  std::vector<Node> nodes;
};

// The dissection of the graph with the adjacency in compressed rows: vertex v's neighbours are
// index[begin[v] .. begin[v + 1]) (without v itself; each edge both ways).
DissectionTree nested_dissection(const std::vector<int>& begin, const std::vector<int>& index);

}  // namespace springlab
