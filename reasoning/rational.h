#pragma once

#include <compare>
#include <cstdint>
#include <string>

namespace mechanist {

/// An exact ratio p/q of 64-bit integers, always reduced with q > 0: transmission ratios are
/// products of tooth counts, so 1/40 stays 1/40 instead of 0.025000000000000001.
/// Arithmetic throws std::overflow_error when a reduced result does not fit in 64 bits.
class Rational {
 public:
  Rational() = default;
  Rational(std::int64_t integer) : numerator_(integer) {}  // NOLINT: implicit on purpose
  /// Throws std::invalid_argument for a zero denominator.
  Rational(std::int64_t numerator, std::int64_t denominator);

  /// p/q already in lowest terms with q > 0, as another Rational gave them: no reduction.
  /// Checked in debug builds.
  static Rational FromReduced(std::int64_t numerator, std::int64_t denominator);

  std::int64_t numerator() const { return numerator_; }
  std::int64_t denominator() const { return denominator_; }
  double ToDouble() const { return static_cast<double>(numerator_) / denominator_; }
  bool is_zero() const { return numerator_ == 0; }
  /// "p/q", or "p" when q = 1.
  std::string ToString() const;

  Rational operator-() const;
  Rational operator+(const Rational& o) const;
  Rational operator-(const Rational& o) const { return *this + (-o); }
  Rational operator*(const Rational& o) const;
  /// Throws std::domain_error for division by zero.
  Rational operator/(const Rational& o) const;
  bool operator==(const Rational& o) const = default;
  std::strong_ordering operator<=>(const Rational& o) const;

 private:
  std::int64_t numerator_ = 0;
  std::int64_t denominator_ = 1;
};

}  // namespace mechanist
