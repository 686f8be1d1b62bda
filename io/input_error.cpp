#include "io/input_error.h"

#include <fmt/format.h>

#include <iterator>
#include <utility>

namespace mechanist {
namespace {

std::string Format(const std::string& file, const std::string& pointer, int line, int column,
                   const std::string& message) {
  std::string text = file;
  auto out = std::back_inserter(text);
  if (line > 0) {
    fmt::format_to(out, ":{}", line);
    if (column > 0) fmt::format_to(out, ":{}", column);
  }
  text += ": ";
  if (!pointer.empty()) fmt::format_to(out, "at {}: ", pointer);
  text += message;
  return text;
}

}  // namespace

InputError::InputError(std::string file, std::string pointer, int line, int column,
                       std::string message)
    : std::runtime_error(Format(file, pointer, line, column, message)),
      file_(std::move(file)),
      pointer_(std::move(pointer)),
      line_(line),
      column_(column),
      detail_(std::move(message)) {}

}  // namespace mechanist
