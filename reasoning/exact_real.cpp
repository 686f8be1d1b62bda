#include "reasoning/exact_real.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "kernel/support/number_format.h"

namespace mechanist {

static_assert(sizeof(ExactReal) == 16, "ExactReal has grown: rows, rates and motions hold many");

namespace {

/// Runs an exact operation, or gives nothing when the result overflows.
template <typename Op>
std::optional<Rational> Exactly(const Rational& a, const Rational& b, Op op) {
  try {
    return op(a, b);
  } catch (const std::overflow_error&) {
    return std::nullopt;
  }
}

/// The exact result when there is one, else the approximate value.
ExactReal Result(const std::optional<Rational>& exact, double approximate) {
  return exact ? ExactReal(*exact) : ExactReal::Approximate(approximate);
}

}  // namespace

ExactReal ExactReal::Approximate(double value) {
  ExactReal r;
  r.numerator_ = std::bit_cast<std::int64_t>(value);
  r.denominator_ = 0;
  return r;
}

ExactReal ExactReal::FromDecimal(double value) {
  if (!std::isfinite(value)) return Approximate(value);
  char text[64];
  for (int digits = 1; digits <= 15; ++digits) {
    std::snprintf(text, sizeof text, "%.*e", digits - 1, value);
    if (std::strtod(text, nullptr) != value) continue;
    // text is "d.ddde[+-]xx": mantissa digits and a decimal exponent.
    std::int64_t mantissa = 0;
    int exponent = std::atoi(std::strchr(text, 'e') + 1) - (digits - 1);
    for (const char* c = text; *c != 'e'; ++c) {
      if (*c >= '0' && *c <= '9') mantissa = mantissa * 10 + (*c - '0');
    }
    if (value < 0) mantissa = -mantissa;
    try {
      Rational r(mantissa);
      for (; exponent > 0; --exponent) r = r * Rational(10);
      for (; exponent < 0; ++exponent) r = r / Rational(10);
      // Its nearest double is `value`: at most 15 digits over a power of ten that fits in 64
      // bits are both exact doubles, and their quotient is rounded once.
      return r;
    } catch (const std::overflow_error&) {
      return Approximate(value);
    }
  }
  return Approximate(value);
}

bool ExactReal::IsZero(double tolerance) const {
  return is_exact() ? numerator_ == 0 : std::abs(value()) <= tolerance;
}

std::string ExactReal::ToString() const {
  return is_exact() ? exact()->ToString() : FormatNumber(value(), 10);
}

ExactReal ExactReal::operator-() const {
  if (!is_exact()) return Approximate(-value());
  ExactReal r;  // |p| <= INT64_MAX for every Rational, so -p fits
  r.numerator_ = -numerator_;
  r.denominator_ = denominator_;
  return r;
}

ExactReal ExactReal::operator+(const ExactReal& o) const {
  if (!is_exact() || !o.is_exact()) return Approximate(value() + o.value());
  return Result(
      Exactly(*exact(), *o.exact(), [](const Rational& a, const Rational& b) { return a + b; }),
      value() + o.value());
}

ExactReal ExactReal::operator*(const ExactReal& o) const {
  // An exact zero annihilates even an approximate factor: a structural zero stays exact.
  if (is_exact_zero() || o.is_exact_zero()) return ExactReal();
  if (!is_exact() || !o.is_exact()) return Approximate(value() * o.value());
  return Result(
      Exactly(*exact(), *o.exact(), [](const Rational& a, const Rational& b) { return a * b; }),
      value() * o.value());
}

ExactReal ExactReal::operator/(const ExactReal& o) const {
  if (o.is_exact() ? o.numerator_ == 0 : o.value() == 0.0) {
    throw std::domain_error("division by zero");
  }
  if (is_exact_zero()) return ExactReal();
  if (!is_exact() || !o.is_exact()) return Approximate(value() / o.value());
  return Result(
      Exactly(*exact(), *o.exact(), [](const Rational& a, const Rational& b) { return a / b; }),
      value() / o.value());
}

}  // namespace mechanist
