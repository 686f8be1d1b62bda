#pragma once
// Open CASCADE's STEP work library with mechanist's Part 21 scanner (part21_records.h) in
// place of its flex and bison parser. It has Open CASCADE's types: included by the facade's
// sources (io/occt) and by the tests' and benchmarks' Open CASCADE units, nowhere else.
#include <StepSelect_WorkLibrary.hxx>

namespace mechanist {

/// Reads a STEP file into a StepData_StepModel as StepFile_Read does: the same records and
/// models, the same reports of faults (its messages of information gravity and above; not its
/// progress traces), about four times as fast (0.09 against 0.36 s on a 4 MB export). A file
/// outside the scanner's subset, not a regular file or one of 4 GiB or more, is read by the
/// base class (Open CASCADE's own parser), whose messages then name what is wrong. Install it
/// with `reader.WS()->SetLibrary(new Part21WorkLibrary)` before ReadFile.
class Part21WorkLibrary : public StepSelect_WorkLibrary {
 public:
  Part21WorkLibrary();
  /// Returns 0 when the file was read (`model` is then set), as the base class does: -1 when
  /// it cannot be opened, 1 on a syntax error.
  Standard_Integer ReadFile(Standard_CString name, Handle(Interface_InterfaceModel) & model,
                            const Handle(Interface_Protocol) & protocol) const override;
};

}  // namespace mechanist
