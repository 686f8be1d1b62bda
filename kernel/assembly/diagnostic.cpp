#include "kernel/assembly/diagnostic.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
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

void SortDiagnosticRuns(std::vector<Diagnostic>* diagnostics,
                        const std::vector<std::size_t>& run_starts) {
  std::vector<Diagnostic>& d = *diagnostics;
  if ((run_starts.empty() ? !d.empty() : run_starts.front() != 0) ||
      !std::is_sorted(run_starts.begin(), run_starts.end()) ||
      (!run_starts.empty() && run_starts.back() > d.size())) {
    throw std::invalid_argument(fmt::format(
        "SortDiagnosticRuns: run starts must ascend from 0 within the {} diagnostics", d.size()));
  }
  const auto at = [&](std::size_t i) { return d.begin() + static_cast<std::ptrdiff_t>(i); };
  for (std::size_t r = 0; r < run_starts.size(); ++r) {
    const auto first = at(run_starts[r]);
    const auto last = r + 1 < run_starts.size() ? at(run_starts[r + 1]) : d.end();
    if (!std::is_sorted(first, last, DiagnosticLess)) std::sort(first, last, DiagnosticLess);
    std::inplace_merge(d.begin(), first, last, DiagnosticLess);
  }
}

}  // namespace mechanist
