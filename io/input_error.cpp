#include "io/input_error.h"

#include <utility>

namespace mechanist {
namespace {

std::string Format(const std::string& file, const std::string& pointer, int line, int column,
                   const std::string& message) {
  std::string text = file;
  if (line > 0) {
    text += ":" + std::to_string(line);
    if (column > 0) text += ":" + std::to_string(column);
  }
  text += ": ";
  if (!pointer.empty()) text += "at " + pointer + ": ";
  return text + message;
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
