#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>

namespace mechanist::internal {

/// `text` with &, <, >, " and ' replaced by XML entities, for attribute values and comments.
std::string XmlEscape(std::string_view text);

/// "<!-- text -->" with `text` escaped and every "--" (not allowed in a comment) spaced out.
std::string XmlComment(std::string_view text);

/// `value` with 12 significant digits (%.12g), "-0" and magnitudes below 1e-15 as "0":
/// simulator files must be identical across runs and free of round-off noise.
std::string Number(double value);

/// "x y z" of Number.
std::string Numbers(const Eigen::Vector3d& v);

}  // namespace mechanist::internal
