// The gap-search example's conclusions: one enclosed cavity of the analytic volume at a
// coarse voxel, none once the voxel resolves the drain hole.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "io/load_assembly.h"
#include "reasoning/gap_search.h"

namespace mechanist {
namespace {

TEST(GapExamples, SealedEnclosureDrainsOnceTheVoxelResolvesItsHole) {
  const Assembly assembly = LoadAssembly(std::filesystem::path(MECHANIST_SOURCE_DIR) /
                                         "examples/sealed_enclosure/assembly.json");
  GapSearchOptions options;
  options.voxel = 2.0;
  const GapSearch coarse = FindGaps(assembly, options);
  ASSERT_EQ(coarse.gaps.size(), 1u);
  const Gap& gap = coarse.gaps[0];
  EXPECT_LE(std::abs(gap.volume - 114.0 * 54 * 30), gap.volume_error);
  EXPECT_EQ(gap.parts.size(), 6u);
  EXPECT_GE(gap.wall, 3.0 - options.voxel);
  EXPECT_LE(gap.wall, 3.0 + options.voxel);
  options.voxel = 0.5;
  EXPECT_TRUE(FindGaps(assembly, options).gaps.empty());
}

TEST(GapExamples, AThreeMillimetreDrainHoleIsOpenAtTwoMillimetreVoxels) {
  // The same box with a 3 mm hole: 1.5 voxels wide, it holds free octants and drains.
  const std::filesystem::path file =
      std::filesystem::path(MECHANIST_SOURCE_DIR) / "examples/sealed_enclosure/assembly.json";
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string hole = "\"diameter\": 1}";
  const auto at = text.find(hole);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, hole.size(), "\"diameter\": 3}");
  GapSearchOptions options;
  options.voxel = 2.0;
  EXPECT_TRUE(FindGaps(LoadAssemblyText(text, file), options).gaps.empty());
  options.voxel = 7.0;  // the hole narrower than half an octant's diagonal: closed
  EXPECT_EQ(FindGaps(LoadAssemblyText(text, file), options).gaps.size(), 1u);
}

}  // namespace
}  // namespace mechanist
