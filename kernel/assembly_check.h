#pragma once

#include <vector>

#include "kernel/assembly.h"
#include "kernel/diagnostic.h"

namespace mechanist {

/// Checks of the description that need no reasoning, in part order:
/// - each part's mesh (CheckMesh): `mesh_not_closed`, `mesh_misoriented`, `mesh_inward`,
///   `mesh_degenerate_faces`, `mesh_invalid` (warnings: analysis still runs, but
///   interference and gap results on such a part are unreliable);
/// - `feature_outside_part`: a feature origin farther than the part's box diagonal (at least
///   1 mm) outside the part's box, usually a unit or frame mistake (warning); features at
///   the edge of a part (the bore of a split bearing) are normal.
std::vector<Diagnostic> CheckAssembly(const Assembly& assembly);

}  // namespace mechanist
