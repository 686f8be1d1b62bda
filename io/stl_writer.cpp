#include "io/stl_writer.h"

#include <cstdint>
#include <cstring>

namespace mechanist {
namespace {

void Put(std::string& out, const void* data, std::size_t size) {
  out.append(static_cast<const char*>(data), size);
}

void PutVector(std::string& out, const Eigen::Vector3d& v) {
  const float xyz[3] = {static_cast<float>(v.x()), static_cast<float>(v.y()),
                        static_cast<float>(v.z())};
  Put(out, xyz, sizeof xyz);  // little-endian on every machine we build for (x86-64, arm64)
}

}  // namespace

std::string BinaryStl(const TriangleMesh& mesh, double scale) {
  std::string out;
  out.reserve(84 + 50 * mesh.faces.size());
  char header[80] = {};
  std::strncpy(header, "binary STL written by mechanist", sizeof header - 1);
  Put(out, header, sizeof header);
  const auto count = static_cast<std::uint32_t>(mesh.faces.size());
  Put(out, &count, sizeof count);
  for (const TriangleMesh::Face& f : mesh.faces) {
    const Eigen::Vector3d a = scale * mesh.vertices[f[0]];
    const Eigen::Vector3d b = scale * mesh.vertices[f[1]];
    const Eigen::Vector3d c = scale * mesh.vertices[f[2]];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    PutVector(out, n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero());
    PutVector(out, a);
    PutVector(out, b);
    PutVector(out, c);
    const std::uint16_t attributes = 0;
    Put(out, &attributes, sizeof attributes);
  }
  return out;
}

}  // namespace mechanist
