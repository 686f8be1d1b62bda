#pragma once

#include <string>

#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

/// The bytes of a binary STL file of `mesh` with every coordinate multiplied by `scale` (1e-3
/// writes a mesh in mm as metres), facet normals from the vertices' winding; the 80-byte
/// header names mechanist.
std::string BinaryStl(const TriangleMesh& mesh, double scale = 1.0);

}  // namespace mechanist
