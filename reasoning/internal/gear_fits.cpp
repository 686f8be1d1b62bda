// Gearing: spur, internal and helical gear pairs, cycloid discs in pin rings, worms and worm
// wheels, racks.

#include <fmt/format.h>

#include "reasoning/internal/recognizer.h"

namespace mechanist::internal {

void Recognizer::GearGear(const WorldFeature& x, const WorldFeature& y) {
  if (x.f.internal && y.f.internal) return;
  // Order by name so that the pair and its ratio do not depend on the file's order.
  const bool swap = NameLess(y, x);
  const WorldFeature& g1 = swap ? y : x;
  const WorldFeature& g2 = swap ? x : y;
  if (AxialOverlap(g1.axis, g2.axis) <= L_) return;
  const Feature& f1 = g1.f;
  const Feature& f2 = g2.f;
  const double angle = AngleBetweenLines(g1.axis.direction, g2.axis.direction);
  const Eigen::Vector3d mid2 = g2.axis.origin + 0.5 * g2.axis.length * g2.axis.direction;
  const double d = DistanceToLine(mid2, g1.axis.origin, g1.axis.direction);
  const bool internal = f1.internal || f2.internal;
  const int z_internal = f1.internal ? f1.teeth : f2.teeth;
  const int z_external = f1.internal ? f2.teeth : f1.teeth;
  if (internal && z_internal <= z_external) return;  // a ring must be larger than its pinion
  // Helical gears mesh with equal helix angles, of opposite hands when external and the same
  // hand when internal; their centre distance takes the transverse module m / cos(helix).
  const double helix1 = assembly_.feature(g1.ref).helix_angle;
  const double helix2 = assembly_.feature(g2.ref).helix_angle;
  const double cos_helix = std::cos(helix1);
  auto required = [&](double m) {
    const double transverse = m / cos_helix;
    return internal ? transverse * (z_internal - z_external) / 2
                    : transverse * (f1.teeth + f2.teeth) / 2;
  };
  const double m = f1.module;
  if (!SameModule(f1.module, f2.module)) {
    // Meant to mesh if the distance fits either gear's module.
    if (angle <= near_A_ && (std::abs(d - required(f1.module)) < f1.module ||
                             std::abs(d - required(f2.module)) < f2.module)) {
      Near("gear_module_mismatch", g1, g2,
           fmt::format("modules differ: {} and {} (required equal)", Mm(f1.module), Mm(f2.module)));
    }
    return;
  }
  const double a = required(m);
  const double error = std::abs(d - a);
  const double helix_error = std::abs(helix2 - (internal ? helix1 : -helix1));
  if (angle <= A_ && error <= L_ && helix_error > A_) {
    Near("gear_helix_mismatch", g1, g2,
         fmt::format("helix angles {} and {} (required equal, {})", Deg(helix1), Deg(helix2),
                     internal ? "of the same hand for an internal pair" : "of opposite hands"));
    return;
  }
  if (angle <= A_ && error <= L_) {
    AddPair(PairType::kGear, g1, g2);
    return;
  }
  if (error >= m) return;
  // The module across the teeth: m, or m / cos(helix) for helical gears.
  const std::string module =
      helix1 == 0.0 ? FormatNumber(m) : fmt::format("{} / cos({})", FormatNumber(m), Deg(helix1));
  const std::string formula = internal
                                  ? fmt::format("{} x |{} - {}| / 2", module, f2.teeth, f1.teeth)
                                  : fmt::format("{} x ({} + {}) / 2", module, f1.teeth, f2.teeth);
  if (angle > A_ && angle <= near_A_) {
    Near("gear_axes_not_parallel", g1, g2,
         fmt::format("axes are {} apart (required parallel within {})", Deg(angle), Deg(A_)));
  } else if (angle <= A_) {
    Near("gear_center_distance", g1, g2,
         fmt::format("centre distance {}, required {} = {} (off by {}, tolerance {})", Mm(d), Mm(a),
                     formula, Mm(d - a), Mm(L_)));
  }
}

void Recognizer::BevelBevel(const WorldFeature& x, const WorldFeature& y) {
  const bool swap = NameLess(y, x);
  const WorldFeature& g1 = swap ? y : x;
  const WorldFeature& g2 = swap ? x : y;
  const Feature& f1 = g1.f;
  const Feature& f2 = g2.f;
  const double apart = (g2.axis.origin - g1.axis.origin).norm();
  const double m = std::max(f1.module, f2.module);
  if (apart > m) return;  // not even nearly a common apex
  const double shaft_angle =
      std::acos(std::clamp(g1.axis.direction.dot(g2.axis.direction), -1.0, 1.0));
  const double angle_error = shaft_angle - (f1.pitch_angle + f2.pitch_angle);
  if (std::abs(angle_error) > near_A_) return;  // facing side gears of a differential
  // Two crown gears face each other (90 + 90 degrees): their cones are one plane, no mesh.
  if (f1.pitch_angle + f2.pitch_angle >= kPi - A_) return;
  if (!SameModule(f1.module, f2.module)) {
    Near("bevel_module_mismatch", g1, g2,
         fmt::format("modules differ: {} and {} (required equal)", Mm(f1.module), Mm(f2.module)));
    return;
  }
  if (apart > L_) {
    Near("bevel_apex", g1, g2,
         fmt::format("pitch cone apexes are {} apart (required common, tolerance {})", Mm(apart),
                     Mm(L_)));
    return;
  }
  if (std::abs(angle_error) > A_) {
    Near("bevel_pitch_angles", g1, g2,
         fmt::format("the axes are {} apart, the pitch angles {} + {} = {} (off by {}, tolerance "
                     "{})",
                     Deg(shaft_angle), Deg(f1.pitch_angle), Deg(f2.pitch_angle),
                     Deg(f1.pitch_angle + f2.pitch_angle), Deg(angle_error), Deg(A_)));
    return;
  }
  if (std::abs(f1.spiral_angle + f2.spiral_angle) > A_) {
    Near("bevel_spiral_mismatch", g1, g2,
         fmt::format("spiral angles {} and {} (required equal, of opposite hands)",
                     Deg(f1.spiral_angle), Deg(f2.spiral_angle)));
    return;
  }
  // Along the common pitch line each gear's teeth run from L - face width to L; mating gears
  // end together (their pitch circles, m z / 2 = L sin(pitch angle), then roll at z1 : z2).
  const double L1 = f1.OuterConeDistance();
  const double L2 = f2.OuterConeDistance();
  if (std::abs(L1 - L2) > L_ || std::min(L1, L2) - std::max(L1 - f1.length, L2 - f2.length) <= L_) {
    Near("bevel_cone_distance", g1, g2,
         fmt::format("the teeth do not end together on the pitch line: outer cone distances {} = "
                     "{} x {} / (2 sin {}) and {} = {} x {} / (2 sin {}) (required equal), face "
                     "widths {} and {}",
                     Mm(L1), FormatNumber(m), f1.teeth, Deg(f1.pitch_angle), Mm(L2),
                     FormatNumber(m), f2.teeth, Deg(f2.pitch_angle), Mm(f1.length), Mm(f2.length)));
    return;
  }
  AddPair(PairType::kBevelGear, g1, g2);
}

void Recognizer::CycloidPins(const WorldFeature& disc, const WorldFeature& ring) {
  if (AxialOverlap(disc.axis, ring.axis) <= L_) return;
  const double angle = AngleBetweenLines(disc.axis.direction, ring.axis.direction);
  if (angle > near_A_) return;
  const double e = assembly_.feature(disc.ref).eccentricity;
  const double offset = DistanceToLine(disc.axis.origin, ring.axis.origin, ring.axis.direction);
  if (std::abs(offset - e) > near_L_) return;
  if (ring.f.teeth != disc.f.teeth + 1) {
    Near("cycloid_pin_count", disc, ring,
         fmt::format("{} pins for {} lobes (required one pin more than lobes)", ring.f.teeth,
                     disc.f.teeth));
    return;
  }
  if (angle > A_) {
    Near("cycloid_axes_not_parallel", disc, ring,
         fmt::format("axes are {} apart (required parallel within {})", Deg(angle), Deg(A_)));
  } else if (std::abs(offset - e) > L_) {
    Near("cycloid_eccentricity", disc, ring,
         fmt::format("the disc's axis is {} from the ring's, required its eccentricity {} (off "
                     "by {}, tolerance {})",
                     Mm(offset), Mm(e), Mm(offset - e), Mm(L_)));
  } else {
    AddPair(PairType::kCycloidal, disc, ring);
  }
}

void Recognizer::WormWheel(const WorldFeature& w, const WorldFeature& g) {
  const double angle = AngleBetweenLines(w.axis.direction, g.axis.direction);
  const LineLineClosest c =
      ClosestPointsOfLines(w.axis.origin, w.axis.direction, g.axis.origin, g.axis.direction);
  if (c.s < -L_ || c.s > w.axis.length + L_ || c.t < -L_ || c.t > g.axis.length + L_) return;
  const Feature& fw = w.f;
  const Feature& fg = g.f;
  if (!SameModule(fw.module, fg.module)) {
    const double a_worm = (fw.pitch_diameter + fw.module * fg.teeth) / 2;
    const double a_wheel = (fw.pitch_diameter + fg.module * fg.teeth) / 2;
    if (angle >= kPi / 2 - near_A_ &&
        (std::abs(c.distance - a_worm) < fw.module || std::abs(c.distance - a_wheel) < fg.module)) {
      Near("worm_module_mismatch", w, g,
           fmt::format("modules differ: {} and {} (required equal)", Mm(fw.module), Mm(fg.module)));
    }
    return;
  }
  const double a = (fw.pitch_diameter + fw.module * fg.teeth) / 2;
  const double error = std::abs(c.distance - a);
  if (angle >= kPi / 2 - A_ && error <= L_) {
    AddPair(PairType::kWormGear, w, g);
    return;
  }
  if (error >= fg.module) return;
  if (angle < kPi / 2 - A_ && angle >= kPi / 2 - near_A_) {
    Near("worm_axes_not_perpendicular", w, g,
         fmt::format("axes are {} apart (required 90 deg within {})", Deg(angle), Deg(A_)));
  } else if (angle >= kPi / 2 - A_) {
    Near("worm_center_distance", w, g,
         fmt::format("centre distance {}, required {} = ({} + {} x {}) / 2 (off by {}, "
                     "tolerance {})",
                     Mm(c.distance), Mm(a), FormatNumber(fw.pitch_diameter),
                     FormatNumber(fw.module), fg.teeth, Mm(c.distance - a), Mm(L_)));
  }
}

void Recognizer::GearRack(const WorldFeature& g, const WorldFeature& r) {
  if (g.f.internal) return;
  const double to_axis = AngleBetweenLines(g.axis.direction, r.axis.direction);
  const double to_normal = AngleBetweenLines(g.axis.direction, r.normal_W);
  const LineLineClosest c =
      ClosestPointsOfLines(g.axis.origin, g.axis.direction, r.axis.origin, r.axis.direction);
  if (c.s < -L_ || c.s > g.axis.length + L_ || c.t < -L_ || c.t > r.axis.length + L_) return;
  const Eigen::Vector3d p_gear = g.axis.origin + c.s * g.axis.direction;
  const Eigen::Vector3d p_rack = r.axis.origin + c.t * r.axis.direction;
  if ((p_gear - p_rack).dot(r.normal_W) <= 0) return;  // the pinion is on the other side
  if (!SameModule(g.f.module, r.f.module)) {
    if (std::abs(c.distance - g.f.module * g.f.teeth / 2) < g.f.module ||
        std::abs(c.distance - r.f.module * g.f.teeth / 2) < r.f.module) {
      Near("rack_module_mismatch", g, r,
           fmt::format("modules differ: {} and {} (required equal)", Mm(g.f.module),
                       Mm(r.f.module)));
    }
    return;
  }
  const double a = g.f.module * g.f.teeth / 2;
  const double error = std::abs(c.distance - a);
  const bool square = to_axis >= kPi / 2 - A_ && to_normal >= kPi / 2 - A_;
  if (square && error <= L_) {
    AddPair(PairType::kRackPinion, g, r);
  } else if (square && error < g.f.module) {
    Near("rack_pitch_line_distance", g, r,
         fmt::format("pitch line at {} from the pinion's axis, required {} = {} x {} / 2 (off by "
                     "{}, tolerance {})",
                     Mm(c.distance), Mm(a), FormatNumber(g.f.module), g.f.teeth, Mm(c.distance - a),
                     Mm(L_)));
  }
}

}  // namespace mechanist::internal
