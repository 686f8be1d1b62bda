#pragma once

#include <bit>
#include <cstdint>
#include <optional>
#include <string>

#include "reasoning/rational.h"

namespace mechanist {

/// A real number carried both as a double and, while every input to it was exact, as an
/// exact Rational: motion rates are exact where the mechanism is made of tooth counts, thread
/// leads and idealised (parallel, perpendicular, coincident) geometry, and approximate where
/// general geometry (a linkage's lever arms) or pi (a rack's travel) enters. Arithmetic keeps
/// both; the exact part is dropped, never wrong, when an input is approximate or the result
/// does not fit in 64 bits.
class ExactReal {
 public:
  ExactReal() : numerator_(0), denominator_(1) {}
  ExactReal(const Rational& exact)  // NOLINT: implicit on purpose, like Rational's
      : numerator_(exact.numerator()), denominator_(exact.denominator()) {}
  /// An approximate number.
  static ExactReal Approximate(double value);
  /// The exact value of a decimal number as a user writes it (1.5 -> 3/2, 0.25 -> 1/4): the
  /// shortest decimal with at most 15 significant digits that reads back as `value`;
  /// approximate when that needs more than 64 bits.
  static ExactReal FromDecimal(double value);

  /// The value, the exact one rounded to the nearest double.
  double value() const {
    return denominator_ != 0 ? static_cast<double>(numerator_) / static_cast<double>(denominator_)
                             : std::bit_cast<double>(numerator_);
  }
  std::optional<Rational> exact() const {
    if (!is_exact()) return std::nullopt;
    return Rational::FromReduced(numerator_, denominator_);
  }
  bool is_exact() const { return denominator_ != 0; }
  /// Exactly zero when exact; otherwise |value| <= tolerance.
  bool IsZero(double tolerance) const;
  /// "p/q" when exact, otherwise FormatNumber(value, 10).
  std::string ToString() const;

  ExactReal operator-() const;
  ExactReal operator+(const ExactReal& o) const;
  ExactReal operator-(const ExactReal& o) const { return *this + (-o); }
  ExactReal operator*(const ExactReal& o) const;
  /// Throws std::domain_error when `o` is zero.
  ExactReal operator/(const ExactReal& o) const;
  ExactReal& operator+=(const ExactReal& o) { return *this = *this + o; }

 private:
  bool is_exact_zero() const { return denominator_ != 0 && numerator_ == 0; }
  // 16 bytes, not a double beside an optional Rational (32): linear-system rows, feature rates
  // and part motions hold many of them. Exact: the reduced p/q with q > 0, and value() its
  // nearest double. Approximate: q = 0, and p holds the double's bits.
  std::int64_t numerator_;
  std::int64_t denominator_;
};

}  // namespace mechanist
