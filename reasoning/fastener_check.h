#pragma once

#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/diagnostic.h"
#include "reasoning/pair.h"

namespace mechanist {

/// The seeds' fastening semantics as checks on recognised pairs, at the file's poses:
/// - `bolt_too_short` (warning): a thread engages less of a through tapped hole (a nut) than
///   its length, or stops short of a collinear nut of its size within one nut length plus one
///   diameter; the message gives the shortfall in mm. Not for a tapped hole a heuristic
///   guessed (named by a `nut_on_bolt` or `screw_in_plain_hole` finding of the assembly).
/// - `nut_without_bolt` (warning): a part whose only feature besides faces is a through tapped
///   hole, with no thread in it.
/// - `loose_fastening_only` (warning): a part whose fastening pairs are all loose threads (it
///   can turn and travel on them).
/// Thread and hole size mismatches are recognition's near misses (`thread_mismatch`,
/// `hole_smaller_than_thread`).
std::vector<Diagnostic> CheckFasteners(const Assembly& assembly, const std::vector<Pair>& pairs);

}  // namespace mechanist
