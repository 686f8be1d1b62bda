#pragma once
// A STEP file's text (ISO 10303-21 exchange structure) as the records Open CASCADE's own
// parser (StepFile_Read, flex and bison) hands to StepData_StepReaderData, read by a
// hand-written scanner (a 4 MB export in 0.01 s; the whole model then loads about four times
// as fast as through StepFile_Read, bench/part21_bench). It reads the subset real CAD exports use
// and gives up (nullopt) on anything else, so that the caller can leave such a file, and its error
// messages, to Open CASCADE's parser. No Open CASCADE types here: the scanner is tested and
// fuzzed on its own.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mechanist {

/// The records of a Part 21 file in Open CASCADE's encoding (StepFile_ReadData):
/// - the header's entities, then the data section's, in file order;
/// - a complex entity `#7=(A(..)B(..))` is a chain of records, the first with ident `#7`, the
///   others without an ident;
/// - each nested list is a record of its own, ident `$n`, placed before the record that holds
///   it (the lists close in that order); n counts the lists of one entity (or one part of a
///   complex entity) in the order they open, from 1. The list's type is that of a typed
///   parameter (`LENGTH_MEASURE(2.)`), or none. The holding record has a parameter of kind
///   `kSub` naming `$n`.
/// Texts are spans of the file's text, without a terminating NUL.
struct Part21Records {
  /// [begin, begin + size) of the file's text.
  struct Span {
    std::uint32_t begin = 0;
    std::uint32_t size = 0;
  };
  /// The parameter kinds of Open CASCADE's scanner (Interface_ParamType).
  enum class Kind : std::uint8_t {
    kInteger,
    kReal,
    kIdent,
    kVoid,
    kText,
    kEnum,
    kHexa,
    kMisc,
    kSub
  };
  /// A parameter: its kind and its text, or the nested list it names.
  struct Param {
    Kind kind = Kind::kMisc;
    Span text;    // all kinds but kSub
    int sub = 0;  // kSub: the nested list `$sub`
  };
  /// An entity, a part of a complex entity, or a nested list, with its parameters.
  struct Record {
    Span ident;   // `#7`; empty for a header entity and a complex entity's further parts
    int sub = 0;  // > 0: a nested list, ident `$sub`
    Span type;    // empty for an untyped nested list
    std::uint32_t first = 0;  // its parameters: params[first, first + count)
    std::uint32_t count = 0;
  };
  std::size_t header_records = 0;  // records[0, header_records) are the header's
  std::vector<Record> records;
  std::vector<Param> params;
  int max_sub = 0;  // the largest `$n` used
};

/// The records of `text`, a whole STEP file; nullopt when it is not in the subset read here:
/// anything malformed, an empty data section, scopes, user-defined types (`!NAME`), a second data
/// section, texts with an apostrophe inside other than doubled, numbers Open CASCADE's scanner
/// splits (`1E5`), lists nested more than 64 deep, control characters outside texts, files of 4 GiB
/// and more. For every text it reads, Open CASCADE's scanner ends each token where this one does
/// (checked by tests against StepFile_Read on real exports).
std::optional<Part21Records> ReadPart21Records(std::string_view text);

/// A reference in a data section to an entity that it does not define.
struct Part21UndefinedReference {
  std::string entity;   ///< `#10`: the entity whose parameters hold it (also in a nested list or a
                        ///< further part of a complex entity)
  std::string type;     ///< the entity's type (a complex entity's first part's)
  std::string missing;  ///< `#13912`
};

/// The references of `records` (ReadPart21Records of `text`) to entities that its data section
/// does not define, in file order: what a file cut short, or damaged, lacks.
std::vector<Part21UndefinedReference> UndefinedReferences(const Part21Records& records,
                                                          std::string_view text);

}  // namespace mechanist
