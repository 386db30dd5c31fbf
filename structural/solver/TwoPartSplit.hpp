#pragma once
// Items (terms, event sources) dealt into two parts of about equal cost, for work that the
// explicit step runs on its two threads (docs/performance.md, "Two threads"). Items that must
// stay together (a group) go to one part; each part keeps the items' order. The split depends on
// the scene only, never on the thread count.
#include <vector>

namespace chute {

struct TwoPartSplit {
  std::vector<int> part[2];  // item indices, ascending
  bool split() const { return !part[0].empty() && !part[1].empty(); }
};

// groupOf[i]: item i's group (any ints); cost[i] >= 0. The groups, costliest first (ties: the
// one met first), each to the part with less cost so far (a tie: the first).
TwoPartSplit splitInTwo(const std::vector<int>& groupOf, const std::vector<double>& cost);

// The groups of items that share a free node: nodesOf[i] are the nodes item i reads or writes,
// freeNode[n] whether node n may move (a node fixed in all three directions is never written, so
// it joins no one). Items without free nodes are groups of their own.
std::vector<int> groupsBySharedFreeNodes(const std::vector<std::vector<int>>& nodesOf,
                                         const std::vector<char>& freeNode);

}  // namespace chute
