#pragma once

#include <ostream>
#include <vector>

#include "kernel/assembly.h"
#include "kernel/diagnostic.h"

namespace mechanist {

/// Writes the `mechanist info` summary: units and tolerances, then per part its mesh source,
/// triangle count, world box (mm), ground flag and features with their world axes, then
/// drivers, adjustments, goals, steps, overrides and expectations. Lengths in mm, angles in
/// degrees. Deterministic: the same assembly always gives the same text.
void WriteInfo(const Assembly& assembly, std::ostream& out);

/// Writes diagnostics one per line: "severity code: message".
void WriteDiagnostics(const std::vector<Diagnostic>& diagnostics, std::ostream& out);

}  // namespace mechanist
