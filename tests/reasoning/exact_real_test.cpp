#include "reasoning/exact_real.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>

namespace mechanist {
namespace {

TEST(ExactReal, DecimalsAreReadAsWritten) {
  EXPECT_EQ(*ExactReal::FromDecimal(1.5).exact(), Rational(3, 2));
  EXPECT_EQ(*ExactReal::FromDecimal(0.1).exact(), Rational(1, 10));
  EXPECT_EQ(*ExactReal::FromDecimal(25.4).exact(), Rational(127, 5));
  EXPECT_EQ(*ExactReal::FromDecimal(-3).exact(), Rational(-3));
  EXPECT_FALSE(ExactReal::FromDecimal(3.141592653589793).is_exact());
  EXPECT_EQ(ExactReal(Rational(1, 40)).ToString(), "1/40");
}

// The value of an exact decimal is computed from p/q: it must be the double the user wrote,
// for every decimal of up to 15 digits whose power of ten fits.
TEST(ExactReal, ExactDecimalsReadBackAsTheirDouble) {
  std::mt19937_64 random(7);
  int exact = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const int digits = 1 + static_cast<int>(random() % 15);
    const std::int64_t mantissa =
        static_cast<std::int64_t>(random() % static_cast<std::uint64_t>(std::pow(10, digits)));
    const int exponent = static_cast<int>(random() % 24) - 18;
    const double value = (trial % 2 ? -1.0 : 1.0) *
                         std::stod(std::to_string(mantissa) + "e" + std::to_string(exponent));
    const ExactReal r = ExactReal::FromDecimal(value);
    EXPECT_EQ(r.value(), value) << mantissa << "e" << exponent;
    exact += r.is_exact();  // only exact values are computed from p/q
  }
  EXPECT_GT(exact, 15000);
}

TEST(ExactReal, ApproximateValuesKeepEveryBit) {
  for (const double v :
       {0.1, -0.0, 3.141592653589793, -1e300, 5e-324, std::numeric_limits<double>::infinity()}) {
    const ExactReal r = ExactReal::Approximate(v);
    EXPECT_FALSE(r.is_exact());
    EXPECT_FALSE(r.exact().has_value());
    EXPECT_EQ(std::signbit(r.value()), std::signbit(v));
    EXPECT_EQ(r.value(), v);
  }
  EXPECT_TRUE(std::isnan(ExactReal::Approximate(std::nan("")).value()));
  EXPECT_EQ(ExactReal::Approximate(0.5).ToString(), "0.5");
}

// Against independent oracles: Rational arithmetic for exact operands, double arithmetic as
// soon as one operand is approximate.
TEST(ExactReal, ArithmeticAgreesWithRationalsAndDoubles) {
  std::mt19937_64 random(11);
  auto small = [&] { return static_cast<std::int64_t>(random() % 199) - 99; };
  for (int trial = 0; trial < 5000; ++trial) {
    std::int64_t q1 = small(), q2 = small();
    if (q1 == 0) q1 = 1;
    if (q2 == 0) q2 = -1;
    const Rational a(small(), q1), b(small(), q2);
    const ExactReal x(a), y(b);
    EXPECT_EQ(*(x + y).exact(), a + b);
    EXPECT_EQ(*(x - y).exact(), a - b);
    EXPECT_EQ(*(x * y).exact(), a * b);
    EXPECT_EQ(*(-x).exact(), -a);
    EXPECT_EQ((x + y).value(), (a + b).ToDouble());
    if (!b.is_zero()) {
      EXPECT_EQ(*(x / y).exact(), a / b);
    }
    const double d = static_cast<double>(small()) / 7.0;
    const ExactReal z = ExactReal::Approximate(d);
    EXPECT_FALSE((x + z).is_exact());
    EXPECT_EQ((x + z).value(), a.ToDouble() + d);
    EXPECT_EQ((z * y).is_exact(), b.is_zero());  // an exact zero annihilates
    EXPECT_EQ((z * y).value(), b.is_zero() ? 0.0 : d * b.ToDouble());
    EXPECT_EQ((-z).value(), -d);
  }
}

TEST(ExactReal, OverflowFallsBackToTheDouble) {
  const ExactReal big(Rational(INT64_MAX / 2));
  const ExactReal product = big * ExactReal(Rational(3));
  EXPECT_FALSE(product.is_exact());
  EXPECT_EQ(product.value(), static_cast<double>(INT64_MAX / 2) * 3.0);
  EXPECT_EQ((big + big + big).value(), 3.0 * static_cast<double>(INT64_MAX / 2));
  EXPECT_THROW(big / ExactReal(), std::domain_error);
  EXPECT_THROW(big / ExactReal::Approximate(0.0), std::domain_error);
  EXPECT_TRUE(ExactReal().IsZero(0.0));
  EXPECT_TRUE(ExactReal::Approximate(1e-10).IsZero(1e-9));
  EXPECT_FALSE(ExactReal(Rational(1, INT64_MAX)).IsZero(1e-9));  // exact: not zero
}

}  // namespace
}  // namespace mechanist
