#pragma once

#include <stdexcept>
#include <string>

namespace mechanist {

/// Bad user input: names the file, the JSON pointer (empty for non-JSON files), the line and
/// column where known (0 when not), and what was expected and found. The CLI exits with 2.
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string pointer, int line, int column, std::string message);

  const std::string& file() const { return file_; }
  const std::string& pointer() const { return pointer_; }
  int line() const { return line_; }
  int column() const { return column_; }
  /// The message without the location.
  const std::string& detail() const { return detail_; }

 private:
  std::string file_, pointer_;
  int line_, column_;
  std::string detail_;
};

}  // namespace mechanist
