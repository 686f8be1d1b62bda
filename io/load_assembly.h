#pragma once

#include <filesystem>
#include <string_view>

#include "io/step_reader.h"
#include "kernel/assembly/assembly.h"
#include "reasoning/adjustment.h"

namespace mechanist {

/// How far LoadAssembly goes.
struct LoadOptions {
  /// Solve the file's adjustments for its goals and lock them, the loose fastenings that
  /// allowed them taken as tightened (spec: "once solved, an adjustment is locked"), as the
  /// designer does on the bench. Off: the parts stay at the file's poses.
  bool adjust = false;
  /// Receives the solve when `adjust` is set and the file declares adjustments and goals.
  AdjustmentSummary* adjustments = nullptr;
  /// Follows the reading of each STEP file (AssemblyFileReader::ReadParts).
  StepFileProgress reading = {};
};

/// The one path from an assembly file (or a STEP assembly alone) to the assembly every
/// command and mechanist::testing work on:
/// 1. read (AssemblyFileReader): the settings and the parts as written;
/// 2. recognise the features the file does not write (CompleteFeatures);
/// 3. read the relations (placements, drivers, ..., expectations) against those features;
/// 4. place the parts placed by features (ResolvePlacements);
/// 5. infer fasteners among the parts whose features were not written: nuts on bolts
///    (InferNutsOnBolts), then screws in plain holes (InferScrewsInPlainHoles), after placing
///    because they need the parts' poses;
/// 6. choose a ground part when the file fixes none (ChooseGround);
/// 7. adjust, when `options.adjust` says so (Adjusted).
/// What steps 2, 5, 6 and 7 did is in Assembly::findings (`features_recognised`,
/// `tessellation_gears`, `nut_on_bolt`, `screw_in_plain_hole`, `ground_chosen`,
/// `adjustment_locked`), after the reader's own (`step_reader`). Throws InputError as
/// AssemblyFileReader does, and for placements that cannot be solved (at the part's `place`).
/// Never modifies the file.
Assembly LoadAssembly(const std::filesystem::path& file, const LoadOptions& options = {});

/// As LoadAssembly, for `text` that stands for the file `file` (mesh paths and messages).
Assembly LoadAssemblyText(std::string_view text, const std::filesystem::path& file,
                          const LoadOptions& options = {});

}  // namespace mechanist
