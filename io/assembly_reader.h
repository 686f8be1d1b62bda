#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/step_reader.h"
#include "kernel/assembly/assembly.h"
#include "reasoning/feature_completion.h"

namespace mechanist {

/// The settings and parts of an assembly file as written, before the reasoning layer
/// completes them.
struct WrittenParts {
  /// Units, tolerance, friction, name and the parts: meshes read (a STEP solid triangulated,
  /// with the features of its exact faces), written features, poses; placements unsolved.
  AssemblySpec spec;
  std::vector<PartOrigin> origins;  ///< per part: where its features come from
};

/// Reads an assembly file in the format of spec/assembly-format.md (version 1: JSON with
/// comments), or a STEP assembly alone (as a file that imports it and adds nothing). Reading
/// only reads; LoadAssembly (io/load_assembly.h) runs the whole pipeline. It reads in two
/// steps so that the reasoning layer can complete the parts between them: ReadParts, then
/// ReadRelations, whose feature references ("part/feature") may name features recognised in
/// between. Lengths are converted to millimetres and angles to radians; mesh paths are
/// relative to the file's folder; a mesh file used by several parts is read once.
/// Every step throws InputError naming the file, the JSON pointer, line and column, what was
/// expected and what was found: for syntax errors, unknown keys (except under "extra"), wrong
/// types, missing required values, non-positive sizes, zero axes, improper rotations,
/// duplicate ids, dangling references, cycles of placements and unreadable or malformed
/// meshes (for a STEP file alone: the STEP file, without a line). Never modifies the file.
class AssemblyFileReader {
 public:
  /// Reads and parses `file`.
  static AssemblyFileReader Open(const std::filesystem::path& file);
  /// Parses `text`, which stands for the file `file` (mesh paths and messages).
  AssemblyFileReader(std::string_view text, const std::filesystem::path& file);
  AssemblyFileReader(AssemblyFileReader&&) noexcept;
  AssemblyFileReader& operator=(AssemblyFileReader&&) noexcept;
  ~AssemblyFileReader();

  /// The settings and the parts as written (imported STEP solids, the file's own parts);
  /// `progress` (when given) follows the reading of each STEP file.
  WrittenParts ReadParts(const StepFileProgress& progress = {});
  /// Adds to `spec` (the parts ReadParts gave, completed) the placement conditions, drivers,
  /// adjustments, goals, steps, overrides and expectations.
  AssemblySpec ReadRelations(AssemblySpec spec);
  /// Throws the InputError for a placement of `part` that cannot be solved, at its `place`.
  [[noreturn]] void FailAtPlacement(std::size_t part, const std::string& message) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// An expectation's ratio written as text: an integer or "p/q" (exact, reduced) or a decimal;
/// nothing for anything else or a zero denominator.
std::optional<ExpectedRatio> ParseRatio(const std::string& text);

}  // namespace mechanist
