#include "kernel/diagnostic.h"

#include <tuple>

namespace mechanist {

std::string_view ToString(Severity severity) {
  switch (severity) {
    case Severity::kInfo:
      return "info";
    case Severity::kWarning:
      return "warning";
    case Severity::kError:
      return "error";
  }
  return "?";
}

bool DiagnosticLess(const Diagnostic& x, const Diagnostic& y) {
  return std::tie(x.code, x.features, x.parts, x.message) <
         std::tie(y.code, y.features, y.parts, y.message);
}

}  // namespace mechanist
