#pragma once

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
  ExactReal() : value_(0.0), exact_(Rational(0)) {}
  ExactReal(const Rational& exact)  // NOLINT: implicit on purpose, like Rational's
      : value_(exact.ToDouble()), exact_(exact) {}
  /// An approximate number.
  static ExactReal Approximate(double value);
  /// The exact value of a decimal number as a user writes it (1.5 -> 3/2, 0.25 -> 1/4): the
  /// shortest decimal with at most 15 significant digits that reads back as `value`;
  /// approximate when that needs more than 64 bits.
  static ExactReal FromDecimal(double value);

  double value() const { return value_; }
  const std::optional<Rational>& exact() const { return exact_; }
  bool is_exact() const { return exact_.has_value(); }
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
  ExactReal(double value, std::optional<Rational> exact) : value_(value), exact_(exact) {}
  double value_;
  std::optional<Rational> exact_;
};

}  // namespace mechanist
