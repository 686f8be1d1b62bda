#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace mechanist {

enum class Severity { kInfo, kWarning, kError };

/// "info", "warning", "error".
std::string_view ToString(Severity severity);

/// A finding about the assembly, for the user: a stable machine-readable `code`
/// ("mesh_not_closed"), a sentence, and the parts and features ("part/feature") it concerns.
struct Diagnostic {
  Severity severity = Severity::kWarning;
  std::string code;
  std::string message;
  std::vector<std::string> parts;
  std::vector<std::string> features;
};

}  // namespace mechanist
