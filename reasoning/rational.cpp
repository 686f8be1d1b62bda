#include "reasoning/rational.h"

#include <fmt/format.h>

#include <cassert>
#include <numeric>
#include <stdexcept>

namespace mechanist {
namespace {

// 128-bit intermediates: products of two 64-bit values never overflow before reduction.
__extension__ using Wide = __int128;

std::int64_t Checked(Wide value) {
  if (value > INT64_MAX || value < -INT64_MAX) {
    throw std::overflow_error("exact ratio does not fit in 64 bits");
  }
  return static_cast<std::int64_t>(value);
}

/// Reduces p/q computed in 128 bits, then checks that it fits.
Rational Reduced(Wide p, Wide q) {
  if (q < 0) p = -p, q = -q;
  Wide a = p < 0 ? -p : p, b = q;
  while (b != 0) {
    const Wide r = a % b;
    a = b;
    b = r;
  }
  if (a > 1) p /= a, q /= a;
  return Rational(Checked(p), Checked(q));
}

}  // namespace

Rational::Rational(std::int64_t numerator, std::int64_t denominator) {
  if (denominator == 0) throw std::invalid_argument("zero denominator in a ratio");
  if (numerator == INT64_MIN || denominator == INT64_MIN) {
    throw std::overflow_error("exact ratio does not fit in 64 bits");
  }
  const std::int64_t g = std::gcd(numerator, denominator);
  numerator_ = (denominator < 0 ? -numerator : numerator) / (g == 0 ? 1 : g);
  denominator_ = (denominator < 0 ? -denominator : denominator) / (g == 0 ? 1 : g);
}

Rational Rational::FromReduced(std::int64_t numerator, std::int64_t denominator) {
  assert(denominator > 0 && std::gcd(numerator, denominator) == 1);
  Rational r;
  r.numerator_ = numerator;
  r.denominator_ = denominator;
  return r;
}

std::string Rational::ToString() const {
  return denominator_ == 1 ? std::to_string(numerator_)
                           : fmt::format("{}/{}", numerator_, denominator_);
}

Rational Rational::operator-() const { return Rational(-numerator_, denominator_); }

Rational Rational::operator+(const Rational& o) const {
  return Reduced(static_cast<Wide>(numerator_) * o.denominator_ +
                     static_cast<Wide>(o.numerator_) * denominator_,
                 static_cast<Wide>(denominator_) * o.denominator_);
}

Rational Rational::operator*(const Rational& o) const {
  return Reduced(static_cast<Wide>(numerator_) * o.numerator_,
                 static_cast<Wide>(denominator_) * o.denominator_);
}

Rational Rational::operator/(const Rational& o) const {
  if (o.numerator_ == 0) throw std::domain_error("division of a ratio by zero");
  return Reduced(static_cast<Wide>(numerator_) * o.denominator_,
                 static_cast<Wide>(denominator_) * o.numerator_);
}

std::strong_ordering Rational::operator<=>(const Rational& o) const {
  return static_cast<Wide>(numerator_) * o.denominator_ <=>
         static_cast<Wide>(o.numerator_) * denominator_;
}

}  // namespace mechanist
