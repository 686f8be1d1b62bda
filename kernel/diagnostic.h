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

/// The report order of diagnostics: by code, then features, parts and message. It depends on
/// names only, so reordering the input file does not reorder the report.
bool DiagnosticLess(const Diagnostic& x, const Diagnostic& y);

}  // namespace mechanist
