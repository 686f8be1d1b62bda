#include "reasoning/exact_real.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "kernel/number_format.h"

namespace mechanist {
namespace {

/// Runs an exact operation, or gives nothing when an operand is approximate or it overflows.
template <typename Op>
std::optional<Rational> Exactly(const std::optional<Rational>& a, const std::optional<Rational>& b,
                                Op op) {
  if (!a || !b) return std::nullopt;
  try {
    return op(*a, *b);
  } catch (const std::overflow_error&) {
    return std::nullopt;
  }
}

}  // namespace

ExactReal ExactReal::Approximate(double value) { return ExactReal(value, std::nullopt); }

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
      return ExactReal(value, r);
    } catch (const std::overflow_error&) {
      return Approximate(value);
    }
  }
  return Approximate(value);
}

bool ExactReal::IsZero(double tolerance) const {
  return exact_ ? exact_->is_zero() : std::abs(value_) <= tolerance;
}

std::string ExactReal::ToString() const {
  return exact_ ? exact_->ToString() : FormatNumber(value_, 10);
}

ExactReal ExactReal::operator-() const {
  return ExactReal(-value_, exact_ ? std::optional<Rational>(-*exact_) : std::nullopt);
}

ExactReal ExactReal::operator+(const ExactReal& o) const {
  auto exact =
      Exactly(exact_, o.exact_, [](const Rational& a, const Rational& b) { return a + b; });
  return ExactReal(exact ? exact->ToDouble() : value_ + o.value_, exact);
}

ExactReal ExactReal::operator*(const ExactReal& o) const {
  // An exact zero annihilates even an approximate factor: a structural zero stays exact.
  if ((exact_ && exact_->is_zero()) || (o.exact_ && o.exact_->is_zero())) return ExactReal();
  auto exact =
      Exactly(exact_, o.exact_, [](const Rational& a, const Rational& b) { return a * b; });
  return ExactReal(exact ? exact->ToDouble() : value_ * o.value_, exact);
}

ExactReal ExactReal::operator/(const ExactReal& o) const {
  if (o.exact_ ? o.exact_->is_zero() : o.value_ == 0.0) {
    throw std::domain_error("division by zero");
  }
  if (exact_ && exact_->is_zero()) return ExactReal();
  auto exact =
      Exactly(exact_, o.exact_, [](const Rational& a, const Rational& b) { return a / b; });
  return ExactReal(exact ? exact->ToDouble() : value_ / o.value_, exact);
}

}  // namespace mechanist
