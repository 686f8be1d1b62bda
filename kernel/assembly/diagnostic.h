#pragma once

#include <cstddef>
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

/// Puts `diagnostics` in DiagnosticLess order, given as runs that start at `run_starts`
/// (ascending; the first run starts at 0): a run out of order is sorted, then the runs are
/// merged. The findings of one source usually come in order already (the motion analysis
/// names pairs in pair order), so tens of thousands of them cost a linear pass where one sort
/// of the whole would compare their strings n log n times. Throws std::invalid_argument unless
/// `run_starts` ascends from 0 within the diagnostics (or is empty with them).
void SortDiagnosticRuns(std::vector<Diagnostic>* diagnostics,
                        const std::vector<std::size_t>& run_starts);

}  // namespace mechanist
