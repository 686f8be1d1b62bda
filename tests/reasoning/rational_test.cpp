#include "reasoning/rational.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace mechanist {
namespace {

TEST(Rational, ReducesAndKeepsTheSignInTheNumerator) {
  EXPECT_EQ(Rational(2, -4).ToString(), "-1/2");
  EXPECT_EQ(Rational(40, 40).ToString(), "1");
  EXPECT_EQ(Rational(0, -7), Rational(0));
  EXPECT_THROW(Rational(1, 0), std::invalid_argument);
}

TEST(Rational, ArithmeticIsExact) {
  // A compound train 17/31 * 31/17 is exactly 1; 1/3 + 1/6 = 1/2.
  EXPECT_EQ(Rational(17, 31) * Rational(31, 17), Rational(1));
  EXPECT_EQ(Rational(1, 3) + Rational(1, 6), Rational(1, 2));
  EXPECT_EQ(Rational(1, 3) - Rational(1, 2), Rational(-1, 6));
  EXPECT_EQ(Rational(3, 4) / Rational(-9, 8), Rational(-2, 3));
  EXPECT_LT(Rational(-1, 40), Rational(1, 40));
  EXPECT_DOUBLE_EQ(Rational(-1, 40).ToDouble(), -0.025);
  EXPECT_THROW(Rational(1) / Rational(0), std::domain_error);
}

TEST(Rational, OverflowIsReportedNotWrapped) {
  const Rational big(INT64_MAX / 2, 1);
  EXPECT_THROW(big * Rational(3), std::overflow_error);
  // Large intermediates that reduce back into range are fine.
  EXPECT_EQ(Rational(INT64_MAX / 3, 7) * Rational(7, INT64_MAX / 3), Rational(1));
}

}  // namespace
}  // namespace mechanist
