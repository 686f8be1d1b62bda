#pragma once

#include <filesystem>

#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

/// Reads a triangle mesh from an STL (ASCII or binary), OBJ, PLY (ASCII or binary
/// little/big endian) or OFF file, chosen by the extension (case-insensitive). Polygons with
/// more than three vertices are fanned into triangles; coordinates are returned as written
/// (the caller scales units). Tolerates CRLF line endings, comment and header lines, and
/// files whose declared counts are wrong where the data itself is unambiguous.
/// Throws InputError naming the file and the line (text formats) for unreadable or malformed
/// files: a missing file, a binary STL whose size does not match its triangle count, an index
/// out of range, a non-numeric coordinate, an unsupported extension.
TriangleMesh ReadMesh(const std::filesystem::path& path);

}  // namespace mechanist
