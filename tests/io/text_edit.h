#pragma once

// Test helpers: read an example's text and put a design mistake into it.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace mechanist::testing {

inline std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// `text` with the first `from` replaced by `to`; a test failure when `from` is missing.
inline std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

}  // namespace mechanist::testing
