#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/diagnostic.h"

namespace mechanist {

/// Writes the `mechanist info` summary: units (the length units a STEP file declares, for one
/// read alone or each one an assembly file reads) and tolerances, then per part its mesh source,
/// triangle count, world box (mm), ground flag and features with their world axes, then
/// drivers, adjustments, goals, steps, overrides and expectations. Lengths in mm, angles in
/// degrees. Deterministic: the same assembly always gives the same text.
void WriteInfo(const Assembly& assembly, std::ostream& out);

/// One feature as `info` lists it: "id: kind at (origin) axis (direction)" and its parameters,
/// in the world for the part pose X_WP (mm).
std::string DescribeFeature(const Feature& f, const RigidTransform& X_WP);

/// Writes diagnostics one per line: "severity code: message".
void WriteDiagnostics(const std::vector<Diagnostic>& diagnostics, std::ostream& out);

}  // namespace mechanist
