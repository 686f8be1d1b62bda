#pragma once

#include <cstddef>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/diagnostic.h"

namespace mechanist {

/// Checks of the description that need no reasoning, in part order:
/// - each part's mesh (features-only parts have none to check) (CheckMesh): `mesh_not_closed`,
///   `mesh_misoriented`, `mesh_inward`, `mesh_invalid` (warnings: analysis still runs, but
///   interference and gap results on such a part are unreliable); `mesh_non_manifold` (a
///   watertight mesh) and `mesh_degenerate_faces`, except on a STEP solid's tessellation
///   (Part::tessellated), where they are the mesher's and change nothing; for a STEP solid's
///   tessellation with gaps, `tessellation_open` (infos: nothing for the designer to do); each said
///   once for all the parts that have it alike;
/// - `feature_outside_part`: a feature origin farther than the part's box diagonal (at least
///   1 mm) outside the part's box, usually a unit or frame mistake (warning); features at
///   the edge of a part (the bore of a split bearing) are normal.
std::vector<Diagnostic> CheckAssembly(const Assembly& assembly);

/// The features-only parts (Part::HasGeometry false), ordered by part id: the commands that
/// need geometry (interference, assemble, sweep, gaps) skip them and say so.
std::vector<std::size_t> PartsWithoutGeometry(const Assembly& assembly);

}  // namespace mechanist
