#pragma once
// Open CASCADE's STEP work library with mechanist's Part 21 scanner (part21_records.h) in
// place of its flex and bison parser. Included only by the Open CASCADE facade's sources.
#include <StepSelect_WorkLibrary.hxx>

namespace mechanist {

/// Reads a STEP file into a StepData_StepModel as StepFile_Read does: the same records, the
/// same models (entities, checks and messages), about 0.2 s sooner on a 4 MB export. A file
/// outside the scanner's subset, or one whose records Open CASCADE finds faulty, is read by
/// the base class (Open CASCADE's own parser), so that its messages name what is wrong.
/// Install it with `reader.WS()->SetLibrary(new Part21WorkLibrary)` before ReadFile.
class Part21WorkLibrary : public StepSelect_WorkLibrary {
 public:
  /// Returns 0 when the file was read (`model` is then set), as the base class does: -1 when
  /// it cannot be opened, 1 on a syntax error.
  Standard_Integer ReadFile(Standard_CString name, Handle(Interface_InterfaceModel) & model,
                            const Handle(Interface_Protocol) & protocol) const override;
};

}  // namespace mechanist
