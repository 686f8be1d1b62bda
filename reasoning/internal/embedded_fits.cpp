// Parts in no pair that are sunk into another part (FixEmbeddedParts): a connector modelled
// inside a motor's end cap, an insert, a part pressed or clipped in whose fastening the file
// leaves out. Real solids cannot overlap, so the overlap says where the part is held.

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "kernel/collision/collision_mesh_cache.h"
#include "kernel/collision/mesh_contact.h"
#include "reasoning/internal/recognizer.h"

namespace mechanist::internal {
namespace {

/// How deep a part goes into its host, and where.
struct Embedding {
  std::size_t host = 0;
  double depth = 0.0;  ///< mm; infinite when the part lies wholly inside the host
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
};

}  // namespace

void Recognizer::FixEmbeddedParts() {
  if (!assembly_.inference().embedded_parts) return;
  const std::size_t n = assembly_.parts().size();
  std::vector<bool> connected(n, false);
  for (const Pair& p : pairs_) connected[p.a.part] = connected[p.b.part] = true;
  auto rigid_solid = [&](std::size_t i) {
    const Part& part = assembly_.part(i);
    return part.HasGeometry() && !part.features.empty() && !assembly_.IsCompliant(i);
  };
  // The feature of part `i` whose origin is nearest p_W (the lowest index on ties).
  auto nearest_feature = [&](std::size_t i, const Eigen::Vector3d& p_W) {
    const std::vector<Feature>& features = assembly_.part(i).features;
    std::size_t best = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < features.size(); ++k) {
      const double distance = (X_WP_[i] * features[k].origin - p_W).norm();
      if (distance < best_distance) {
        best = k;
        best_distance = distance;
      }
    }
    return FeatureRef{i, best};
  };

  std::vector<std::size_t> unconnected;
  for (std::size_t i = 0; i < n; ++i) {
    if (!connected[i] && !assembly_.IsGround(i) && rigid_solid(i)) unconnected.push_back(i);
  }
  if (unconnected.empty()) return;

  CollisionMeshCache meshes;
  std::vector<Aabb> boxes_W(n);
  for (std::size_t i = 0; i < n; ++i) boxes_W[i] = TransformBox(X_WP_[i], assembly_.MeshBox(i));
  // Host part -> (embedded part, how deep), for one info per host.
  std::map<std::size_t, std::vector<std::pair<std::size_t, double>>> by_host;
  for (const std::size_t i : unconnected) {
    std::optional<Embedding> deepest;
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i || !rigid_solid(j) || !boxes_W[i].Intersects(boxes_W[j])) continue;
      const ContactMeasure contact =
          MeasureContact(meshes.Get(assembly_.part(i).mesh), X_WP_[i],
                         meshes.Get(assembly_.part(j).mesh), X_WP_[j], L_);
      if (contact.kind != ContactMeasure::Kind::kPenetrating) continue;
      // An open sheet has no inside: how deep it goes is unknown, so it says nothing of a seat.
      if (contact.open[0] || contact.open[1]) continue;
      // Part i wholly inside j; j wholly inside i is no seat for i.
      const double depth =
          contact.contained == 1 ? std::numeric_limits<double>::infinity() : contact.depth;
      if (contact.contained == 2 || !(depth > L_)) continue;
      if (!deepest || depth > deepest->depth) deepest = Embedding{j, depth, contact.p_W};
    }
    if (!deepest) continue;
    Pair fixed;
    fixed.type = PairType::kFixed;
    fixed.dof = 0;
    fixed.source = PairSource::kEmbedded;
    fixed.a = nearest_feature(i, deepest->p_W);
    fixed.b = nearest_feature(deepest->host, deepest->p_W);
    pairs_.push_back(fixed);
    by_host[deepest->host].emplace_back(i, deepest->depth);
  }

  for (const auto& [host, embedded] : by_host) {
    std::vector<std::string> names;
    double depth = 0.0;
    for (const auto& [part, d] : embedded) {
      names.emplace_back(assembly_.PartId(part));
      depth = std::max(depth, d);
    }
    std::sort(names.begin(), names.end());
    const bool one = names.size() == 1;
    const std::string where =
        std::isinf(depth) ? std::string(one ? "lies inside" : "lie in")
                          : fmt::format("{} {} deep in", one ? "lies" : "lie up to", Mm(depth));
    std::string message = fmt::format(
        "{} '{}' {} in no pair but {} '{}': taken as fixed to it (sunk in, as an insert or a "
        "part pressed or clipped in whose fastening the file leaves out; solids cannot "
        "overlap, so check the model if {} not meant to; \"infer\": {{\"embedded_parts\": "
        "false}} turns this off)",
        one ? "part" : "parts", fmt::join(names, "', '"), one ? "is" : "are", where,
        assembly_.PartId(host), one ? "it is" : "they are");
    names.emplace_back(assembly_.PartId(host));
    diagnostics_.push_back({Severity::kInfo, "embedded", std::move(message), std::move(names), {}});
  }
}

}  // namespace mechanist::internal
