#include "kernel/collision/grid_broad_phase.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

namespace mechanist {
namespace {

using PairSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

// The oracle: every pair of boxes, tested directly.
PairSet BruteForce(const std::vector<Aabb>& boxes, const std::vector<std::uint32_t>& owners) {
  PairSet pairs;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    for (std::uint32_t j = i + 1; j < boxes.size(); ++j) {
      if (owners[i] != owners[j] && !boxes[i].empty() && !boxes[j].empty() &&
          boxes[i].Intersects(boxes[j])) {
        pairs.insert({i, j});
      }
    }
  }
  return pairs;
}

Aabb Box(const Eigen::Vector3d& center, const Eigen::Vector3d& half) {
  Aabb b;
  b.Extend(center - half);
  b.Extend(center + half);
  return b;
}

TEST(GridBroadPhase, FindsExactlyTheOverlappingPairsOfDifferentOwners) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> at(-100, 100), size(0.1, 6);
  for (const std::size_t n : {1u, 2u, 50u, 2000u}) {
    std::vector<Aabb> boxes;
    std::vector<std::uint32_t> owners;
    for (std::size_t i = 0; i < n; ++i) {
      // Mostly small boxes, a few spanning much of the scene (tested against all), some
      // touching exactly, and every third box sharing its owner with the one before.
      Eigen::Vector3d half(size(random), size(random), size(random));
      if (i % 97 == 5) half *= 20;
      const Eigen::Vector3d c(std::round(at(random)), std::round(at(random)), at(random));
      boxes.push_back(Box(c, i % 13 == 0 ? Eigen::Vector3d(0.5, 0.5, 0.5) : half));
      owners.push_back(static_cast<std::uint32_t>(i % 3 == 2 ? i - 1 : i));
    }
    const auto found = OverlappingBoxPairs(boxes, owners);
    const PairSet truth = BruteForce(boxes, owners);
    EXPECT_EQ(PairSet(found.begin(), found.end()), truth) << n << " boxes";
    EXPECT_EQ(found.size(), truth.size()) << "a pair reported twice";
    EXPECT_TRUE(std::is_sorted(found.begin(), found.end(),
                               [](const auto& x, const auto& y) { return x.first < y.first; }));
  }
}

TEST(GridBroadPhase, TouchingBoxesCountAndEmptyOnesNever) {
  std::vector<Aabb> boxes = {Box({0, 0, 0}, {1, 1, 1}), Box({2, 0, 0}, {1, 1, 1}), Aabb(),
                             Box({0, 0, 0}, {5, 5, 5})};
  const auto found = OverlappingBoxPairs(boxes, std::vector<std::uint32_t>{0, 1, 2, 0});
  EXPECT_EQ(PairSet(found.begin(), found.end()), (PairSet{{0, 1}, {1, 3}}));
  EXPECT_TRUE(OverlappingBoxPairs({}, {}).empty());
  EXPECT_THROW(OverlappingBoxPairs(boxes, std::vector<std::uint32_t>{0}), std::invalid_argument);
}

TEST(GridBroadPhase, ManyTinyBoxesFarApartStillFitTheKey) {
  // A million cells per axis at the median size: the cells grow until the key fits 32 bits.
  std::vector<Aabb> boxes;
  std::vector<std::uint32_t> owners;
  for (std::uint32_t i = 0; i < 3000; ++i) {
    const double x = (i % 3 == 0 ? 1e6 : 0.0) + 0.5 * i;
    boxes.push_back(Box({x, 1e6 * (i % 5 == 0), 1e6 * (i % 7 == 0)}, {0.3, 0.3, 0.3}));
    owners.push_back(i);
  }
  const auto found = OverlappingBoxPairs(boxes, owners);
  EXPECT_EQ(PairSet(found.begin(), found.end()), BruteForce(boxes, owners));
}

}  // namespace
}  // namespace mechanist
