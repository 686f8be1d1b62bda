#include "kernel/assembly/assembly.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string_view>
#include <unordered_map>
#include <utility>

namespace mechanist {

std::optional<std::size_t> Part::FindFeature(const std::string& feature_id) const {
  for (std::size_t i = 0; i < features.size(); ++i) {
    if (features[i].id == feature_id) return i;
  }
  return std::nullopt;
}

Assembly::Assembly(AssemblySpec spec) : spec_(std::move(spec)) {
  // FeatureRef holds 32-bit indices.
  if (spec_.parts.size() > UINT32_MAX) throw std::length_error("assembly: too many parts");
  std::unordered_map<const TriangleMesh*, Aabb> boxes;  // per distinct mesh
  for (std::size_t i = 0; i < spec_.parts.size(); ++i) {
    Part& part = spec_.parts[i];
    ground_.push_back(part.ground);
    compliant_.push_back(part.compliant);
    has_compliant_ = has_compliant_ || part.compliant;
    if (part.features.size() > UINT32_MAX) {
      throw std::length_error(fmt::format("part '{}' has too many features", part.id));
    }
    for (std::size_t f = 0; f < part.features.size(); ++f) {
      features_of_kind_[part.features[f].kind].push_back({i, f});
      feature_kind_.push_back(part.features[f].kind);
      feature_origin_.push_back(part.features[f].origin);
    }
    if (!part_index_.emplace(part.id, i).second) {
      throw std::invalid_argument(fmt::format("duplicate part id '{}'", part.id));
    }
    if (!part.mesh) {
      static const auto kNoMesh = std::make_shared<const TriangleMesh>();
      part.mesh = kNoMesh;  // a features-only part
    }
    file_poses_.push_back(part.X_WP);
    part_id_.push_back(AppendName({part.id}));
    for (const Feature& f : part.features)
      feature_name_.push_back(AppendName({part.id, "/", f.id}));
    const auto [box, added] = boxes.try_emplace(part.mesh.get());
    if (added) box->second = part.mesh->Bounds();
    mesh_box_.push_back(box->second);
    std::vector<std::uint32_t> by_id(part.features.size());
    std::iota(by_id.begin(), by_id.end(), 0);
    std::sort(by_id.begin(), by_id.end(), [&](std::uint32_t x, std::uint32_t y) {
      return part.features[x].id < part.features[y].id;
    });
    first_feature_.push_back(feature_rank_.size());
    feature_rank_.resize(feature_rank_.size() + by_id.size());
    for (std::uint32_t r = 0; r < by_id.size(); ++r) {
      if (r > 0 && part.features[by_id[r]].id == part.features[by_id[r - 1]].id) {
        throw std::invalid_argument(fmt::format("duplicate feature id '{}' in part '{}'",
                                                part.features[by_id[r]].id, part.id));
      }
      feature_rank_[first_feature_.back() + by_id[r]] = r;
    }
    for (const PlacementCondition& c : part.placement) {
      if (c.feature >= part.features.size()) {
        throw std::invalid_argument(
            fmt::format("placement of part '{}' names no feature", part.id));
      }
      CheckRef(c.target, "placement target");
    }
  }
  part_rank_.resize(spec_.parts.size());
  std::size_t rank = 0;
  for (const auto& [id, part] : part_index_) part_rank_[part] = rank++;
  // Features by name "id/feature": parts ordered as "id/" (ids hold no '/'), compared without
  // building the strings, then each part's features by id.
  std::vector<std::size_t> by_name(spec_.parts.size());
  std::iota(by_name.begin(), by_name.end(), std::size_t{0});
  std::sort(by_name.begin(), by_name.end(), [&](std::size_t x, std::size_t y) {
    const std::string_view a = spec_.parts[x].id, b = spec_.parts[y].id;
    const std::size_t n = std::min(a.size(), b.size());
    if (const int c = a.compare(0, n, b, 0, n); c != 0) return c < 0;
    const auto next = [n](std::string_view s) {
      return static_cast<unsigned char>(s.size() > n ? s[n] : '/');
    };
    return next(a) != next(b) ? next(a) < next(b) : a.size() < b.size();
  });
  feature_name_rank_.resize(feature_rank_.size());
  std::size_t offset = 0;
  for (std::size_t part : by_name) {
    const std::size_t count = spec_.parts[part].features.size();
    for (std::size_t f = 0; f < count; ++f) {
      feature_name_rank_[first_feature_[part] + f] =
          offset + feature_rank_[first_feature_[part] + f];
    }
    offset += count;
  }
  for (const Driver& d : spec_.drivers) {
    CheckRef(d.feature, "driver feature");
    if (d.relative_to) CheckPart(*d.relative_to, "driver relative_to");
  }
  for (const Adjustment& a : spec_.adjustments) {
    CheckPart(a.moves, "adjustment part");
    CheckRef(a.axis, "adjustment axis");
  }
  for (const Goal& g : spec_.goals) {
    for (FeatureRef f : g.features) CheckRef(f, "goal feature");
  }
  for (const AssemblyStep& s : spec_.steps) {
    CheckRef(s.insert, "step feature");
    CheckRef(s.into, "step target");
  }
  for (const PairOverride& o : spec_.overrides) {
    for (FeatureRef f : o.features) CheckRef(f, "override feature");
  }
  for (const Expectation& e : spec_.expectations) {
    if (e.part) CheckPart(*e.part, "expectation part");
    if (e.feature) CheckRef(*e.feature, "expectation feature");
    if (e.kind == Expectation::Kind::kPair) {
      for (FeatureRef f : e.pair) CheckRef(f, "expectation pair");
    }
    for (std::size_t p : e.parts) CheckPart(p, "expectation part");
  }
}

void Assembly::CheckPart(std::size_t part, const char* what) const {
  if (part >= spec_.parts.size()) {
    throw std::invalid_argument(fmt::format("{} refers to no part", what));
  }
}

void Assembly::CheckRef(FeatureRef ref, const char* what) const {
  CheckPart(ref.part, what);
  if (ref.feature >= spec_.parts[ref.part].features.size()) {
    throw std::invalid_argument(
        fmt::format("{} refers to no feature of part '{}'", what, spec_.parts[ref.part].id));
  }
}

std::optional<std::size_t> Assembly::FindPart(const std::string& id) const {
  const auto it = part_index_.find(id);
  if (it == part_index_.end()) return std::nullopt;
  return it->second;
}

std::optional<FeatureRef> Assembly::FindFeature(const std::string& path) const {
  const std::size_t slash = path.find('/');
  if (slash == std::string::npos) return std::nullopt;
  const auto part = FindPart(path.substr(0, slash));
  if (!part) return std::nullopt;
  const auto feature = spec_.parts[*part].FindFeature(path.substr(slash + 1));
  if (!feature) return std::nullopt;
  return FeatureRef{*part, *feature};
}

const std::vector<FeatureRef>& Assembly::FeaturesOfKind(FeatureKind kind) const {
  static const std::vector<FeatureRef> kNone;
  const auto it = features_of_kind_.find(kind);
  return it == features_of_kind_.end() ? kNone : it->second;
}

std::string Assembly::FeatureName(FeatureRef ref) const {
  if (ref.feature >= FeatureCount(ref.part)) {
    throw std::out_of_range(
        fmt::format("FeatureName: part {} has no feature {}", ref.part, ref.feature));
  }
  const NameSpan name = feature_name_[FeatureIndex(ref)];
  return names_.substr(name.offset, name.size);
}

std::string_view Assembly::PartId(std::size_t part) const {
  const NameSpan id = part_id_.at(part);
  return std::string_view(names_).substr(id.offset, id.size);
}

Assembly::NameSpan Assembly::AppendName(std::initializer_list<std::string_view> pieces) {
  std::size_t size = 0;
  for (std::string_view piece : pieces) size += piece.size();
  if (names_.size() + size > UINT32_MAX) {
    throw std::length_error("assembly: the part and feature names exceed 4 GB");
  }
  const NameSpan span{static_cast<std::uint32_t>(names_.size()), static_cast<std::uint32_t>(size)};
  for (std::string_view piece : pieces) names_.append(piece);
  return span;
}

std::size_t MainPart(const Assembly& assembly, std::span<const std::size_t> parts) {
  if (parts.empty()) throw std::logic_error("MainPart: no parts");
  std::size_t main = parts.front();
  double largest = -1.0;
  for (const std::size_t p : parts) {
    const Part& part = assembly.part(p);
    const double volume = part.HasGeometry() ? std::abs(part.mesh->SignedVolume()) : 0.0;
    if (volume > largest) {
      main = p;
      largest = volume;
    }
  }
  return main;
}

}  // namespace mechanist
