#include "reasoning/interference.h"

#include <algorithm>
#include <cmath>

#include "kernel/collision/broad_phase.h"
#include "kernel/support/parallel_for.h"

namespace mechanist {

std::string_view ToString(ContactVerdict verdict) {
  switch (verdict) {
    case ContactVerdict::kTouching:
      return "touching";
    case ContactVerdict::kDesignedFit:
      return "designed_fit";
    case ContactVerdict::kClash:
      return "clash";
  }
  return "";
}

namespace {

// As InEngagementRegion, with cylinders at least `min_radius` wide.
bool InRegion(const Feature& f, const RigidTransform& X_WP, const Eigen::Vector3d& p_W,
              double tolerance, double min_radius) {
  const Eigen::Vector3d origin_W = X_WP * f.origin;
  const Eigen::Vector3d axis_W = X_WP.RotateDirection(f.axis);
  const Eigen::Vector3d r = p_W - origin_W;
  const double along = r.dot(axis_W);
  const double radial = (r - along * axis_W).norm();
  auto in_cylinder = [&](double radius, double start, double end) {
    return along >= start - tolerance && along <= end + tolerance &&
           radial <= std::max(radius, min_radius) + tolerance;
  };
  switch (f.kind) {
    case FeatureKind::kShaft:
    case FeatureKind::kHole:
    case FeatureKind::kThread:
    case FeatureKind::kTappedHole:
      return in_cylinder(0.5 * f.diameter, 0.0, f.length);
    case FeatureKind::kGear:
      // Teeth reach one module beyond the pitch circle (inward for a ring gear, whose region
      // still has to include its mating pinion's tips, hence the outer bound for both).
      return in_cylinder(f.PitchRadius() + f.module, 0.0, f.length);
    case FeatureKind::kWormWheel:
      return in_cylinder(f.PitchRadius() + f.module, 0.0, f.length);
    case FeatureKind::kWorm:
      return in_cylinder(0.5 * f.pitch_diameter + f.module, 0.0, f.length);
    case FeatureKind::kRack: {
      // A band one module either side of the pitch line.
      const Eigen::Vector3d n_W = X_WP.RotateDirection(f.normal);
      return along >= -tolerance && along <= f.length + tolerance &&
             std::abs(r.dot(n_W)) <= f.module + tolerance;
    }
    case FeatureKind::kBall:
    case FeatureKind::kSocket:
      return r.norm() <= 0.5 * f.diameter + tolerance;
    case FeatureKind::kSlot:
    case FeatureKind::kKey:
      return along >= -tolerance && along <= f.length + tolerance &&
             radial <= std::max(f.width, f.depth) + tolerance;
    case FeatureKind::kFace:
      return false;
    case FeatureKind::kPinRing:
      // The pins and the lobes between them: out to the pins' outer edge.
      return in_cylinder(0.5 * f.diameter + f.pin_diameter, 0.0, f.length);
    case FeatureKind::kCycloidDisc:
      // The lobes' size is not in the feature: the disc's whole side (as far as its ring).
      return along >= -tolerance && along <= f.length + tolerance;
    case FeatureKind::kBevelGear: {
      // The frustum the teeth fill, one module beyond the pitch cone's face width each way.
      const double L = f.OuterConeDistance();
      const double c = std::cos(f.pitch_angle);
      return along >= (L - f.length) * c - f.module - tolerance &&
             along <= L * c + f.module + tolerance &&
             radial <= L * std::sin(f.pitch_angle) + f.module + tolerance;
    }
  }
  return false;
}

// Whether `pair` is a shaft in a hole whose diameters leave room (the hole at least as wide,
// within the length tolerance, as recognition takes sizes): its features do not overlap,
// whatever their meshes do.
bool IsFitWithRoom(const Assembly& assembly, const Pair& pair) {
  const Feature& a = assembly.feature(pair.a);
  const Feature& b = assembly.feature(pair.b);
  const auto inner = [](FeatureKind k) {
    return k == FeatureKind::kShaft || k == FeatureKind::kThread;
  };
  const auto outer = [](FeatureKind k) {
    return k == FeatureKind::kHole || k == FeatureKind::kTappedHole;
  };
  const double tolerance = assembly.tolerance().length;
  if (inner(a.kind) && outer(b.kind)) return b.diameter >= a.diameter - tolerance;
  if (outer(a.kind) && inner(b.kind)) return a.diameter >= b.diameter - tolerance;
  return false;
}

}  // namespace

bool IsAxialFit(FeatureKind kind) {
  return kind == FeatureKind::kShaft || kind == FeatureKind::kHole ||
         kind == FeatureKind::kThread || kind == FeatureKind::kTappedHole;
}

bool InEngagementRegion(const Feature& f, const RigidTransform& X_WP, const Eigen::Vector3d& p_W,
                        double tolerance) {
  return InRegion(f, X_WP, p_W, tolerance, 0.0);
}

bool OverlapIsDesigned(const Pair& pair) {
  switch (pair.type) {
    case PairType::kGear:
    case PairType::kBevelGear:
    case PairType::kWormGear:
    case PairType::kRackPinion:
    case PairType::kCycloidal:
      return true;
    case PairType::kScrew:
      return true;
    case PairType::kFixed:
      return pair.fastening == PairFastening::kPressFit ||
             pair.fastening == PairFastening::kTight || pair.fastening == PairFastening::kSetscrew;
    default:
      return false;
  }
}

double MeshDeviation(const Assembly& assembly, std::size_t part, double radius) {
  const Part& p = assembly.part(part);
  if (p.mesh_angle <= 0.0 || !std::isfinite(radius)) return p.mesh_deviation;
  return std::min(p.mesh_deviation, radius * (1 - std::cos(p.mesh_angle / 2)));
}

bool InPairRegion(const Assembly& assembly, const AssemblyState& state, const Pair& pair,
                  const Eigen::Vector3d& p_W, double tolerance) {
  const Feature& a = assembly.feature(pair.a);
  const Feature& b = assembly.feature(pair.b);
  // An axial fit overlaps between the two diameters: each cylinder is taken at the larger.
  const double min_radius =
      IsAxialFit(a.kind) && IsAxialFit(b.kind) ? 0.5 * std::max(a.diameter, b.diameter) : 0.0;
  return InRegion(a, state.X_WP.at(pair.a.part), p_W, tolerance, min_radius) &&
         InRegion(b, state.X_WP.at(pair.b.part), p_W, tolerance, min_radius);
}

std::vector<PartContact> FindContacts(const Assembly& assembly, const AssemblyState& state,
                                      const CollisionModel& model, const std::vector<Pair>& pairs) {
  const double tolerance = assembly.tolerance().length;
  std::vector<Aabb> boxes;
  for (std::size_t p = 0; p < assembly.parts().size(); ++p) {
    boxes.push_back(TransformBox(state.X_WP[p], model.part_mesh(p).bounds()));
  }
  // Measured on every core (each measure only reads the meshes), then judged in order.
  const auto near = OverlappingBoxes(boxes, tolerance);
  std::vector<ContactMeasure> measures(near.size());
  ParallelFor(near.size(), [&](std::size_t k) {
    const auto [i, j] = near[k];
    measures[k] = MeasureContact(model.part_mesh(i), state.X_WP[i], model.part_mesh(j),
                                 state.X_WP[j], tolerance);
  });
  std::vector<PartContact> contacts;
  for (std::size_t n = 0; n < near.size(); ++n) {
    const auto [i, j] = near[n];
    PartContact contact;
    contact.part_a = i;
    contact.part_b = j;
    contact.measure = measures[n];
    if (contact.measure.kind == ContactMeasure::Kind::kSeparate) continue;
    if (contact.measure.kind == ContactMeasure::Kind::kPenetrating) {
      contact.verdict = ContactVerdict::kClash;
      for (std::size_t k = 0; k < pairs.size(); ++k) {
        const Pair& pair = pairs[k];
        const bool between =
            (pair.a.part == i && pair.b.part == j) || (pair.a.part == j && pair.b.part == i);
        if (between && OverlapIsDesigned(pair) &&
            InPairRegion(assembly, state, pair, contact.measure.p_W, tolerance)) {
          contact.verdict = ContactVerdict::kDesignedFit;
          contact.pair = k;
          break;
        }
      }
    }
    if (contact.verdict == ContactVerdict::kClash) {
      // In a fit with room, no deeper than the meshes may lie off their surfaces: the
      // tessellations of a line-on-line fit, touching.
      for (const Pair& pair : pairs) {
        const bool between =
            (pair.a.part == i && pair.b.part == j) || (pair.a.part == j && pair.b.part == i);
        if (!between || !IsFitWithRoom(assembly, pair)) continue;
        const double radius =
            0.5 * std::max(assembly.feature(pair.a).diameter, assembly.feature(pair.b).diameter);
        const double allowance =
            tolerance + MeshDeviation(assembly, i, radius) + MeshDeviation(assembly, j, radius);
        if (contact.measure.depth <= allowance &&
            InPairRegion(assembly, state, pair, contact.measure.p_W, allowance)) {
          contact.verdict = ContactVerdict::kTouching;
          break;
        }
      }
    }
    contacts.push_back(contact);
  }
  std::sort(contacts.begin(), contacts.end(), [&](const PartContact& x, const PartContact& y) {
    const auto key = [&](const PartContact& c) {
      const std::string& a = assembly.part(c.part_a).id;
      const std::string& b = assembly.part(c.part_b).id;
      return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
    };
    return key(x) < key(y);
  });
  return contacts;
}

}  // namespace mechanist
