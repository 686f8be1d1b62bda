#pragma once

#include <filesystem>
#include <string>

#include "kernel/assembly/assembly.h"

namespace mechanist {

/// The text of `adjusted` as an assembly file to be written at `output`: the JSON of
/// `original`'s source file (its comments are not kept, its key order is) with, for every part
/// that moved, its "pose" replaced by {"position", "quaternion"} in the file's units and its
/// "place" removed; every feature that ApplyAdjustments tightened written `"fastening":
/// "tight"` (in a bolt's or setscrew's library parameters, or its feature entry); every
/// adjustment's "range" shifted by its solved value (ApplyAdjustments);
/// and relative "mesh" and "import" paths rewritten relative to `output`'s folder. Throws
/// InputError when the source cannot be read or parsed.
std::string AdjustedAssemblyText(const Assembly& original, const Assembly& adjusted,
                                 const std::filesystem::path& output);

}  // namespace mechanist
