#include "reasoning/pair_graph.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "test_assembly.h"

namespace mechanist {
namespace {

using testing::MakeAssembly;
using testing::MakePart;

Pair Edge(std::size_t a, std::size_t b, PairType type) {
  Pair p;
  p.type = type;
  p.a = {a, 0};
  p.b = {b, 0};
  return p;
}

TEST(PairGraph, SubassembliesAreFixedComponentsWithAllGroundPartsJoined) {
  // c and a are ground (never connected by a pair); b is fixed to a; d, e fixed to each
  // other and revolute to b; f alone.
  const Assembly assembly = MakeAssembly(
      {MakePart("c", {}, RigidTransform(), true), MakePart("a", {}, RigidTransform(), true),
       MakePart("b", {}), MakePart("e", {}), MakePart("d", {}), MakePart("f", {})});
  const std::vector<Pair> pairs = {Edge(1, 2, PairType::kFixed), Edge(3, 4, PairType::kFixed),
                                   Edge(2, 4, PairType::kRevolute)};
  const PairGraph graph(assembly, pairs);
  EXPECT_EQ(graph.part_count(), 6u);
  EXPECT_EQ(graph.PairsOf(4), (std::vector<std::size_t>{1, 2}));
  EXPECT_TRUE(graph.PairsOf(5).empty());
  const auto groups = graph.Subassemblies();
  ASSERT_EQ(groups.size(), 3u);
  EXPECT_TRUE(groups[0].ground);
  EXPECT_EQ(groups[0].parts, (std::vector<std::size_t>{1, 2, 0}));  // a, b, c by id
  EXPECT_FALSE(groups[1].ground);
  EXPECT_EQ(groups[1].parts, (std::vector<std::size_t>{4, 3}));  // d, e
  EXPECT_EQ(groups[2].parts, (std::vector<std::size_t>{5}));
}

TEST(PairGraph, ReachableCrossesOnlyThePairsItIsAllowedTo) {
  // a - b (fixed), b - c (gear), c - d (revolute), e alone; a pair from d to itself.
  const Assembly assembly = MakeAssembly({MakePart("a", {}), MakePart("b", {}), MakePart("c", {}),
                                          MakePart("d", {}), MakePart("e", {})});
  const std::vector<Pair> pairs = {Edge(0, 1, PairType::kFixed), Edge(1, 2, PairType::kGear),
                                   Edge(2, 3, PairType::kRevolute), Edge(3, 3, PairType::kFixed)};
  const PairGraph graph(assembly, pairs);
  auto all = [](std::size_t, std::size_t, std::size_t) { return true; };
  const std::size_t a = 0, e = 4;
  EXPECT_EQ(graph.Reachable({&a, 1}, all), (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_EQ(graph.Reachable({&e, 1}, all), (std::vector<std::size_t>{4}));
  // Not across gear teeth: a and b only.
  const auto no_gears = [&](std::size_t pair, std::size_t, std::size_t) {
    return pairs[pair].type != PairType::kGear;
  };
  EXPECT_EQ(graph.Reachable({&a, 1}, no_gears), (std::vector<std::size_t>{0, 1}));
  // The callback sees each crossing's direction: from c, only towards higher indices.
  const std::size_t c = 2;
  EXPECT_EQ(
      graph.Reachable({&c, 1}, [](std::size_t, std::size_t at, std::size_t to) { return to > at; }),
      (std::vector<std::size_t>{2, 3}));
  // Several starts, given twice.
  const std::vector<std::size_t> starts = {3, 4, 3};
  EXPECT_EQ(graph.Reachable(starts, no_gears), (std::vector<std::size_t>{2, 3, 4}));
}

TEST(PairGraph, SubassembliesMatchABruteForceGroupingOnRandomAssemblies) {
  // Oracle: components labelled by relaxing over the fixed pairs to the largest label (every
  // ground part starts with the largest, n, so they form one component), each ordered by id, the
  // ground one first and the others by their first id. Ids are shuffled against the file order, so
  // that a floating group can come before the ground one by id.
  std::mt19937 random(3);
  for (int trial = 0; trial < 50; ++trial) {
    const std::size_t n = 1 + random() % 12;
    std::vector<std::string> ids;
    for (std::size_t i = 0; i < n; ++i) ids.push_back("p" + std::to_string(100 + i));
    std::shuffle(ids.begin(), ids.end(), random);
    std::vector<Part> parts;
    for (std::size_t i = 0; i < n; ++i) {
      parts.push_back(MakePart(ids[i], {}, RigidTransform(), random() % 4 == 0));
    }
    std::vector<Pair> pairs;
    for (std::size_t k = random() % (2 * n); k > 0; --k) {
      pairs.push_back(
          Edge(random() % n, random() % n, random() % 3 ? PairType::kFixed : PairType::kRevolute));
    }
    const Assembly assembly = MakeAssembly(parts);
    std::vector<std::size_t> label(n);
    for (std::size_t i = 0; i < n; ++i) label[i] = assembly.IsGround(i) ? n : i;
    for (bool changed = true; changed;) {
      changed = false;
      for (const Pair& p : pairs) {
        if (p.type != PairType::kFixed) continue;
        std::size_t& x = label[p.a.part];
        std::size_t& y = label[p.b.part];
        if (x != y) x = y = std::max(x, y), changed = true;
      }
    }
    std::map<std::size_t, std::vector<std::size_t>> components;
    for (std::size_t i = 0; i < n; ++i) components[label[i]].push_back(i);
    const auto by_id = [&](std::size_t x, std::size_t y) { return ids[x] < ids[y]; };
    std::vector<Subassembly> expected;
    for (auto& [l, members] : components) {
      std::sort(members.begin(), members.end(), by_id);
      Subassembly s;
      s.parts = members;
      s.ground = l == n;
      expected.push_back(s);
    }
    std::sort(expected.begin(), expected.end(), [&](const Subassembly& x, const Subassembly& y) {
      if (x.ground != y.ground) return x.ground;
      return by_id(x.parts.front(), y.parts.front());
    });
    const std::vector<Subassembly> groups = PairGraph(assembly, pairs).Subassemblies();
    ASSERT_EQ(groups.size(), expected.size()) << "trial " << trial;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      EXPECT_EQ(groups[g].parts, expected[g].parts) << "trial " << trial << ", group " << g;
      EXPECT_EQ(groups[g].ground, expected[g].ground) << "trial " << trial << ", group " << g;
    }
  }
}

TEST(PairGraph, NoGroundPartMeansNoGroundSubassembly) {
  const Assembly assembly = MakeAssembly({MakePart("x", {}), MakePart("y", {})});
  const auto groups = PairGraph(assembly, {Edge(0, 1, PairType::kFixed)}).Subassemblies();
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_FALSE(groups[0].ground);
}

}  // namespace
}  // namespace mechanist
