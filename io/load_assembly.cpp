#include "io/load_assembly.h"

#include <optional>
#include <stdexcept>
#include <utility>

#include "io/assembly_reader.h"
#include "io/input_error.h"
#include "reasoning/fastener_inference.h"
#include "reasoning/feature_completion.h"
#include "reasoning/ground_choice.h"
#include "reasoning/implied_frame.h"
#include "reasoning/pin_ring_inference.h"
#include "reasoning/placement.h"

namespace mechanist {
namespace {

void Append(std::vector<Diagnostic> found, AssemblySpec* spec) {
  spec->findings.insert(spec->findings.end(), std::make_move_iterator(found.begin()),
                        std::make_move_iterator(found.end()));
}

Assembly Load(AssemblyFileReader reader, const std::string& file, const LoadOptions& options) {
  WrittenParts written = reader.ReadParts(options.reading);
  Append(CompleteFeatures(&written.spec.parts, written.origins), &written.spec);
  AssemblySpec spec = reader.ReadRelations(std::move(written.spec));
  try {
    ResolvePlacements(&spec);
  } catch (const PlacementError& e) {
    reader.FailAtPlacement(e.part(), e.what());
  }
  // The heuristic reinterprets only features the geometry gave, never written ones.
  const auto inferred = [&](std::size_t part, std::size_t feature) {
    return written.origins[part].Inferred(spec.parts[part], feature);
  };
  Append(InferNutsOnBolts(&spec.parts, spec.tolerance.length, spec.tolerance.angle, inferred),
         &spec);
  Append(
      InferScrewsInPlainHoles(&spec.parts, spec.tolerance.length, spec.tolerance.angle, inferred),
      &spec);
  Append(InferPinRingsOfParts(&spec.parts, spec.tolerance.length, spec.tolerance.angle, inferred),
         &spec);
  Append(ImplyGearFrame(&spec), &spec);
  Append(ChooseGround(&spec.parts), &spec);
  std::optional<Assembly> assembly;
  try {
    assembly.emplace(std::move(spec));
  } catch (const std::invalid_argument& e) {
    // The reader rejects everything Assembly checks; this is a last line of defence.
    throw InputError(file, "/", 0, 0, e.what());
  }
  if (!options.adjust) return std::move(*assembly);
  return Adjusted(*assembly, options.adjustments);
}

}  // namespace

Assembly LoadAssembly(const std::filesystem::path& file, const LoadOptions& options) {
  return Load(AssemblyFileReader::Open(file), file.string(), options);
}

Assembly LoadAssemblyText(std::string_view text, const std::filesystem::path& file,
                          const LoadOptions& options) {
  return Load(AssemblyFileReader(text, file), file.string(), options);
}

}  // namespace mechanist
