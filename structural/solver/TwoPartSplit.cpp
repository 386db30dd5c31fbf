#include "solver/TwoPartSplit.hpp"

#include <algorithm>
#include <map>
#include <numeric>

namespace chute {

TwoPartSplit splitInTwo(const std::vector<int>& groupOf, const std::vector<double>& cost) {
  // Groups in the order first met, with their cost.
  std::vector<int> order;
  std::map<int, size_t> slot;
  std::vector<double> groupCost;
  for (size_t i = 0; i < groupOf.size(); ++i) {
    auto [it, fresh] = slot.emplace(groupOf[i], groupCost.size());
    if (fresh) groupCost.push_back(0.0), order.push_back(groupOf[i]);
    groupCost[it->second] += cost[i];
  }
  std::vector<size_t> byCost(groupCost.size());
  std::iota(byCost.begin(), byCost.end(), size_t{0});
  std::stable_sort(byCost.begin(), byCost.end(),
                   [&](size_t a, size_t b) { return groupCost[a] > groupCost[b]; });
  std::vector<int> partOfGroup(groupCost.size(), 0);
  double load[2] = {0.0, 0.0};
  for (size_t g : byCost) {
    const int p = load[1] < load[0] ? 1 : 0;
    partOfGroup[g] = p;
    load[p] += groupCost[g];
  }
  TwoPartSplit out;
  for (size_t i = 0; i < groupOf.size(); ++i)
    out.part[partOfGroup[slot[groupOf[i]]]].push_back(static_cast<int>(i));
  return out;
}

std::vector<int> groupsBySharedFreeNodes(const std::vector<std::vector<int>>& nodesOf,
                                         const std::vector<char>& freeNode) {
  // Union-find over the items: each free node remembers the first item that had it.
  std::vector<int> parent(nodesOf.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::map<int, int> holder;
  for (size_t i = 0; i < nodesOf.size(); ++i)
    for (int n : nodesOf[i]) {
      if (!freeNode[n]) continue;
      auto [it, fresh] = holder.emplace(n, static_cast<int>(i));
      if (!fresh) {
        const int a = find(static_cast<int>(i)), b = find(it->second);
        parent[std::max(a, b)] = std::min(a, b);
      }
    }
  std::vector<int> group(nodesOf.size());
  for (size_t i = 0; i < nodesOf.size(); ++i) group[i] = find(static_cast<int>(i));
  return group;
}

}  // namespace chute
