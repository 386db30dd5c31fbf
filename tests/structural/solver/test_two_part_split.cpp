// The explicit step's two-part split (solver/TwoPartSplit.hpp): groups stay whole, each part keeps
// the items' order, costs are balanced greedily; items sharing a free node form one group, a
// node fixed in all three directions joins no one.
#include <gtest/gtest.h>

#include <algorithm>

#include "solver/TwoPartSplit.hpp"

using namespace chute;

TEST(TwoPartSplit, GroupsStayWholeAndThePartsKeepTheItemsOrder) {
  // Four groups of costs 7, 7, 7, 7 (seven lines a grommet, as the C-9's), interleaved.
  std::vector<int> group;
  std::vector<double> cost;
  for (int i = 0; i < 28; ++i) group.push_back(i % 4), cost.push_back(1.0);
  const TwoPartSplit s = splitInTwo(group, cost);
  ASSERT_TRUE(s.split());
  EXPECT_EQ(s.part[0].size(), 14u);
  EXPECT_EQ(s.part[1].size(), 14u);
  for (int p = 0; p < 2; ++p) {
    EXPECT_TRUE(std::is_sorted(s.part[p].begin(), s.part[p].end()));
    for (int i : s.part[p])
      for (int j : s.part[1 - p]) EXPECT_NE(group[i], group[j]) << i << " and " << j;
  }
}

TEST(TwoPartSplit, CostliestGroupsFirstEachToTheLighterPart) {
  // Groups of cost 5, 4, 3, 3, 1: 5 -> first, 4 -> second, 3 -> second (7), 3 -> first (8),
  // 1 -> second (8).
  const std::vector<int> group = {0, 1, 2, 3, 4};
  const std::vector<double> cost = {5, 4, 3, 3, 1};
  const TwoPartSplit s = splitInTwo(group, cost);
  EXPECT_EQ(s.part[0], (std::vector<int>{0, 3}));
  EXPECT_EQ(s.part[1], (std::vector<int>{1, 2, 4}));
}

TEST(TwoPartSplit, OneGroupIsNotSplit) {
  const TwoPartSplit s = splitInTwo({3, 3, 3}, {1, 2, 3});
  EXPECT_FALSE(s.split());
  EXPECT_EQ(s.part[0], (std::vector<int>{0, 1, 2}));
}

TEST(TwoPartSplit, ItemsSharingAFreeNodeAreOneGroupAFixedNodeJoinsNoOne) {
  // Lines 0-3 all end at node 0 (fixed: a confluence held); 0 and 1 share grommet node 5, 2 and
  // 3 grommet node 6; line 4 shares nothing; line 5 reaches line 4 through node 9, free.
  std::vector<char> freeNode(10, 1);
  freeNode[0] = 0;
  const std::vector<std::vector<int>> nodes = {{0, 1, 5}, {0, 2, 5}, {0, 3, 6},
                                               {0, 4, 6}, {7, 9},    {8, 9}};
  const std::vector<int> g = groupsBySharedFreeNodes(nodes, freeNode);
  EXPECT_EQ(g[0], g[1]);
  EXPECT_EQ(g[2], g[3]);
  EXPECT_NE(g[0], g[2]);
  EXPECT_EQ(g[4], g[5]);
  EXPECT_NE(g[4], g[0]);
  EXPECT_NE(g[4], g[2]);
  // Freed, the confluence makes them all one.
  freeNode[0] = 1;
  const std::vector<int> one = groupsBySharedFreeNodes(nodes, freeNode);
  EXPECT_EQ(one[0], one[2]);
  EXPECT_NE(one[0], one[4]);
}
