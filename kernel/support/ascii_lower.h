#pragma once

#include <cctype>
#include <string>
#include <string_view>

namespace mechanist {

/// `text` with its ASCII letters in lower case (file extensions, ids compared in any case);
/// other bytes as they are.
inline std::string AsciiLower(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower;
}

}  // namespace mechanist
