#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "kernel/assembly/assembly.h"

namespace mechanist {

/// Reads an assembly file in the format of spec/assembly-format.md (version 1): JSON with
/// comments. Lengths are converted to millimetres and angles to radians; mesh paths are
/// relative to the file's folder; a mesh file used by several parts is read once.
/// Throws InputError naming the file, the JSON pointer, line and column, what was expected
/// and what was found: for syntax errors, unknown keys (except under "extra"), wrong types,
/// missing required values, non-positive sizes, zero axes, improper rotations, duplicate ids,
/// dangling references and unreadable or malformed meshes. Never modifies the file.
Assembly ReadAssembly(const std::filesystem::path& file);

/// As ReadAssembly, for `text` that stands for the file `file` (used to resolve mesh paths
/// and in messages).
Assembly ParseAssembly(std::string_view text, const std::filesystem::path& file);

/// An expectation's ratio written as text: an integer or "p/q" (exact, reduced) or a decimal;
/// nothing for anything else or a zero denominator.
std::optional<ExpectedRatio> ParseRatio(const std::string& text);

}  // namespace mechanist
