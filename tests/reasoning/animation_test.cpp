// Which parts an animation shows in a clash, and when.

#include "reasoning/animation.h"

#include <gtest/gtest.h>

namespace mechanist {
namespace {

TEST(Animation, PartsAreInAClashFromTheirFirstContactOn) {
  Animation animation;
  animation.s = {0.0, 0.5, 1.0};
  animation.clash_from.assign(4, std::nullopt);
  PartContact at_rest;
  at_rest.part_a = 0;
  at_rest.part_b = 1;
  at_rest.verdict = ContactVerdict::kClash;
  PartContact mate = at_rest;
  mate.part_a = 2;
  mate.part_b = 3;
  mate.verdict = ContactVerdict::kTouching;
  OperationCheck check;
  check.clashes = {OperationClash{1, 2, 0.4, 0.0, Eigen::Vector3d::Zero()},
                   OperationClash{2, 3, 0.7, 0.0, Eigen::Vector3d::Zero()}};
  MarkClashes({at_rest, mate}, check, &animation);
  EXPECT_EQ(animation.clash_from[0], 0.0);
  EXPECT_EQ(animation.clash_from[1], 0.0);  // the earlier of its two clashes
  EXPECT_EQ(animation.clash_from[2], 0.4);
  EXPECT_EQ(animation.clash_from[3], 0.7);  // a touching mate is no clash
  EXPECT_TRUE(animation.InClash(0, 0));
  EXPECT_FALSE(animation.InClash(2, 0));
  EXPECT_TRUE(animation.InClash(2, 1));
  EXPECT_FALSE(animation.InClash(3, 1));
  EXPECT_TRUE(animation.InClash(3, 2));
}

}  // namespace
}  // namespace mechanist
