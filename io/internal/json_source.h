#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <unordered_map>

namespace mechanist::internal {

/// Line and column (1-based) where a JSON value starts in its file.
struct JsonPosition {
  int line = 0;
  int column = 0;
};

/// A parsed JSON document with the position of every value, keyed by JSON pointer
/// (RFC 6901, "" for the root), so that errors about a value can name its line and column.
struct JsonSource {
  std::string file;
  nlohmann::ordered_json root;
  std::unordered_map<std::string, JsonPosition> positions;

  /// Position of the value at `pointer`, or of its nearest ancestor that has one.
  JsonPosition PositionOf(const std::string& pointer) const;
};

/// Parses JSON text with `//` and `/* */` comments. Throws InputError (naming `file`, line and
/// column) on a syntax error or a duplicate key in an object.
JsonSource ParseJson(std::string_view text, const std::string& file);

/// Appends a key or index to a JSON pointer, escaping '~' and '/'.
std::string JoinPointer(const std::string& pointer, std::string_view token);

}  // namespace mechanist::internal
