#include "reasoning/pair_graph.h"

#include <gtest/gtest.h>

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

TEST(PairGraph, NoGroundPartMeansNoGroundSubassembly) {
  const Assembly assembly = MakeAssembly({MakePart("x", {}), MakePart("y", {})});
  const auto groups = PairGraph(assembly, {Edge(0, 1, PairType::kFixed)}).Subassemblies();
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_FALSE(groups[0].ground);
}

}  // namespace
}  // namespace mechanist
