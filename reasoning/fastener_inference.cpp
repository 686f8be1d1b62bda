#include "reasoning/fastener_inference.h"

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "kernel/features/feature_recognition.h"
#include "kernel/geometry/line_geometry.h"
#include "kernel/support/number_format.h"

namespace mechanist {

double CoarsePitch(double diameter) {
  static const std::array<std::pair<double, double>, 22> kTable = {
      {{1, 0.25}, {1.2, 0.25}, {1.6, 0.35}, {2, 0.4},  {2.5, 0.45}, {3, 0.5},
       {4, 0.7},  {5, 0.8},    {6, 1.0},    {8, 1.25}, {10, 1.5},   {12, 1.75},
       {14, 2.0}, {16, 2.0},   {20, 2.5},   {24, 3.0}, {30, 3.5},   {36, 4.0},
       {42, 4.5}, {48, 5.0},   {56, 5.5},   {64, 6.0}}};
  const auto* best = &kTable[0];
  for (const auto& row : kTable) {
    if (std::abs(row.first - diameter) < std::abs(best->first - diameter)) best = &row;
  }
  return best->second;
}

namespace {

// Makes `shaft` a tight thread screwed into `hole`, a tight tapped hole, both of the ISO coarse
// pitch for the shaft's diameter, which it returns.
double ScrewTight(Feature* shaft, Feature* hole) {
  const double pitch = CoarsePitch(shaft->diameter);
  hole->kind = FeatureKind::kTappedHole;
  hole->fastening = Fastening::kTight;
  hole->pitch = pitch;
  shaft->kind = FeatureKind::kThread;
  shaft->fastening = Fastening::kTight;
  shaft->pitch = pitch;
  return pitch;
}

// The mesh's vertices about the line (origin, unit direction): each one's distance along it
// and from it, and their largest distance from it and extent along it: how wide and how long a
// part is about an axis (mm).
struct Girth {
  double radius = 0.0, lo = 0.0, hi = 0.0;
  std::vector<std::pair<double, double>> vertices;  // (along, from the line)
};

Girth GirthAbout(const TriangleMesh& mesh, const Eigen::Vector3d& origin,
                 const Eigen::Vector3d& direction) {
  Girth g{
      0.0, std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), {}};
  g.vertices.reserve(mesh.vertices.size());
  for (const Eigen::Vector3d& v : mesh.vertices) {
    const Eigen::Vector3d d = v - origin;
    const double s = d.dot(direction), r = (d - s * direction).norm();
    g.vertices.emplace_back(s, r);
    g.radius = std::max(g.radius, r);
    g.lo = std::min(g.lo, s), g.hi = std::max(g.hi, s);
  }
  return g;
}

// Whether the shaft's axis `s` runs along the hole's `h` (within the tolerances) and the two
// overlap along it.
bool Engaged(const AxisSegment& s, const AxisSegment& h, double length_tolerance,
             double angle_tolerance) {
  return AngleBetweenLines(s.direction, h.direction) <= angle_tolerance &&
         DistanceToLine(h.origin, s.origin, s.direction) <= length_tolerance &&
         AxialOverlap(s, h) > length_tolerance;
}

}  // namespace

std::vector<Diagnostic> InferNutsOnBolts(
    std::vector<Part>* parts, double length_tolerance, double angle_tolerance,
    const std::function<bool(std::size_t part, std::size_t feature)>& inferred) {
  std::vector<Diagnostic> found;
  std::map<const TriangleMesh*, MeshFeatures> shapes;
  for (std::size_t n = 0; n < parts->size(); ++n) {
    Part& nut = (*parts)[n];
    std::vector<std::size_t> holes;
    bool all_inferred = true;
    for (std::size_t f = 0; f < nut.features.size(); ++f) {
      all_inferred = all_inferred && inferred(n, f);
      if (nut.features[f].kind == FeatureKind::kHole) holes.push_back(f);
    }
    if (!all_inferred || holes.size() != 1) continue;
    // Instances of one product share their mesh: recognised once.
    auto cached = shapes.find(nut.mesh.get());
    if (cached == shapes.end())
      cached = shapes.emplace(nut.mesh.get(), RecognizeFeatures(*nut.mesh)).first;
    const MeshFeatures& shape = cached->second;
    if (shape.polygon_sides == 0 || !shape.axis) continue;
    Feature& hole = nut.features[holes[0]];
    if (AngleBetweenLines(hole.axis, *shape.axis) > angle_tolerance) continue;
    // A nut is small for its bore (an M5 hexagon nut is 9.2 mm across its corners and 4 mm
    // thick): an arm's square hub on a motor shaft is no nut.
    const Girth girth = GirthAbout(*nut.mesh, hole.origin, hole.axis);
    if (girth.radius > 2 * hole.diameter || girth.hi - girth.lo > 2 * hole.diameter) continue;
    const AxisSegment h = hole.WorldAxis(nut.X_WP);
    for (std::size_t b = 0; b < parts->size(); ++b) {
      if (b == n) continue;
      Part& bolt = (*parts)[b];
      for (std::size_t f = 0; f < bolt.features.size(); ++f) {
        Feature& shaft = bolt.features[f];
        // A shaft, or one a nut before this one made a thread (a rod with a nut at each end).
        if (shaft.kind != FeatureKind::kShaft && shaft.kind != FeatureKind::kThread) continue;
        if (!inferred(b, f)) continue;
        const AxisSegment s = shaft.WorldAxis(bolt.X_WP);
        if (std::abs(shaft.diameter - hole.diameter) > 0.02 * hole.diameter ||
            !Engaged(s, h, length_tolerance, angle_tolerance)) {
          continue;
        }
        const double pitch = ScrewTight(&shaft, &hole);
        found.push_back(
            {Severity::kInfo,
             "nut_on_bolt",
             fmt::format("part '{}' (a {}-sided prism with a bore) sits on '{}/{}' ({} "
                         "mm): taken as a nut on a bolt, a tight thread of pitch {} mm "
                         "(heuristic)",
                         nut.id, shape.polygon_sides, bolt.id, shaft.id,
                         FormatNumber(shaft.diameter), FormatNumber(pitch)),
             {nut.id, bolt.id},
             {fmt::format("{}/{}", nut.id, hole.id), fmt::format("{}/{}", bolt.id, shaft.id)}});
        break;
      }
      if (hole.kind == FeatureKind::kTappedHole) break;
    }
  }
  return found;
}

namespace {

// A screw taken as screwed into plain holes (InferScrewsInPlainHoles), for its finding.
struct Tapped {
  struct Hole {
    std::string part, hole;
    std::string diameter;  // as drawn, formatted
  };
  std::string screw;                  // its part's id
  double diameter = 0, pitch = 0;     // its thread's, mm
  bool through = false;               // its tip out past every hole
  std::vector<Hole> holes;            // the tip's first
  std::vector<std::string> features;  // its thread, then its holes

  // Whether `other` reads as this one but for the names of the screw and its holes.
  bool Alike(const Tapped& other) const {
    return diameter == other.diameter && pitch == other.pitch && through == other.through &&
           holes.size() == other.holes.size() &&
           std::equal(holes.begin(), holes.end(), other.holes.begin(),
                      [](const Hole& a, const Hole& b) {
                        return a.part == b.part && a.diameter == b.diameter;
                      });
  }
};

}  // namespace

std::vector<Diagnostic> InferScrewsInPlainHoles(
    std::vector<Part>* parts, double length_tolerance, double angle_tolerance,
    const std::function<bool(std::size_t part, std::size_t feature)>& inferred) {
  std::vector<Diagnostic> found;
  std::vector<Tapped> screws;
  for (std::size_t s = 0; s < parts->size(); ++s) {
    Part& screw = (*parts)[s];
    if (!screw.HasGeometry()) continue;
    bool all_inferred = true;
    std::optional<std::size_t> shank;
    for (std::size_t f = 0; f < screw.features.size(); ++f) {
      all_inferred = all_inferred && inferred(s, f);
      const Feature& x = screw.features[f];
      if (x.kind == FeatureKind::kShaft && (!shank || x.length > screw.features[*shank].length)) {
        shank = f;
      }
    }
    if (!all_inferred || !shank) continue;
    Feature& thread = screw.features[*shank];
    if (thread.length < 1.5 * thread.diameter) continue;
    // The head: a shorter, wider coaxial shaft at one end of the shank.
    const AxisSegment a = thread.LocalAxis();
    std::optional<Eigen::Vector3d> head_side;  // from the shank's middle toward the head
    double head_diameter = 0.0;
    for (const Feature& x : screw.features) {
      if (x.kind != FeatureKind::kShaft || &x == &thread) continue;
      if (x.diameter < 1.3 * thread.diameter || x.diameter > 2.5 * thread.diameter ||
          x.length > x.diameter || AngleBetweenLines(x.axis, a.direction) > angle_tolerance ||
          DistanceToLine(x.origin, a.origin, a.direction) > length_tolerance) {
        continue;
      }
      const double t0 = (x.origin - a.origin).dot(a.direction);
      const double t1 = t0 + x.length * x.axis.dot(a.direction);
      // Beside the shank, up to a quarter of its diameter away (a fillet under the head).
      const double near = std::min(t0, t1), far = std::max(t0, t1);
      const double gap = 0.25 * thread.diameter + length_tolerance;
      if (far <= length_tolerance && far >= -gap) {
        head_side = -a.direction;
      } else if (near >= a.length - length_tolerance && near <= a.length + gap) {
        head_side = a.direction;
      } else {
        continue;
      }
      head_diameter = x.diameter;
      break;
    }
    const Girth girth = GirthAbout(*screw.mesh, a.origin, a.direction);
    std::optional<double> tip_along;  // from a.origin along a.direction
    if (!head_side) {
      // A head that is no cylinder (domed, cross-recessed): one end of the mesh, over a shank
      // diameter along the axis, 1.3 to 2.5 diameters wide, and no longer than it is wide
      // (what is wider than the shank), the other end no wider than the shank (a chamfered or
      // rolled tip).
      auto end_width = [&](bool at_hi) {
        double width = 0.0;
        for (const auto& [s, r] : girth.vertices) {
          if (at_hi ? s >= girth.hi - thread.diameter : s <= girth.lo + thread.diameter) {
            width = std::max(width, 2 * r);
          }
        }
        return width;
      };
      auto wide_length = [&](bool at_hi) {  // from that end, how far the part is wider
        double length = 0.0;
        for (const auto& [s, r] : girth.vertices) {
          if (r > 0.6 * thread.diameter + length_tolerance) {
            length = std::max(length, at_hi ? girth.hi - s : s - girth.lo);
          }
        }
        return length;
      };
      const double lo_width = end_width(false), hi_width = end_width(true);
      auto head_like = [&](double w, bool at_hi) {
        return w >= 1.3 * thread.diameter && w <= 2.5 * thread.diameter && wide_length(at_hi) <= w;
      };
      auto tip_like = [&](double w) { return w <= 1.1 * thread.diameter + length_tolerance; };
      if (head_like(hi_width, true) && tip_like(lo_width)) {
        head_side = a.direction, head_diameter = hi_width, tip_along = girth.lo;
      } else if (head_like(lo_width, false) && tip_like(hi_width)) {
        head_side = -a.direction, head_diameter = lo_width, tip_along = girth.hi;
      }
    }
    if (!head_side) continue;
    // A screw is no wider than its head (a motor with a shaft is).
    if (girth.radius > 0.5 * head_diameter * 1.05) continue;
    if (!tip_along) tip_along = head_side->dot(a.direction) > 0 ? 0.0 : a.length;
    const Eigen::Vector3d tip_P = a.origin + *tip_along * a.direction;
    const AxisSegment t = thread.WorldAxis(screw.X_WP);
    const Eigen::Vector3d tip = screw.X_WP * tip_P;
    const Eigen::Vector3d inward = screw.X_WP.RotateDirection(-*head_side);  // toward the tip
    // Plain holes of other parts along the shank, drawn at the thread's size (within 10%) or
    // at the tap drill's (down to 75% of it): engaged with the shank.
    struct Along {
      std::size_t part, feature;
      bool tip;      // the shank's tip ends inside it
      double start;  // where the hole begins, mm from the tip toward it (negative: before it)
    };
    std::vector<Along> along;
    for (std::size_t p = 0; p < parts->size(); ++p) {
      if (p == s) continue;
      const Part& part = (*parts)[p];
      for (std::size_t f = 0; f < part.features.size(); ++f) {
        const Feature& hole = part.features[f];
        // A plain hole, or one tapped tight at the shank's size already: a screw from its
        // other end (an extrusion's long core hole takes one at each end).
        const bool tapped = hole.kind == FeatureKind::kTappedHole &&
                            hole.fastening == Fastening::kTight &&
                            std::abs(hole.diameter - thread.diameter) <= length_tolerance;
        if ((hole.kind != FeatureKind::kHole && !tapped) || !inferred(p, f)) continue;
        const AxisSegment h = hole.WorldAxis(part.X_WP);
        if (hole.diameter < 0.75 * thread.diameter ||
            hole.diameter > 1.1 * thread.diameter + length_tolerance ||
            !Engaged(t, h, length_tolerance, angle_tolerance)) {
          continue;
        }
        // The tip inside the hole: not before its start nor past its end.
        const double s0 = (h.origin - tip).dot(inward);
        const double s1 = (h.origin + h.length * h.direction - tip).dot(inward);
        const bool tip_inside =
            std::min(s0, s1) <= length_tolerance && std::max(s0, s1) >= -length_tolerance;
        along.push_back({p, f, tip_inside, std::min(s0, s1)});
      }
    }
    std::stable_partition(along.begin(), along.end(), [](const Along& x) { return x.tip; });
    // A tip out past every hole still ends in the last hole narrower than the shank, which it
    // can only pass threaded: a nut or a tapped plate it comes through.
    const bool through = !along.empty() && !along.front().tip;
    if (through) {
      std::erase_if(along, [&](const Along& x) {
        return (*parts)[x.part].features[x.feature].diameter >= thread.diameter - length_tolerance;
      });
      std::stable_sort(along.begin(), along.end(),
                       [](const Along& x, const Along& y) { return x.start > y.start; });
    }
    if (along.empty()) continue;
    const Along tip_hole = along.front();
    // The tip's hole is tapped, and so is every hole the shank passes that is narrower than
    // the thread (it can only be threaded: a motor's long screws run through a tapped stator
    // into a tapped flange).
    Tapped tapped{screw.id, thread.diameter, 0.0, through, {}, {}};
    tapped.features.push_back(screw.id + "/" + thread.id);
    for (const Along& x : along) {
      Feature& hole = (*parts)[x.part].features[x.feature];
      const bool tip = x.part == tip_hole.part && x.feature == tip_hole.feature;
      if (!tip && hole.diameter >= thread.diameter - length_tolerance) continue;
      const std::string& id = (*parts)[x.part].id;
      tapped.holes.push_back({id, hole.id, FormatNumber(hole.diameter)});
      tapped.features.push_back(id + "/" + hole.id);
      hole.diameter = thread.diameter;
      tapped.pitch = ScrewTight(&thread, &hole);
    }
    screws.push_back(std::move(tapped));
  }
  // One finding for the screws that read alike but for their names: of one size, through the
  // same parts' holes of the same sizes (the four screws of a motor's flange), listed by id so
  // that the file's order of parts changes nothing.
  std::sort(screws.begin(), screws.end(),
            [](const Tapped& a, const Tapped& b) { return a.screw < b.screw; });
  std::vector<std::vector<const Tapped*>> alike;
  for (const Tapped& t : screws) {
    auto group = std::find_if(alike.begin(), alike.end(),
                              [&](const auto& g) { return g.front()->Alike(t); });
    if (group == alike.end()) {
      alike.push_back({&t});
    } else {
      group->push_back(&t);
    }
  }
  for (const std::vector<const Tapped*>& group : alike) {
    const Tapped& first = *group.front();
    const bool several = group.size() > 1;
    // The screws, then the parts whose holes they tapped; each screw's thread and holes.
    std::vector<std::string> names, part_ids, feature_names;
    for (const Tapped* t : group) {
      names.push_back(fmt::format("'{}'", t->screw));
      part_ids.push_back(t->screw);
    }
    for (const Tapped* t : group) {
      for (const Tapped::Hole& h : t->holes) {
        if (std::find(part_ids.begin(), part_ids.end(), h.part) == part_ids.end()) {
          part_ids.push_back(h.part);
        }
      }
      feature_names.insert(feature_names.end(), t->features.begin(), t->features.end());
    }
    // The holes at the k-th place along each screw, the tip's first: "'plate/hole_4' (2.459 mm)".
    const auto holes_at = [&](std::size_t k) {
      std::vector<std::string> named;
      for (const Tapped* t : group) {
        named.push_back(fmt::format("'{}/{}'", t->holes[k].part, t->holes[k].hole));
      }
      return fmt::format("{} ({} mm)", fmt::join(named, ", "), first.holes[k].diameter);
    };
    std::string message = fmt::format(
        "{} {} ({}a head and a {} mm shank) {} {}: taken as screwed into {}, {} of pitch {} mm "
        "(heuristic: the file models no thread)",
        several ? fmt::format("{} parts,", group.size()) : "part", fmt::join(names, ", "),
        several ? "each " : "", FormatNumber(first.diameter),
        first.through
            ? (several ? "come out through the narrower" : "comes out through the narrower")
            : (several ? "end, one each, in" : "ends in"),
        holes_at(0), several ? "them" : "it", several ? "tight threads" : "a tight thread",
        FormatNumber(first.pitch));
    for (std::size_t k = 1; k < first.holes.size(); ++k) {
      message += fmt::format("{} {}", k == 1 ? "; also threaded through" : ",", holes_at(k));
    }
    found.push_back({Severity::kInfo, "screw_in_plain_hole", message, part_ids, feature_names});
  }
  return found;
}

}  // namespace mechanist
