#include "viz/gltf_writer.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include "viz/display_colors.h"
#include "viz/feature_lines.h"

namespace mechanist {
namespace {

// The file is little-endian and the buffer holds values as they lie in memory.
static_assert(std::endian::native == std::endian::little);

using nlohmann::json;

constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kLines = 1;  // primitive modes
constexpr int kTriangles = 4;

// The binary chunk and the JSON that describes it.
class GltfBuilder {
 public:
  json doc = json::object();
  std::string bin;

  // A buffer view over `bytes`, started on a 4-byte boundary (the alignment of every
  // component type used here).
  int AddView(const void* bytes, std::size_t size, int target) {
    bin.append((4 - bin.size() % 4) % 4, '\0');
    json view = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", size}};
    if (target != 0) view["target"] = target;
    bin.append(static_cast<const char*>(bytes), size);
    doc["bufferViews"].push_back(view);
    return static_cast<int>(doc["bufferViews"].size()) - 1;
  }

  int AddFloats(const std::vector<float>& values, int components, const char* type, int target,
                bool bounds) {
    const int view = AddView(values.data(), values.size() * sizeof(float), target);
    const std::size_t count = values.size() / components;
    json accessor = {
        {"bufferView", view}, {"componentType", kFloat}, {"count", count}, {"type", type}};
    if (bounds) {  // required for positions and animation inputs
      std::vector<float> lo(values.begin(), values.begin() + components);
      std::vector<float> hi = lo;
      for (std::size_t i = 0; i < values.size(); ++i) {
        const std::size_t c = i % components;
        lo[c] = std::min(lo[c], values[i]);
        hi[c] = std::max(hi[c], values[i]);
      }
      accessor["min"] = lo;
      accessor["max"] = hi;
    }
    doc["accessors"].push_back(accessor);
    return static_cast<int>(doc["accessors"].size()) - 1;
  }

  int AddIndices(const std::vector<std::uint32_t>& indices) {
    const int view =
        AddView(indices.data(), indices.size() * sizeof(std::uint32_t), kElementArrayBuffer);
    doc["accessors"].push_back({{"bufferView", view},
                                {"componentType", kUnsignedInt},
                                {"count", indices.size()},
                                {"type", "SCALAR"}});
    return static_cast<int>(doc["accessors"].size()) - 1;
  }

  int AddMesh(const TriangleMesh& mesh, int material, const std::string& name) {
    std::vector<float> positions;
    positions.reserve(3 * mesh.vertices.size());
    for (const Eigen::Vector3d& v : mesh.vertices) {
      for (int i = 0; i < 3; ++i) positions.push_back(static_cast<float>(v[i]));
    }
    std::vector<std::uint32_t> indices;
    indices.reserve(3 * mesh.faces.size());
    for (const TriangleMesh::Face& f : mesh.faces) {
      for (const std::int32_t i : f) indices.push_back(static_cast<std::uint32_t>(i));
    }
    return AddPrimitive(positions, indices, material, name, kTriangles);
  }

  // Line segments (mode LINES) along each polyline of `lines`.
  int AddLines(const std::vector<std::vector<Eigen::Vector3d>>& lines, int material,
               const std::string& name) {
    std::vector<float> positions;
    std::vector<std::uint32_t> indices;
    for (const std::vector<Eigen::Vector3d>& line : lines) {
      const auto first = static_cast<std::uint32_t>(positions.size() / 3);
      for (const Eigen::Vector3d& v : line) {
        for (int i = 0; i < 3; ++i) positions.push_back(static_cast<float>(v[i]));
      }
      for (std::uint32_t k = 1; k < line.size(); ++k) {
        indices.insert(indices.end(), {first + k - 1, first + k});
      }
    }
    return AddPrimitive(positions, indices, material, name, kLines);
  }

  // A mesh of one primitive of `mode` over `positions` (x, y, z in turn) and `indices`.
  int AddPrimitive(const std::vector<float>& positions, const std::vector<std::uint32_t>& indices,
                   int material, const std::string& name, int mode) {
    const int position = AddFloats(positions, 3, "VEC3", kArrayBuffer, true);
    const int index = AddIndices(indices);
    doc["meshes"].push_back({{"name", name},
                             {"primitives", json::array({{{"attributes", {{"POSITION", position}}},
                                                          {"indices", index},
                                                          {"material", material},
                                                          {"mode", mode}}})}});
    return static_cast<int>(doc["meshes"].size()) - 1;
  }

  int AddMaterial(const Eigen::Vector3d& rgb, double alpha) {
    json material = {{"pbrMetallicRoughness",
                      {{"baseColorFactor", {rgb.x(), rgb.y(), rgb.z(), alpha}},
                       {"metallicFactor", 0.0},
                       {"roughnessFactor", 0.6}}}};
    if (alpha < 1.0) {
      material["alphaMode"] = "BLEND";
      material["doubleSided"] = true;
    }
    doc["materials"].push_back(material);
    return static_cast<int>(doc["materials"].size()) - 1;
  }

  // The GLB container: a 12-byte header, the JSON chunk padded with spaces, the binary chunk
  // padded with zeros.
  std::string Glb() {
    doc["buffers"] = json::array({{{"byteLength", bin.size()}}});
    std::string text = doc.dump();
    text.append((4 - text.size() % 4) % 4, ' ');
    bin.append((4 - bin.size() % 4) % 4, '\0');
    std::string out;
    auto word = [&out](std::uint32_t w) { out.append(reinterpret_cast<const char*>(&w), 4); };
    word(0x46546C67);  // "glTF"
    word(2);
    word(static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
    word(static_cast<std::uint32_t>(text.size()));
    word(0x4E4F534A);  // "JSON"
    out += text;
    word(static_cast<std::uint32_t>(bin.size()));
    word(0x004E4942);  // "BIN\0"
    out += bin;
    return out;
  }
};

std::vector<double> Quaternion(const RigidTransform& X) {
  const Eigen::Quaterniond q(X.rotation());
  return {q.x(), q.y(), q.z(), q.w()};
}

std::vector<double> Translation(const RigidTransform& X) {
  return {X.translation().x(), X.translation().y(), X.translation().z()};
}

}  // namespace

std::string GlbAnimation(const Assembly& assembly, const Analysis& analysis,
                         const Animation& animation, double fps,
                         const TriangleMesh* gap_surface_W) {
  if (!(fps > 0.0)) throw std::invalid_argument("GlbAnimation: fps must be positive");
  GltfBuilder b;
  b.doc["asset"] = {{"version", "2.0"}, {"generator", "mechanist"}};
  const std::size_t n = assembly.parts().size();
  const std::size_t frames = animation.frame_count();

  const DisplayColors colors = ColorParts(analysis);
  std::map<std::pair<double, std::pair<double, double>>, int> material_of_color;
  std::map<std::pair<const TriangleMesh*, int>, int> mesh_of;
  json root = {{"name", assembly.name().empty() ? "assembly" : assembly.name()},
               // -90 degrees about x takes z up to y up; mm to m.
               {"rotation", {-std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)}},
               {"scale", {1e-3, 1e-3, 1e-3}},
               {"children", json::array()}};
  b.doc["nodes"].push_back(root);
  for (std::size_t p = 0; p < n; ++p) {
    const Part& part = assembly.part(p);
    bool clash = false;
    for (std::size_t k = 0; k < frames; ++k) clash = clash || animation.InClash(p, k);
    const Eigen::Vector3d rgb = clash ? ClashColor() : colors.part[p];
    const auto key = std::make_pair(rgb.x(), std::make_pair(rgb.y(), rgb.z()));
    json node = {{"name", part.id}};
    const auto material_of = [&] {
      auto material = material_of_color.find(key);
      if (material == material_of_color.end()) {
        material = material_of_color.emplace(key, b.AddMaterial(rgb, 1.0)).first;
      }
      return material;
    };
    if (!part.HasGeometry() && !part.features.empty()) {
      // A features-only part is drawn by its feature lines.
      node["mesh"] = b.AddLines(FeatureLines(part, true), material_of()->second,
                                fmt::format("{} features", part.id));
    } else if (part.HasGeometry()) {
      const auto material = material_of();
      auto mesh = mesh_of.find({part.mesh.get(), material->second});
      if (mesh == mesh_of.end()) {
        mesh = mesh_of
                   .emplace(std::make_pair(part.mesh.get(), material->second),
                            b.AddMesh(*part.mesh, material->second, part.mesh_source))
                   .first;
      }
      node["mesh"] = mesh->second;
    }
    const RigidTransform& X_WP = frames > 0 ? animation.states[0].X_WP[p] : part.X_WP;
    node["translation"] = Translation(X_WP);
    node["rotation"] = Quaternion(X_WP);
    b.doc["nodes"].push_back(node);
    b.doc["nodes"][0]["children"].push_back(p + 1);
  }
  if (gap_surface_W && !gap_surface_W->faces.empty()) {
    const int material = b.AddMaterial(GapColor(), 0.45);
    b.doc["nodes"].push_back(
        {{"name", "gaps"}, {"mesh", b.AddMesh(*gap_surface_W, material, "gaps")}});
    b.doc["nodes"][0]["children"].push_back(n + 1);
  }
  b.doc["scene"] = 0;
  b.doc["scenes"] = json::array({{{"nodes", {0}}}});

  // Keys: one per frame, for the parts that move.
  std::vector<float> times(frames);
  for (std::size_t k = 0; k < frames; ++k) times[k] = static_cast<float>(k / fps);
  json samplers = json::array(), channels = json::array();
  int input = -1;
  for (std::size_t p = 0; p < n && frames > 0; ++p) {
    if (animation.run.paths[p].still()) continue;
    if (input < 0) input = b.AddFloats(times, 1, "SCALAR", 0, true);
    std::vector<float> translation, rotation;
    Eigen::Quaterniond previous = Eigen::Quaterniond::Identity();
    for (std::size_t k = 0; k < frames; ++k) {
      const RigidTransform& X_WP = animation.states[k].X_WP[p];
      for (int i = 0; i < 3; ++i) translation.push_back(static_cast<float>(X_WP.translation()[i]));
      Eigen::Quaterniond q(X_WP.rotation());
      // q and -q are one rotation; keep consecutive keys on one side so that the
      // interpolation does not go the long way round.
      if (k > 0 && q.dot(previous) < 0.0) q.coeffs() = -q.coeffs();
      previous = q;
      for (int i = 0; i < 4; ++i) rotation.push_back(static_cast<float>(q.coeffs()[i]));
    }
    const int node = static_cast<int>(p + 1);
    for (const auto& [path, values, type] :
         {std::tuple<const char*, const std::vector<float>*, const char*>{"translation",
                                                                          &translation, "VEC3"},
          {"rotation", &rotation, "VEC4"}}) {
      const int output = b.AddFloats(*values, type[3] - '0', type, 0, false);
      samplers.push_back({{"input", input}, {"output", output}, {"interpolation", "LINEAR"}});
      channels.push_back(
          {{"sampler", samplers.size() - 1}, {"target", {{"node", node}, {"path", path}}}});
    }
  }
  if (!channels.empty()) {
    b.doc["animations"] =
        json::array({{{"name", "run"}, {"samplers", samplers}, {"channels", channels}}});
  }
  return b.Glb();
}

}  // namespace mechanist
