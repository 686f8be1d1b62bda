// The only translation unit that includes Open CASCADE.
// Open CASCADE's signals become exceptions at OCC_CATCH_SIGNALS (its own mechanism on Linux:
// the signal handler jumps to the nearest such point, which throws).
#define OCC_CONVERT_SIGNALS
#include "io/step_reader.h"

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Eigen/Eigenvalues>
#include <GProp_GProps.hxx>
#include <GeomLib_IsPlanarSurface.hxx>
#include <IMeshData_Status.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <OSD.hxx>
#include <Poly_Triangulation.hxx>
#include <Precision.hxx>
#include <STEPCAFControl_ExternFile.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPConstruct_ExternRefs.hxx>
#include <ShapeFix_Face.hxx>
#include <ShapeFix_Shape.hxx>
#include <ShapeFix_Solid.hxx>
#include <ShapeFix_Wire.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <StepBasic_ConversionBasedUnitAndLengthUnit.hxx>
#include <StepBasic_DocumentFile.hxx>
#include <StepBasic_SiUnitAndLengthUnit.hxx>
#include <StepGeom_GeomRepContextAndGlobUnitAssCtxAndGlobUncertaintyAssCtx.hxx>
#include <StepGeom_GeometricRepresentationContextAndGlobalUnitAssignedContext.hxx>
#include <StepRepr_GlobalUnitAssignedContext.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_TShape.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSAlgo.hxx>
#include <XSAlgo_AlgoContainer.hxx>
#include <XSControl_WorkSession.hxx>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <csignal>
#include <fstream>
#include <gp_Cone.hxx>
#include <gp_Sphere.hxx>
#include <iterator>
#include <map>
#include <mutex>
#include <numeric>
#include <regex>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>

#include "io/occt/part21_records.h"
#include "io/occt/part21_work_library.h"
#include "kernel/geometry/circle_fit.h"
#include "kernel/mesh/mesh_check.h"
#include "kernel/solvers/linear_algebra.h"
#include "kernel/support/ascii_lower.h"
#include "kernel/support/number_format.h"
#include "kernel/support/parallel_for.h"

namespace mechanist {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string NameOf(const TDF_Label& label) {
  Handle(TDataStd_Name) name;
  if (!label.FindAttribute(TDataStd_Name::GetID(), name)) return "";
  return TCollection_AsciiString(name->Get()).ToCString();
}

// A product instance's name as read, or empty for one without a name of its own: unnamed
// ("=>[0:1:1:2]", Open CASCADE's label entry), or a NEXT_ASSEMBLY_USAGE_OCCURRENCE's
// identifier standing in for a blank name ("NAUO1", as SolidWorks writes them).
std::string InstanceName(const std::string& name) {
  static const std::regex kOccurrenceId("NAUO[0-9]+");
  if (name.rfind("=>", 0) == 0 || std::regex_match(name, kOccurrenceId)) return "";
  return name;
}

std::string Sanitised(const std::string& name) {
  std::string out = name;
  for (char& c : out) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) c = '_';
  }
  return out;
}

RigidTransform ToRigid(const gp_Trsf& t) {
  Eigen::Matrix3d R;
  Eigen::Vector3d p;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) R(i, j) = t.Value(i + 1, j + 1);
    p[i] = t.Value(i + 1, 4);
  }
  return RigidTransform(R, p, 1e-6);
}

Eigen::Vector3d ToEigen(const gp_XYZ& v) { return {v.X(), v.Y(), v.Z()}; }

// How closely two faces of one cylinder, cone or sphere agree (and a cone with the cylinder it
// ends): exact surfaces to rounding (1e-6 of the radius, at least of 1 mm; 1e-9 in the cosine
// of their axes' angle), surfaces fitted to free-form faces to the fit's tolerance (mm) and the
// 1 mrad their normals are held to.
struct Agreement {
  double length = 0.0;  // mm; 0: rounding
  double cosine = 1e-9;
  double Length(double radius) const { return length > 0 ? length : 1e-6 * std::max(1.0, radius); }
  // Two faces agree as closely as the looser of them.
  Agreement With(const Agreement& o) const {
    return {std::max(length, o.length), std::max(cosine, o.cosine)};
  }
};

// A cylinder being gathered from its faces.
struct Cylinder {
  Eigen::Vector3d point, direction;
  double radius = 0.0;
  bool convex = true;
  Agreement agree;
  // Each face's extent along the axis (from `point`) and angular span (radians).
  struct Span {
    double lo = 1e300, hi = -1e300;
    double coverage = 0.0;
  };
  std::vector<Span> spans;
};

// The stretches of a cylinder along its axis where its faces overlap or touch (within
// `gap` mm), each with the faces' angular spans summed: a bore through the two cheeks of a fork
// is two holes, not one across the gap between them (where the other part's knuckle sits).
std::vector<Cylinder::Span> Stretches(std::vector<Cylinder::Span> spans, double gap) {
  std::sort(spans.begin(), spans.end(),
            [](const Cylinder::Span& a, const Cylinder::Span& b) { return a.lo < b.lo; });
  std::vector<Cylinder::Span> stretches;
  for (const Cylinder::Span& s : spans) {
    if (stretches.empty() || s.lo > stretches.back().hi + gap) {
      stretches.push_back(s);
    } else {
      stretches.back().hi = std::max(stretches.back().hi, s.hi);
      stretches.back().coverage += s.coverage;
    }
  }
  return stretches;
}

// A sphere being gathered from its faces.
struct Sphere {
  Eigen::Vector3d center;
  double radius = 0.0;
  bool convex = true;
  double area = 0.0;  // mm^2, of its faces
  Agreement agree;
};

// A cone being gathered from its faces.
struct Cone {
  Eigen::Vector3d apex, direction;  // direction: where the cone widens
  double semi_angle = 0.0;          // radians
  bool convex = true;
  Agreement agree;
  double coverage = 0.0;  // radians of the faces' angular spans, summed
  double r_min = 1e300, r_max = -1e300;
};

std::string Mm(double x) { return fmt::format("{} mm", FormatNumber(x)); }

// A free-form face (B-spline, Bezier, extrusion, revolution, offset) that is a plane, a
// cylinder, a cone, a sphere or a torus within `tolerance` mm: some exporters and healing steps
// write every surface so.
struct AnalyticFit {
  enum class Kind { kNone, kPlane, kCylinder, kCone, kSphere, kTorus };
  Kind kind = Kind::kNone;
  // plane: a point and its normal; cylinder and torus: a point of the axis and its direction;
  // cone: the apex and the axis, pointing to where the cone widens; sphere: the centre.
  Eigen::Vector3d point, direction;
  double radius = 0.0;      // cylinder, sphere; torus: the major radius (its tube's centre line)
  double semi_angle = 0.0;  // cone: radians between the axis and the surface
  bool outward = true;      // the surface's normal (face orientation aside) points away from
                            // the axis (cylinder, cone), the centre (sphere) or the tube's
                            // centre line (torus)
  double coverage = 0.0;    // radians around the axis that the samples span (cylinder, cone)
  double error = 0.0;       // mm: the largest distance of a sample from the fitted surface
};

// Points and unit normals (the surface's own, face orientation aside) of a face's surface on a
// 9 x 9 grid over its parameter bounds, degenerate points (poles) left out.
struct SurfaceSamples {
  std::vector<Eigen::Vector3d> points, normals;
};

SurfaceSamples SampleSurface(const TopoDS_Face& face, const BRepAdaptor_Surface& surface) {
  SurfaceSamples s;
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  constexpr int kGrid = 9;
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      gp_Pnt p;
      gp_Vec du, dv;
      surface.D1(u0 + (u1 - u0) * i / (kGrid - 1), v0 + (v1 - v0) * j / (kGrid - 1), p, du, dv);
      const gp_Vec n = du.Crossed(dv);
      if (n.Magnitude() < 1e-12) continue;
      s.points.push_back(ToEigen(p.XYZ()));
      s.normals.push_back(ToEigen(n.Normalized().XYZ()));
    }
  }
  return s;
}

// Normals agree with a fitted surface's when their directions differ by less than this (rad).
constexpr double kNormalAngle = 1e-3;

// Radians around `axis` (through `origin`) that the samples span: a full turn less the widest
// gap between their angles.
double Coverage(const SurfaceSamples& s, const Eigen::Vector3d& origin,
                const Eigen::Vector3d& axis) {
  const Eigen::Vector3d x = axis.unitOrthogonal(), y = axis.cross(x);
  std::vector<double> angles;
  for (const Eigen::Vector3d& p : s.points) {
    angles.push_back(std::atan2((p - origin).dot(y), (p - origin).dot(x)));
  }
  std::sort(angles.begin(), angles.end());
  double gap = angles.front() + 2 * kPi - angles.back();
  for (std::size_t k = 1; k < angles.size(); ++k) gap = std::max(gap, angles[k] - angles[k - 1]);
  return 2 * kPi - gap;
}

// A cylinder: the axis is the direction the normals are all perpendicular to (the eigenvector
// of the smallest eigenvalue of sum n n^T), the circle a least-squares fit of the points
// projected across it (Kasa's algebraic fit), every point within `tolerance` of it and every
// normal radial.
AnalyticFit FitCylinder(const SurfaceSamples& s, double tolerance) {
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& n : s.normals) scatter += n * n.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  const Eigen::Vector3d axis = eigen.eigenvectors().col(0);
  for (const Eigen::Vector3d& n : s.normals) {
    if (std::abs(n.dot(axis)) > kNormalAngle) return {};
  }
  const Eigen::Vector3d x = axis.unitOrthogonal(), y = axis.cross(x);
  std::vector<Eigen::Vector2d> across;
  for (const Eigen::Vector3d& p : s.points) across.emplace_back(p.dot(x), p.dot(y));
  const FittedCircle circle = FitCircle(across);
  if (!(circle.radius > 0)) return {};
  AnalyticFit fit;
  fit.radius = circle.radius;
  fit.direction = axis;
  fit.point = circle.center.x() * x + circle.center.y() * y;
  int outward = 0;
  for (std::size_t k = 0; k < s.points.size(); ++k) {
    const Eigen::Vector3d d = s.points[k] - fit.point, radial = d - d.dot(axis) * axis;
    fit.error = std::max(fit.error, std::abs(radial.norm() - fit.radius));
    if (std::abs(std::abs(radial.normalized().dot(s.normals[k])) - 1) > kNormalAngle) return {};
    outward += radial.dot(s.normals[k]) > 0 ? 1 : -1;
  }
  if (fit.error > tolerance || std::abs(outward) != static_cast<int>(s.points.size())) return {};
  fit.kind = AnalyticFit::Kind::kCylinder;
  fit.outward = outward > 0;
  fit.coverage = Coverage(s, fit.point, axis);
  return fit;
}

// A sphere: |p|^2 + D . p + E = 0 by least squares over the points (the algebraic fit, as
// Kasa's for circles), every point within `tolerance` of it and every normal radial.
AnalyticFit FitSphere(const SurfaceSamples& s, double tolerance) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : s.points) mean += p / s.points.size();
  Eigen::MatrixXd A(s.points.size(), 4);
  Eigen::VectorXd b(s.points.size());
  for (std::size_t k = 0; k < s.points.size(); ++k) {
    const Eigen::Vector3d q = s.points[k] - mean;
    A.row(k) << q.x(), q.y(), q.z(), 1.0;
    b(k) = -q.squaredNorm();
  }
  const Eigen::Vector4d c = LinearLeastSquares(A, b);
  const Eigen::Vector3d centre = -0.5 * c.head<3>();
  const double r2 = centre.squaredNorm() - c(3);
  if (!(r2 > 0)) return {};
  AnalyticFit fit;
  fit.point = centre + mean;
  fit.radius = std::sqrt(r2);
  int outward = 0;
  for (std::size_t k = 0; k < s.points.size(); ++k) {
    const Eigen::Vector3d d = s.points[k] - fit.point;
    fit.error = std::max(fit.error, std::abs(d.norm() - fit.radius));
    if (std::abs(std::abs(d.normalized().dot(s.normals[k])) - 1) > kNormalAngle) return {};
    outward += d.dot(s.normals[k]) > 0 ? 1 : -1;
  }
  if (fit.error > tolerance || std::abs(outward) != static_cast<int>(s.points.size())) return {};
  fit.kind = AnalyticFit::Kind::kSphere;
  fit.direction = Eigen::Vector3d::UnitZ();
  fit.outward = outward > 0;
  return fit;
}

// A cone or a torus, the surfaces of revolution other than the cylinder and the sphere. Every
// normal line of a surface of revolution meets its axis: with Pluecker coordinates (d, m) of
// the axis and (n, q x n) of a normal line through q, n . m + d . (q x n) = 0, one linear
// equation per sample, so the axis is the null vector of those rows (the right singular vector
// of the smallest singular value). Each sample then has a height h along the axis and a
// radius r from it; the meridian (h, r) is a line for a cone (least squares) and a circle for
// a torus (Kasa's fit), every sample within `tolerance` of it and every normal square to it.
AnalyticFit FitRevolution(const SurfaceSamples& s, double tolerance) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : s.points) mean += p / s.points.size();
  double scale = 0.0;  // the samples' extent, so that the rows' two halves weigh alike
  for (const Eigen::Vector3d& p : s.points) scale = std::max(scale, (p - mean).norm());
  if (!(scale > 0)) return {};
  Eigen::MatrixXd rows(s.points.size(), 6);
  for (std::size_t k = 0; k < s.points.size(); ++k) {
    const Eigen::Vector3d q = (s.points[k] - mean) / scale;
    rows.row(k) << q.cross(s.normals[k]).transpose(), s.normals[k].transpose();
  }
  const Eigen::Matrix<double, 6, 1> v = LeastSingularVector(rows);
  if (v.head<3>().norm() < 1e-6) return {};
  const Eigen::Vector3d d = v.head<3>().normalized(), m = v.tail<3>() / v.head<3>().norm();
  const Eigen::Vector3d origin = mean + scale * d.cross(m);  // the axis' point nearest the mean
  // Each sample's height and radius, and its normal's components along them; a normal of a
  // surface of revolution lies in the sample's meridian plane.
  std::vector<Eigen::Vector2d> meridian, normals;
  for (std::size_t k = 0; k < s.points.size(); ++k) {
    const Eigen::Vector3d q = s.points[k] - origin;
    const double h = q.dot(d);
    const Eigen::Vector3d radial = q - h * d;
    const double r = radial.norm();
    if (r < tolerance) continue;  // a cone's apex: no radius to check its normal by
    const Eigen::Vector3d n = s.normals[k];
    if (std::abs(n.dot(d.cross(radial / r))) > kNormalAngle) return {};
    meridian.emplace_back(h, r);
    normals.emplace_back(n.dot(d), n.dot(radial / r));
  }
  if (meridian.size() < 6) return {};
  AnalyticFit fit;
  fit.direction = d;
  // A cone: r = a + b h by least squares.
  Eigen::MatrixXd A(meridian.size(), 2);
  Eigen::VectorXd b(meridian.size());
  for (std::size_t k = 0; k < meridian.size(); ++k) {
    A.row(k) << 1.0, meridian[k].x();
    b(k) = meridian[k].y();
  }
  const Eigen::Vector2d line = LinearLeastSquares(A, b);
  const Eigen::Vector2d tangent = Eigen::Vector2d(1, line(1)).normalized();
  const Eigen::Vector2d across(-tangent.y(), tangent.x());
  bool square = true;
  int outward = 0;
  for (std::size_t k = 0; k < meridian.size(); ++k) {
    fit.error = std::max(
        fit.error, std::abs(meridian[k].y() - line(0) - line(1) * meridian[k].x()) * tangent.x());
    square = square && std::abs(normals[k].dot(tangent)) < kNormalAngle;
    outward += normals[k].dot(across) > 0 ? 1 : -1;
  }
  if (std::abs(line(1)) > 1e-6 && fit.error <= tolerance && square &&
      std::abs(outward) == static_cast<int>(meridian.size())) {
    fit.kind = AnalyticFit::Kind::kCone;
    fit.point = origin - line(0) / line(1) * d;  // the apex, where r = 0
    if (line(1) < 0) fit.direction = -d;
    fit.semi_angle = std::atan(std::abs(line(1)));
    fit.outward = outward > 0;
    fit.coverage = Coverage(s, fit.point, d);
    return fit;
  }
  // A torus: the meridian a circle about (h0, R), the tube's centre line.
  // Its tube's centre line off the axis (else a sphere, tried before).
  const FittedCircle tube = FitCircle(meridian);
  if (!(tube.radius > 0) || !(tube.center.y() > tolerance)) return {};
  fit.error = 0.0;
  outward = 0;
  for (std::size_t k = 0; k < meridian.size(); ++k) {
    const Eigen::Vector2d out = meridian[k] - tube.center;
    fit.error = std::max(fit.error, std::abs(out.norm() - tube.radius));
    if (std::abs(std::abs(out.normalized().dot(normals[k])) - 1) > kNormalAngle) return {};
    outward += out.dot(normals[k]) > 0 ? 1 : -1;
  }
  if (fit.error > tolerance || std::abs(outward) != static_cast<int>(meridian.size())) return {};
  fit.kind = AnalyticFit::Kind::kTorus;
  fit.point = origin + tube.center.x() * d;
  fit.radius = tube.center.y();
  fit.outward = outward > 0;
  return fit;
}

// The exact surface a free-form face is, within `tolerance` mm, tried in the order plane (Open
// CASCADE's GeomLib_IsPlanarSurface for the surface itself), cylinder, sphere, then cone or
// torus, the first that fits unless a later one fits ten times closer (and the first is off
// by more than 1e-6 mm); kNone when it is none of them.
AnalyticFit FitAnalytic(const TopoDS_Face& face, const BRepAdaptor_Surface& surface,
                        double tolerance) {
  const SurfaceSamples s = SampleSurface(face, surface);
  if (s.points.size() < 9) return {};
  const GeomLib_IsPlanarSurface planar(BRep_Tool::Surface(face), tolerance);
  if (planar.IsPlanar()) {
    const gp_Pln plane = planar.Plan();
    AnalyticFit fit;
    fit.kind = AnalyticFit::Kind::kPlane;
    fit.point = ToEigen(plane.Location().XYZ());
    fit.direction = ToEigen(plane.Axis().Direction().XYZ());
    if (fit.direction.dot(s.normals[s.normals.size() / 2]) < 0) fit.direction = -fit.direction;
    for (const Eigen::Vector3d& p : s.points) {
      fit.error = std::max(fit.error, std::abs((p - fit.point).dot(fit.direction)));
    }
    return fit;
  }
  // The simplest kind that fits, unless a later one fits ten times closer: a narrow strip of
  // a cone (a bevel gear's tip land) is a cylinder within the tolerance, but not within its
  // cone's rounding.
  AnalyticFit best;
  for (auto* fitter : {FitCylinder, FitSphere, FitRevolution}) {
    const AnalyticFit fit = fitter(s, tolerance);
    if (fit.kind == AnalyticFit::Kind::kNone) continue;
    if (best.kind == AnalyticFit::Kind::kNone ||
        (best.error > 1e-6 && fit.error < 0.1 * best.error)) {
      best = fit;
    }
  }
  return best;
}

// What a cone is beside the solid's cylinders (a countersink at a hole's mouth, a conical end
// (a chamfer or a point) of a shaft, a flare widening out of a shaft, or a cone of its own),
// and its size.
struct ConeWords {
  std::string what, size;
};
ConeWords DescribeCone(const Cone& c, const std::vector<Feature>& features) {
  const double included = 2 * c.semi_angle * 180 / kPi;
  const std::string size = fmt::format("{} deg, diameter {} to {}", FormatNumber(included),
                                       FormatNumber(2 * c.r_min), Mm(2 * c.r_max));
  for (const Feature& f : features) {
    if (f.kind != (c.convex ? FeatureKind::kShaft : FeatureKind::kHole)) continue;
    const Eigen::Vector3d d = c.apex - f.origin;
    const double r = f.diameter / 2, tol = c.agree.Length(r);
    const bool coaxial = std::abs(std::abs(f.axis.dot(c.direction)) - 1) < c.agree.cosine &&
                         (d - d.dot(f.axis) * f.axis).norm() < tol;
    if (!coaxial) continue;
    if (!c.convex && std::abs(c.r_min - r) < tol) {
      return {fmt::format("countersink of {}", f.id), size};
    }
    if (c.convex && std::abs(c.r_max - r) < tol) {
      return {fmt::format("conical end of {}", f.id), size};
    }
    if (c.convex && std::abs(c.r_min - r) < tol) {
      return {fmt::format("conical flare of {} (a countersunk head's underside?)", f.id), size};
    }
  }
  return {c.convex ? "convex cone" : "concave cone", size};
}

// A pin standing out of a wall: a convex cylinder face covering from half a turn to the 270
// degrees that make a shaft. `base` is its axis' start, `length` along `direction`.
struct Pin {
  Eigen::Vector3d base, direction;
  double radius = 0.0, length = 0.0;
};

// Integral pin rings (a cycloidal reducer's housing with its pins cut in one piece): three or
// more pins of one radius, parallel and side by side along their axes, whose axes stand evenly
// around a circle (Kasa's fit within `tolerance` mm; every gap one pitch within `tolerance`
// along the circle), each ring a `pin_ring` feature (`teeth` pins, `diameter` the pin circle's).
std::vector<Feature> PinRings(std::vector<Pin> pins, double tolerance) {
  std::vector<Feature> rings;
  std::vector<bool> used(pins.size(), false);
  for (std::size_t i = 0; i < pins.size(); ++i) {
    if (used[i]) continue;
    const Eigen::Vector3d d = pins[i].direction;
    std::vector<Pin> ring;
    for (std::size_t j = i; j < pins.size(); ++j) {
      Pin p = pins[j];
      if (used[j] || std::abs(p.radius - pins[i].radius) > tolerance ||
          std::abs(std::abs(p.direction.dot(d)) - 1) > 1e-9) {
        continue;
      }
      if (p.direction.dot(d) < 0) {  // the same pin seen from its other end
        p.base += p.length * p.direction;
        p.direction = d;
      }
      const double a = p.base.dot(d) - pins[i].base.dot(d);
      if (a > pins[i].length - tolerance || a + p.length < tolerance) continue;  // not side by side
      ring.push_back(p);
      used[j] = true;
    }
    if (ring.size() < 3) continue;
    const Eigen::Vector3d u = d.unitOrthogonal(), v = d.cross(u);
    std::vector<Eigen::Vector2d> centres;
    for (const Pin& p : ring) centres.emplace_back(p.base.dot(u), p.base.dot(v));
    const FittedCircle circle = FitCircle(centres);
    if (circle.rms > tolerance || circle.radius <= ring.front().radius) continue;
    std::vector<double> angles;
    for (const Eigen::Vector2d& q : centres) {
      angles.push_back(std::atan2(q.y() - circle.center.y(), q.x() - circle.center.x()));
    }
    std::sort(angles.begin(), angles.end());
    const int n = static_cast<int>(angles.size());
    const double pitch = 2 * kPi / n;
    bool even = true;
    for (int k = 0; k < n; ++k) {
      const double gap = k + 1 < n ? angles[k + 1] - angles[k] : angles[0] + 2 * kPi - angles[k];
      even = even && std::abs(gap - pitch) * circle.radius <= tolerance;
    }
    if (!even) continue;
    double lo = 1e300, hi = -1e300;
    for (const Pin& p : ring) {
      lo = std::min(lo, p.base.dot(d));
      hi = std::max(hi, p.base.dot(d) + p.length);
    }
    Feature f;
    f.kind = FeatureKind::kPinRing;
    f.id = fmt::format("pins_{}", rings.size() + 1);
    f.origin = circle.center.x() * u + circle.center.y() * v + lo * d;
    f.axis = d;
    f.length = hi - lo;
    f.teeth = n;
    f.diameter = 2 * circle.radius;
    f.pin_diameter = 2 * ring.front().radius;
    rings.push_back(f);
  }
  return rings;
}

// The length of `solid`'s bounding box's diagonal, mm (1 for an empty solid).
double SizeOf(const TopoDS_Shape& solid) {
  Bnd_Box box;
  BRepBndLib::Add(solid, box);
  return box.IsVoid() ? 1.0 : std::sqrt(box.SquareExtent());
}

// The mesher's linear deflection for a solid of `size` (SizeOf), mm: 1/1000 of its size, and
// at least 0.01 mm. The mesh lies within it of the solid's faces.
double MeshDeflection(double size) { return std::max(0.01, 1e-3 * size); }

// The mesher's angular deflection, rad: no two neighbouring segments of an edge turn by more.
constexpr double kMeshAngle = 0.3;

// Meshes the faces of `solid` (within MeshDeflection of its `size`, SizeOf) and tells whether
// the mesher found none of the defects healing repairs: open, self-intersecting or misoriented
// wires, faces it could not mesh.
bool MeshedCleanly(const TopoDS_Shape& solid, double size) {
  const BRepMesh_IncrementalMesh mesher(solid, MeshDeflection(size), false, kMeshAngle, false);
  constexpr int kDefects = IMeshData_OpenWire | IMeshData_SelfIntersectingWire | IMeshData_Failure |
                           IMeshData_UnorientedWire | IMeshData_TooFewPoints;
  return (mesher.GetStatusFlags() & kDefects) == 0;
}

// The mesh and features of one solid of `size` (SizeOf), meshed (MeshedCleanly), in its
// product's frame, and notes on the faces that give no feature. Returns true when a spherical
// face's bounds enclose a negative area: the face covers its complement, its outer bound turned
// over. (Spherical faces are where it was seen, and their areas are measured anyway, to tell
// balls from caps: a sphere's seam running through a hole, as where a ball is fused with its
// cage, joins that hole to the outer bound, and the quick healing leaves the wires'
// orientation as read.)
bool ConvertSolid(const TopoDS_Shape& solid, double size, TriangleMesh* mesh,
                  std::vector<Feature>* features, std::vector<std::string>* notes) {
  bool bounds_turned_over = false;
  std::vector<Cylinder> cylinders;
  std::vector<Cone> cones;
  std::vector<Sphere> spheres;
  int planes = 0, tori = 0, free_form = 0, partial_cones = 0, partial_spheres = 0;
  // Free-form faces that are exact surfaces: within 1 um or 10 ppm of the solid's size.
  const double fit_tolerance = std::max(1e-3, 1e-5 * size);
  std::map<AnalyticFit::Kind, int> fitted;
  double fit_error = 0.0;
  std::map<std::tuple<double, double, double>, std::int32_t> positions;
  auto* welded = &positions;
  for (TopExp_Explorer e(solid, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face& face = TopoDS::Face(e.Current());
    TopLoc_Location location;
    const Handle(Poly_Triangulation) triangulation = BRep_Tool::Triangulation(face, location);
    if (triangulation.IsNull()) continue;
    const gp_Trsf trsf = location.Transformation();
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    // Faces share their edges' nodes: welded by exact position into one closed mesh.
    std::vector<Eigen::Vector3d> nodes;
    std::vector<std::int32_t> index;
    for (int i = 1; i <= triangulation->NbNodes(); ++i) {
      nodes.push_back(ToEigen(triangulation->Node(i).Transformed(trsf).XYZ()));
      const auto key = std::make_tuple(nodes.back().x(), nodes.back().y(), nodes.back().z());
      auto [it, added] = welded->emplace(key, static_cast<std::int32_t>(mesh->vertices.size()));
      if (added) mesh->vertices.push_back(nodes.back());
      index.push_back(it->second);
    }
    for (int i = 1; i <= triangulation->NbTriangles(); ++i) {
      int a, b, c;
      triangulation->Triangle(i).Get(a, b, c);
      if (reversed) std::swap(b, c);
      mesh->faces.push_back({index[a - 1], index[b - 1], index[c - 1]});
    }
    const BRepAdaptor_Surface surface(face);
    const GeomAbs_SurfaceType type = surface.GetType();
    const bool analytic = type == GeomAbs_Plane || type == GeomAbs_Cylinder ||
                          type == GeomAbs_Cone || type == GeomAbs_Sphere || type == GeomAbs_Torus;
    const AnalyticFit fit = analytic ? AnalyticFit() : FitAnalytic(face, surface, fit_tolerance);
    if (fit.kind != AnalyticFit::Kind::kNone) {
      ++fitted[fit.kind];
      fit_error = std::max(fit_error, fit.error);
    }
    const Agreement agree =
        analytic ? Agreement() : Agreement{fit_tolerance, 1 - std::cos(kNormalAngle)};
    if (type == GeomAbs_Cylinder || fit.kind == AnalyticFit::Kind::kCylinder) {
      Cylinder c;
      Cylinder::Span span;
      if (type == GeomAbs_Cylinder) {
        const gp_Cylinder g = surface.Cylinder();
        c.point = ToEigen(g.Location().XYZ());
        c.direction = ToEigen(g.Axis().Direction().XYZ()).normalized();
        c.radius = g.Radius();
        // The surface's normal points away from the axis for a right-handed frame; the face's
        // orientation says on which side the material is.
        c.convex = g.Position().Direct() != reversed;
        double u0, u1, v0, v1;
        BRepTools::UVBounds(face, u0, u1, v0, v1);
        span.coverage = std::min(u1 - u0, 2 * kPi);
      } else {
        c.point = fit.point;
        c.direction = fit.direction;
        c.radius = fit.radius;
        c.convex = fit.outward != reversed;
        span.coverage = fit.coverage;
      }
      for (const Eigen::Vector3d& p : nodes) {
        span.lo = std::min(span.lo, (p - c.point).dot(c.direction));
        span.hi = std::max(span.hi, (p - c.point).dot(c.direction));
      }
      // One cylinder split into several faces: merged.
      auto same = std::find_if(cylinders.begin(), cylinders.end(), [&](const Cylinder& o) {
        const Eigen::Vector3d d = c.point - o.point;
        const Agreement both = agree.With(o.agree);
        return std::abs(o.radius - c.radius) < both.Length(c.radius) &&
               std::abs(std::abs(o.direction.dot(c.direction)) - 1) < both.cosine &&
               (d - d.dot(o.direction) * o.direction).norm() < both.Length(c.radius) &&
               o.convex == c.convex;
      });
      if (same == cylinders.end()) {
        c.spans.push_back(span);
        c.agree = agree;
        cylinders.push_back(c);
      } else {
        same->agree = same->agree.With(agree);
        const double sign = same->direction.dot(c.direction) > 0 ? 1 : -1;
        const double shift = (c.point - same->point).dot(same->direction);
        same->spans.push_back({shift + (sign > 0 ? span.lo : -span.hi),
                               shift + (sign > 0 ? span.hi : -span.lo), span.coverage});
      }
    } else if (type == GeomAbs_Cone || fit.kind == AnalyticFit::Kind::kCone) {
      Cone c;
      if (type == GeomAbs_Cone) {
        const gp_Cone g = surface.Cone();
        c.apex = ToEigen(g.Apex().XYZ());
        c.direction = ToEigen(g.Axis().Direction().XYZ()).normalized();
        c.semi_angle = std::abs(g.SemiAngle());
        if (g.SemiAngle() < 0) c.direction = -c.direction;  // it narrows along its axis
        // As for a cylinder: the surface's normal points away from the axis in a direct frame.
        c.convex = g.Position().Direct() != reversed;
        double u0, u1, v0, v1;
        BRepTools::UVBounds(face, u0, u1, v0, v1);
        c.coverage = std::min(u1 - u0, 2 * kPi);
      } else {
        c.apex = fit.point;
        c.direction = fit.direction;
        c.semi_angle = fit.semi_angle;
        c.convex = fit.outward != reversed;
        c.coverage = fit.coverage;
      }
      for (const Eigen::Vector3d& p : nodes) {
        const Eigen::Vector3d d = p - c.apex;
        const double r = (d - d.dot(c.direction) * c.direction).norm();
        c.r_min = std::min(c.r_min, r);
        c.r_max = std::max(c.r_max, r);
      }
      auto same = std::find_if(cones.begin(), cones.end(), [&](const Cone& o) {
        const Agreement both = agree.With(o.agree);
        return (o.apex - c.apex).norm() < both.Length(c.r_max) &&
               o.direction.dot(c.direction) > 1 - both.cosine &&
               std::abs(o.semi_angle - c.semi_angle) < std::acos(1 - both.cosine) &&
               o.convex == c.convex;
      });
      if (same == cones.end()) {
        c.agree = agree;
        cones.push_back(c);
      } else {
        same->agree = same->agree.With(agree);
        same->coverage += c.coverage;
        same->r_min = std::min(same->r_min, c.r_min);
        same->r_max = std::max(same->r_max, c.r_max);
      }
    } else if (type == GeomAbs_Sphere || fit.kind == AnalyticFit::Kind::kSphere) {
      Sphere sphere;
      if (type == GeomAbs_Sphere) {
        const gp_Sphere g = surface.Sphere();
        sphere.center = ToEigen(g.Location().XYZ());
        sphere.radius = g.Radius();
        // As for a cylinder: the surface's normal points outward in a direct frame.
        sphere.convex = g.Position().Direct() != reversed;
      } else {
        sphere.center = fit.point;
        sphere.radius = fit.radius;
        sphere.convex = fit.outward != reversed;
      }
      GProp_GProps properties;
      BRepGProp::SurfaceProperties(face, properties);
      sphere.area = properties.Mass();
      bounds_turned_over = bounds_turned_over || sphere.area < 0;
      auto same = std::find_if(spheres.begin(), spheres.end(), [&](const Sphere& o) {
        const Agreement both = agree.With(o.agree);
        return (o.center - sphere.center).norm() < both.Length(sphere.radius) &&
               std::abs(o.radius - sphere.radius) < both.Length(sphere.radius) &&
               o.convex == sphere.convex;
      });
      if (same == spheres.end()) {
        sphere.agree = agree;
        spheres.push_back(sphere);
      } else {
        same->agree = same->agree.With(agree);
        same->area += sphere.area;
      }
    } else if (type == GeomAbs_Torus || fit.kind == AnalyticFit::Kind::kTorus) {
      ++tori;
    } else if (type != GeomAbs_Plane && fit.kind != AnalyticFit::Kind::kPlane) {
      ++free_form;
    } else if (!nodes.empty()) {
      Eigen::Vector3d n, x;
      if (type == GeomAbs_Plane) {
        const gp_Pln plane = surface.Plane();
        n = ToEigen(plane.Axis().Direction().XYZ());
        x = ToEigen(plane.XAxis().Direction().XYZ());
      } else {
        n = fit.direction;
        x = n.unitOrthogonal();
      }
      if (reversed) n = -n;
      const Eigen::Vector3d y = n.cross(x);
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (const Eigen::Vector3d& p : nodes) centre += p / nodes.size();
      double xl = 1e300, xh = -1e300, yl = 1e300, yh = -1e300;
      for (const Eigen::Vector3d& p : nodes) {
        xl = std::min(xl, (p - centre).dot(x)), xh = std::max(xh, (p - centre).dot(x));
        yl = std::min(yl, (p - centre).dot(y)), yh = std::max(yh, (p - centre).dot(y));
      }
      Feature f;
      f.id = fmt::format("face_{}", ++planes);
      f.kind = FeatureKind::kFace;
      f.origin = centre + 0.5 * (xl + xh) * x + 0.5 * (yl + yh) * y;
      f.axis = n.normalized();
      f.width = xh - xl;
      f.height = yh - yl;
      features->push_back(f);
    }
  }
  int shafts = 0, holes = 0;
  std::vector<Pin> pins;
  for (const Cylinder& c : cylinders) {
    for (const Cylinder::Span& s : Stretches(c.spans, fit_tolerance)) {
      if (c.convex && s.coverage >= kPi && s.coverage < 1.5 * kPi) {
        pins.push_back({c.point + s.lo * c.direction, c.direction, c.radius, s.hi - s.lo});
      }
      if (s.coverage < 1.5 * kPi) continue;  // a fillet or a partial cylinder
      Feature f;
      f.kind = c.convex ? FeatureKind::kShaft : FeatureKind::kHole;
      f.id = c.convex ? fmt::format("shaft_{}", ++shafts) : fmt::format("hole_{}", ++holes);
      f.origin = c.point + s.lo * c.direction;
      f.axis = c.direction;
      f.length = s.hi - s.lo;
      f.diameter = 2 * c.radius;
      f.through = !c.convex;
      features->push_back(f);
    }
  }
  for (Feature& ring : PinRings(pins, fit_tolerance)) features->push_back(std::move(ring));
  // A sphere whose faces cover at least half of it is a ball (convex) or a socket (concave);
  // smaller caps (a rounded end, a dome) are counted in the notes.
  int balls = 0, sockets = 0;
  for (const Sphere& sphere : spheres) {
    // Half a sphere or more, to rounding (a fitted sphere's area to twice its fit's relative
    // error).
    const double rounding = std::max(1e-6, 2 * sphere.agree.length / sphere.radius);
    if (sphere.area < 2 * kPi * sphere.radius * sphere.radius * (1 - rounding)) {
      ++partial_spheres;
      continue;
    }
    Feature f;
    f.kind = sphere.convex ? FeatureKind::kBall : FeatureKind::kSocket;
    f.id = sphere.convex ? fmt::format("ball_{}", ++balls) : fmt::format("socket_{}", ++sockets);
    f.origin = sphere.center;
    f.axis = Eigen::Vector3d::UnitZ();  // a sphere has none; the format's default direction
    f.diameter = 2 * sphere.radius;
    features->push_back(f);
  }
  // The format has no cone or torus kind: these faces are named in notes.
  // Alike cones (a bore countersunk at both ends) are one note, in the order first found.
  std::vector<std::pair<ConeWords, int>> described;
  for (const Cone& c : cones) {
    if (c.coverage < 1.5 * kPi) {
      ++partial_cones;
      continue;
    }
    const ConeWords words = DescribeCone(c, *features);
    auto alike = std::find_if(described.begin(), described.end(), [&](const auto& d) {
      return d.first.what == words.what && d.first.size == words.size;
    });
    if (alike == described.end()) {
      described.emplace_back(words, 1);
    } else {
      ++alike->second;
    }
  }
  for (const auto& [words, n] : described) {
    notes->push_back(n == 1 ? fmt::format("{}: {}", words.what, words.size)
                            : fmt::format("{} ({} alike): {}", words.what, n, words.size));
  }
  auto count = [&](int n, const std::string& what) {
    if (n > 0) {
      notes->push_back(fmt::format("{} {} {}: no feature (the format has no such kind)", n, what,
                                   n == 1 ? "face" : "faces"));
    }
  };
  if (!fitted.empty()) {
    int total = 0;
    std::vector<std::string> kinds;
    const std::map<AnalyticFit::Kind, std::array<const char*, 2>> names = {
        {AnalyticFit::Kind::kPlane, {"plane", "planes"}},
        {AnalyticFit::Kind::kCylinder, {"cylinder", "cylinders"}},
        {AnalyticFit::Kind::kCone, {"cone", "cones"}},
        {AnalyticFit::Kind::kSphere, {"sphere", "spheres"}},
        {AnalyticFit::Kind::kTorus, {"torus", "tori"}}};
    for (const auto& [kind, n] : fitted) {
      total += n;
      kinds.push_back(fmt::format("{} {}", n, names.at(kind)[n == 1 ? 0 : 1]));
    }
    notes->push_back(fmt::format("{} free-form {} taken as exact surfaces: {} (within {})", total,
                                 total == 1 ? "face" : "faces", fmt::join(kinds, ", "),
                                 Mm(std::ceil(fit_error * 1e4) / 1e4)));  // to 0.1 um, up
  }
  count(partial_cones, "partial conical");
  count(partial_spheres, "partial spherical");
  count(tori, "toroidal");
  count(free_form, "free-form");
  return bounds_turned_over;
}

// Where CollectingPrinter puts the messages sent on this thread, if not in its own list.
thread_local std::vector<StepMessage>* thread_messages = nullptr;

// Keeps Open CASCADE's messages about the file (which its default printer writes on stdout, in
// the middle of reports): those of warning gravity and above, and the reader's "*** ERR"
// reports, which it sends as traces and information (the entity and the reference it misses,
// then a count of unresolved references). Progress traces are dropped. Whitespace runs and
// "***" become single spaces.
class CollectingPrinter : public Message_Printer {
 public:
  explicit CollectingPrinter(std::vector<StepMessage>* messages) : messages_(messages) {
    SetTraceLevel(Message_Trace);
  }

 protected:
  void send(const TCollection_AsciiString& text, const Message_Gravity gravity) const override {
    const std::string raw = text.ToCString();
    const bool error = gravity >= Message_Fail || raw.find("ERR ") != std::string::npos;
    if (!error && gravity < Message_Warning) return;
    std::string line;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      const bool stars = raw.compare(i, 3, "***") == 0;
      if (stars || std::isspace(static_cast<unsigned char>(raw[i]))) {
        if (!line.empty() && line.back() != ' ') line += ' ';
        if (stars) i += 2;
      } else {
        line += raw[i];
      }
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    if (line.empty()) return;
    (thread_messages ? thread_messages : messages_)->push_back({error, line});
  }

 private:
  std::vector<StepMessage>* messages_;
};

// While alive, the messages CollectingPrinter receives on this thread go to `messages`.
class ThreadMessages {
 public:
  explicit ThreadMessages(std::vector<StepMessage>* messages) { thread_messages = messages; }
  ~ThreadMessages() { thread_messages = nullptr; }
  ThreadMessages(const ThreadMessages&) = delete;
  ThreadMessages& operator=(const ThreadMessages&) = delete;
};

// While alive, Open CASCADE's default messenger sends to a CollectingPrinter instead of its
// own printers (restored on destruction, also when reading throws).
class MessageCapture {
 public:
  explicit MessageCapture(std::vector<StepMessage>* messages)
      : messenger_(Message::DefaultMessenger()), saved_(messenger_->Printers()) {
    messenger_->ChangePrinters().Clear();
    messenger_->AddPrinter(new CollectingPrinter(messages));
  }
  ~MessageCapture() { messenger_->ChangePrinters() = saved_; }
  MessageCapture(const MessageCapture&) = delete;
  MessageCapture& operator=(const MessageCapture&) = delete;

 private:
  Handle(Message_Messenger) messenger_;
  Message_SequenceOfPrinters saved_;
};

// While alive, this thread handles signals on a stack of its own, so that an endless recursion
// can be caught (each thread needs its own; the previous one comes back on destruction).
class AlternateSignalStack {
 public:
  AlternateSignalStack() : stack_(kStackSize) {
    stack_t alternate{};
    alternate.ss_sp = stack_.data();
    alternate.ss_size = stack_.size();
    sigaltstack(&alternate, &saved_);
  }
  ~AlternateSignalStack() { sigaltstack(&saved_, nullptr); }
  AlternateSignalStack(const AlternateSignalStack&) = delete;
  AlternateSignalStack& operator=(const AlternateSignalStack&) = delete;

 private:
  static constexpr std::size_t kStackSize = 1 << 18;
  std::vector<char> stack_;
  stack_t saved_{};
};

// While alive, Open CASCADE's handlers catch the signals of a crash (segmentation and bus
// faults, illegal instructions, floating-point traps), on a stack of their own, so that an
// endless recursion (an edge loop of a damaged file that refers to itself) is caught too. They
// replace whatever handler was set, a sanitizer's or a fuzzer's too: a crash of Open CASCADE on
// a damaged file is bad input there as well, not a finding. The price: while a file is read,
// a segmentation fault of our own code in this file (the faces' features) is reported as a file
// that cannot be read, not by the sanitizer (its other reports, of memory misuse caught by its
// checks, still come). The previous handlers and stack come back on destruction.
class SignalsAsExceptions {
 public:
  SignalsAsExceptions() {
    for (std::size_t k = 0; k < kSignals.size(); ++k) {
      struct sigaction fallback {};
      fallback.sa_handler = SIG_DFL;
      sigaction(kSignals[k], &fallback, &saved_[k]);
    }
    OSD::SetSignal(OSD_SignalMode_SetUnhandled, Standard_False);
    for (std::size_t k = 0; k < kSignals.size(); ++k) {
      struct sigaction action;
      sigaction(kSignals[k], nullptr, &action);
      action.sa_flags |= SA_ONSTACK;
      sigaction(kSignals[k], &action, nullptr);
    }
  }
  ~SignalsAsExceptions() {
    for (std::size_t k = 0; k < kSignals.size(); ++k) sigaction(kSignals[k], &saved_[k], nullptr);
  }
  SignalsAsExceptions(const SignalsAsExceptions&) = delete;
  SignalsAsExceptions& operator=(const SignalsAsExceptions&) = delete;

 private:
  static constexpr std::array<int, 4> kSignals = {SIGSEGV, SIGBUS, SIGILL, SIGFPE};
  std::array<struct sigaction, 4> saved_{};
  AlternateSignalStack stack_;  // this thread's; the converting threads set up their own
};

// The tolerances Open CASCADE's reader heals a shape with (the file's uncertainty, and the
// largest tolerance healing may set).
struct Healing {
  double precision = 0.0;
  double max_tolerance = 0.0;
};

// While alive, Open CASCADE's reader leaves the shapes it reads unhealed and records, for each
// solid, the tolerances it would have healed it with (HealedSolid heals it later): healing
// (mostly computing the curves of edges on faces, which some exporters, Onshape among them,
// leave out) is most of the transfer's time, and done per solid it runs in parallel. Writing
// and the reading of other formats are untouched.
class DeferredHealing : public XSAlgo_AlgoContainer {
 public:
  DeferredHealing() : previous_(XSAlgo::AlgoContainer()) {}
  ~DeferredHealing() override = default;

  // Reading: records the tolerances for each solid of `shape` and returns it as read. Writing:
  // the previous processing.
  TopoDS_Shape ProcessShape(const TopoDS_Shape& shape, const Standard_Real precision,
                            const Standard_Real max_tolerance, const Standard_CString resources,
                            const Standard_CString sequence, Handle(Standard_Transient) & info,
                            const Message_ProgressRange& progress,
                            const Standard_Boolean non_manifold) const override {
    if (std::string_view(sequence).rfind("read.", 0) != 0) {
      return previous_->ProcessShape(shape, precision, max_tolerance, resources, sequence, info,
                                     progress, non_manifold);
    }
    for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) {
      healing_[e.Current().TShape().get()] = {precision, max_tolerance};
    }
    return shape;
  }

  // How the reader would have healed `solid` (its default when it did not say).
  Healing Of(const TopoDS_Shape& solid) const {
    const auto found = healing_.find(solid.TShape().get());
    return found == healing_.end() ? Healing{Precision::Confusion(), 1.0} : found->second;
  }

  const Handle(XSAlgo_AlgoContainer) & previous() const { return previous_; }

 private:
  Handle(XSAlgo_AlgoContainer) previous_;
  mutable std::map<const TopoDS_TShape*, Healing> healing_;
};

// While alive, `deferred` is the reader's processing; the previous one comes back after.
class HealingDeferred {
 public:
  explicit HealingDeferred(const Handle(DeferredHealing) & deferred) : deferred_(deferred) {
    XSAlgo::SetAlgoContainer(deferred_);
  }
  ~HealingDeferred() { XSAlgo::SetAlgoContainer(deferred_->previous()); }
  HealingDeferred(const HealingDeferred&) = delete;
  HealingDeferred& operator=(const HealingDeferred&) = delete;

 private:
  Handle(DeferredHealing) deferred_;
};

// `solid` healed as Open CASCADE's reader heals what it reads by default (XSAlgo_AlgoContainer::
// ProcessShape without a resource file: ShapeFix_Shape, same-parameter fixes of wires off, no
// open solids made); unless `thorough`, without the checks that only a damaged solid needs and
// that take half of healing's time (on the robot hand): of the orientation of wires, faces,
// shells and the solid, and of edges that intersect. The mesh tells when they were needed
// (ConvertAll).
TopoDS_Shape HealedSolid(const TopoDS_Shape& solid, const Healing& healing, bool thorough) {
  Handle(ShapeFix_Shape) fix = new ShapeFix_Shape(solid);
  fix->SetPrecision(healing.precision);
  fix->SetMaxTolerance(healing.max_tolerance);
  const Handle(ShapeFix_Face) faces = fix->FixFaceTool();
  const Handle(ShapeFix_Wire) wires = faces->FixWireTool();
  wires->FixSameParameterMode() = Standard_False;
  fix->FixSolidTool()->CreateOpenSolidMode() = Standard_False;
  if (!thorough) {
    fix->FixSolidTool()->FixShellOrientationMode() = 0;
    fix->FixShellTool()->FixOrientationMode() = 0;
    faces->FixOrientationMode() = 0;
    wires->FixSelfIntersectionMode() = 0;
    wires->FixSelfIntersectingEdgeMode() = 0;
    wires->FixIntersectingEdgesMode() = 0;
    wires->FixNonAdjacentIntersectingEdgesMode() = 0;
  }
  fix->Perform();
  return fix->Shape().IsNull() ? solid : fix->Shape();
}

// Walks an XCAF document's products to their solids (Walk), then heals and converts each
// product's solids once (ConvertAll).
class Walker {
 public:
  Walker(Handle(XCAFDoc_ShapeTool) tool, std::vector<StepSolid>* out) : tool_(tool), out_(out) {}

  void Walk(const TDF_Label& label, const std::string& path, const TopLoc_Location& location) {
    if (tool_->IsAssembly(label)) {
      TDF_LabelSequence components;
      tool_->GetComponents(label, components);
      // An instance without a name of its own adds nothing to its assembly's path, unless
      // other such instances of the assembly hold solids too: each is then named by what it
      // refers to (two unnamed instances of the products body1 and body2, as Solid Edge writes
      // them), not told apart by a number.
      std::vector<TDF_Label> referred(components.Length());
      int unnamed_solids = 0;
      for (int i = 1; i <= components.Length(); ++i) {
        tool_->GetReferredShape(components(i), referred[i - 1]);
        unnamed_solids += InstanceName(NameOf(components(i))).empty() &&
                          TopExp_Explorer(tool_->GetShape(referred[i - 1]), TopAbs_SOLID).More();
      }
      std::map<std::string, int> seen;
      for (int i = 1; i <= components.Length(); ++i) {
        std::string name = InstanceName(NameOf(components(i)));
        if (name.empty() && unnamed_solids > 1) name = InstanceName(NameOf(referred[i - 1]));
        name = Sanitised(name);
        if (!name.empty() && ++seen[name] > 1) name += fmt::format("_{}", seen[name]);
        Walk(referred[i - 1],
             name.empty()   ? path
             : path.empty() ? name
                            : fmt::format("{}.{}", path, name),
             location * tool_->GetLocation(components(i)));
      }
      return;
    }
    const TopoDS_Shape shape = tool_->GetShape(label);
    const std::size_t first = out_->size();
    int index = 0;
    const std::string named = path.empty() ? Sanitised(NameOf(label)) : path;
    if (!TopExp_Explorer(shape, TopAbs_SOLID).More() && !named.empty() &&
        std::find(no_solid_.begin(), no_solid_.end(), named) == no_solid_.end()) {
      no_solid_.push_back(named);
    }
    for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next(), ++index) {
      const auto [cached, added] =
          definition_of_.emplace(std::make_pair(label.Tag(), index), definitions_.size());
      if (added) {
        definitions_.push_back({e.Current(), std::make_shared<TriangleMesh>(), {}, {}, {}, 0.0});
      }
      StepSolid s;
      s.path = index == 0 ? path : fmt::format("{}_solid{}", path, index + 1);
      s.product = NameOf(label);
      s.X_WP = ToRigid(location.Transformation());
      s.mesh = definitions_[cached->second].mesh;
      out_->push_back(std::move(s));
      definition_of_solid_.push_back(cached->second);
    }
    // The instance's solids, one CAD part of several bodies: marked by the instance's number
    // until the paths are unique (ReadSolids names it then).
    ++instances_;
    if (index > 1) {
      for (std::size_t k = first; k < out_->size(); ++k) {
        (*out_)[k].body_of = std::to_string(instances_);
      }
    }
  }

  // The paths of the product instances walked that hold no solid, in walking order.
  const std::vector<std::string>& no_solid() const { return no_solid_; }

  // Heals (as `healing` says) and converts each product's solid walked (once for all its
  // instances), in parallel, and gives
  // every solid walked its features and notes; Open CASCADE's messages meanwhile go to
  // `messages` in the order of the solids, whichever thread sent them. Rethrows the
  // Standard_Failure of the first solid, in walking order, on which Open CASCADE failed or
  // crashed. `converted` receives the fraction of the faces converted after each solid.
  void ConvertAll(const DeferredHealing& healing, std::vector<StepMessage>* messages,
                  const StepProgress& converted) {
    std::vector<std::size_t> faces(definitions_.size(), 0);
    for (std::size_t d = 0; converted && d < definitions_.size(); ++d) {
      for (TopExp_Explorer e(definitions_[d].solid, TopAbs_FACE); e.More(); e.Next()) ++faces[d];
    }
    const double all_faces = std::max<double>(1, std::accumulate(faces.begin(), faces.end(), 0.0));
    std::mutex reporting;
    std::size_t faces_converted = 0;
    ParallelFor(definitions_.size(), [&](std::size_t d) {
      Definition& definition = definitions_[d];
      const AlternateSignalStack stack;
      OCC_CATCH_SIGNALS
      // Healed quickly, then thoroughly when the mesh shows a defect that the checks left out
      // would have repaired: the mesher's, two faces running along an edge the same way (a
      // face turned over), or the solid inside out; or when a spherical face's bounds are
      // turned over (ConvertSolid).
      for (const bool thorough : {false, true}) {
        definition.messages.clear();
        const ThreadMessages redirect(&definition.messages);
        *definition.mesh = TriangleMesh();
        definition.features.clear();
        definition.notes.clear();
        const TopoDS_Shape healed =
            HealedSolid(definition.solid, healing.Of(definition.solid), thorough);
        const double size = SizeOf(healed);
        definition.deviation = MeshDeflection(size);
        const bool clean = MeshedCleanly(healed, size);
        const bool bounds_turned_over = ConvertSolid(healed, size, definition.mesh.get(),
                                                     &definition.features, &definition.notes);
        const MeshCheck check = CheckMesh(*definition.mesh);
        if (thorough || (clean && !bounds_turned_over && check.consistently_oriented() &&
                         check.signed_volume > 0)) {
          break;
        }
        BRepTools::Clean(definition.solid);  // the first try's face meshes
      }
      if (converted) {
        const std::lock_guard<std::mutex> lock(reporting);
        faces_converted += faces[d];
        converted(faces_converted / all_faces);
      }
    });
    for (const Definition& definition : definitions_) {
      messages->insert(messages->end(), definition.messages.begin(), definition.messages.end());
    }
    for (std::size_t k = 0; k < out_->size(); ++k) {
      const Definition& definition = definitions_[definition_of_solid_[k]];
      (*out_)[k].features = definition.features;
      (*out_)[k].notes = definition.notes;
      (*out_)[k].mesh_deviation = definition.deviation;
      (*out_)[k].mesh_angle = kMeshAngle;
    }
  }

 private:
  Handle(XCAFDoc_ShapeTool) tool_;
  std::vector<StepSolid>* out_;
  int instances_ = 0;  // product instances walked
  // A product's solid, converted once for all its instances.
  struct Definition {
    TopoDS_Shape solid;
    std::shared_ptr<TriangleMesh> mesh;
    std::vector<Feature> features;
    std::vector<std::string> notes;
    std::vector<StepMessage> messages;  // Open CASCADE's, while converting it
    double deviation = 0.0;             // of the mesh from the faces, mm (MeshDeflection)
  };
  std::vector<Definition> definitions_;
  std::map<std::pair<int, int>, std::size_t> definition_of_;  // by label tag and solid index
  std::vector<std::size_t> definition_of_solid_;              // of each solid in out_
  std::vector<std::string> no_solid_;  // the paths of the instances without a solid
};

// The first error report of Open CASCADE's reader, which usually names the entity at fault.
std::string FirstError(const std::vector<StepMessage>& messages) {
  for (const StepMessage& m : messages) {
    if (!m.error) continue;
    // Its parser frames a report in stars ("* ERR StepFile : ... *").
    std::string_view text = m.text;
    while (!text.empty() && (text.front() == '*' || text.front() == ' ')) text.remove_prefix(1);
    while (!text.empty() && (text.back() == '*' || text.back() == ' ')) text.remove_suffix(1);
    return fmt::format("; the reader reported: {}", text);
  }
  return "";
}

// The whole text of `file`; empty when it cannot be read.
std::string FileText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Open CASCADE's reports of references to entities the file does not define ("ERR
// StepReaderData Entite #-4 Type:/* (SUB) */ Param.n0 2: #46449 Not found", one per reference,
// a nested list numbered as an entity of its own; then "Unresolved Reference : Fails Count :
// N") replaced, where the first of them stood, by one message per reference that names the
// entity holding it (UndefinedReferences on `file`'s text), or by the reports' own words when
// the scanner does not read the file.
void NameUndefinedReferences(const std::filesystem::path& file,
                             std::vector<StepMessage>* messages) {
  static const std::regex kNotFound(
      R"(ERR StepReaderData Entite (#-?\d+) Type:(.*) Param\.n0 \d+: (#\d+) Not found)");
  const auto is_report = [](const StepMessage& m) {
    return std::regex_match(m.text, kNotFound) ||
           m.text.find("Unresolved Reference") != std::string::npos;
  };
  const auto first = std::find_if(messages->begin(), messages->end(), is_report);
  if (first == messages->end()) return;
  const auto reference = [](std::string_view entity, std::string_view type,
                            std::string_view missing) {
    return StepMessage{true, fmt::format("{} {} refers to {}", entity, type, missing), true};
  };
  std::vector<StepMessage> named;
  const std::string text = FileText(file);
  if (const std::optional<Part21Records> records = ReadPart21Records(text)) {
    for (const Part21UndefinedReference& r : UndefinedReferences(*records, text)) {
      named.push_back(reference(r.entity, r.type, r.missing));
    }
  }
  if (named.empty()) {
    for (const StepMessage& m : *messages) {
      std::smatch match;
      if (std::regex_match(m.text, match, kNotFound)) {
        named.push_back(reference(match[1].str(), match[2].str(), match[3].str()));
      }
    }
  }
  const std::ptrdiff_t at = first - messages->begin();
  std::erase_if(*messages, is_report);
  messages->insert(messages->begin() + at, named.begin(), named.end());
}

// What the reader's `messages` say went wrong, for an error's end: the references to
// entities the file does not define (UndefinedReferenceWords), or else its first error report.
std::string Fault(const std::vector<StepMessage>& messages) {
  const std::string undefined = UndefinedReferenceWords(messages);
  return undefined.empty() ? FirstError(messages) : "; it has " + undefined;
}

// What a status of the reader's ReadFile says about `file`: first what its text shows (no
// STEP file at all, or one cut short), which the parser's report does not say in so many
// words ("Line 2: Incorrect syntax: unexpected TYPE, expecting STEP").
std::string ReadFailure(IFSelect_ReturnStatus status, const std::filesystem::path& file) {
  const std::string text = FileText(file);
  constexpr std::string_view kStart = "ISO-10303-21;", kEnd = "END-ISO-10303-21;";
  const std::size_t start = text.find_first_not_of(" \t\r\n");
  if (start == std::string::npos || text.compare(start, kStart.size(), kStart) != 0) {
    std::string found = text.substr(start == std::string::npos ? 0 : start, 24);
    found = found.substr(0, found.find_first_of("\r\n"));
    const bool printable = std::all_of(found.begin(), found.end(), [](char c) {
      return std::isprint(static_cast<unsigned char>(c));
    });
    return fmt::format(
        "expected a STEP file, beginning \"{}\", found {}", kStart,
        printable ? fmt::format("one beginning \"{}\"", found) : "bytes that are no text");
  }
  if (text.find(kEnd) == std::string::npos) {
    const auto lines = std::count(text.begin(), text.end(), '\n') + (text.back() != '\n');
    return fmt::format("it stops after {} lines without \"{}\": the file is cut short", lines,
                       kEnd);
  }
  switch (status) {
    case IFSelect_RetVoid:
      return "it holds no STEP data";
    case IFSelect_RetError:
      return "it is not valid STEP (a syntax error, or a header without a known schema)";
    default:
      return "the reader failed";
  }
}

// The part files that `reader`'s assembly file (`file`) refers to and that gave no shape (a
// multi-file export, each part in a file of its own, with one missing or damaged), each with
// its DOCUMENT_FILE entity, where it was looked for (as Open CASCADE's reader does: beside
// `file`, unless the reference is absolute) and why it gave nothing; sorted.
std::vector<std::string> UnreadPartFiles(const STEPCAFControl_Reader& reader,
                                         const std::filesystem::path& file) {
  const Handle(XSControl_WorkSession) session = reader.Reader().WS();
  STEPConstruct_ExternRefs references(session);
  references.LoadExternRefs();
  std::vector<std::string> unread;
  for (int i = 1; i <= references.NbExternRefs(); ++i) {
    const char* name = references.FileName(i);
    Handle(STEPCAFControl_ExternFile) part;
    if (name == nullptr || !reader.ExternFile(name, part) || part.IsNull()) continue;
    if (part->GetLoadStatus() == IFSelect_RetDone && !part->GetLabel().IsNull()) continue;
    const std::filesystem::path path = file.parent_path() / name;
    const std::string why = !std::filesystem::exists(path)              ? "no such file"
                            : part->GetLoadStatus() != IFSelect_RetDone ? "not readable as STEP"
                                                                        : "it holds no shape";
    const Handle(StepBasic_DocumentFile) entity = references.DocFile(i);
    const std::string where =
        entity.IsNull() ? "" : fmt::format("#{} DOCUMENT_FILE; ", session->Model()->Number(entity));
    unread.push_back(fmt::format("'{}' ({}looked for at {}: {})", name, where,
                                 path.lexically_normal().string(), why));
  }
  std::sort(unread.begin(), unread.end());
  unread.erase(std::unique(unread.begin(), unread.end()), unread.end());
  return unread;
}

// The shares of a STEP file's reading done once it is parsed and once its shapes are
// transferred (as they are on the robot hand, the largest real export); healing and meshing the
// solids take the rest.
constexpr double kParsed = 0.12;
constexpr double kTransferred = 0.18;

// The name of the length unit `unit`, lower case ("inch", "millimetre"), or empty when it is
// none.
std::string LengthUnitName(const Handle(StepBasic_NamedUnit) & unit) {
  if (const auto converted = Handle(StepBasic_ConversionBasedUnitAndLengthUnit)::DownCast(unit);
      !converted.IsNull() && !converted->Name().IsNull()) {
    return AsciiLower(converted->Name()->ToCString());
  }
  const auto si = Handle(StepBasic_SiUnitAndLengthUnit)::DownCast(unit);
  if (si.IsNull() || si->Name() != StepBasic_sunMetre) return "";
  static const char* const kPrefixes[] = {"exa",   "peta", "tera",  "giga",  "mega",  "kilo",
                                          "hecto", "deca", "deci",  "centi", "milli", "micro",
                                          "nano",  "pico", "femto", "atto"};
  const auto prefix = static_cast<std::size_t>(si->Prefix());
  return std::string(si->HasPrefix() && prefix < std::size(kPrefixes) ? kPrefixes[prefix] : "") +
         "metre";
}

// The length units of every representation context in `model`, in the order of the file,
// each once: the top product's and those of parts that carry their own (Open CASCADE's
// FileUnits reads the top products' only).
std::vector<std::string> LengthUnits(const Interface_InterfaceModel& model) {
  std::vector<std::string> units;
  for (int i = 1; i <= model.NbEntities(); ++i) {
    const Handle(Standard_Transient)& entity = model.Value(i);
    Handle(StepRepr_GlobalUnitAssignedContext) context =
        Handle(StepRepr_GlobalUnitAssignedContext)::DownCast(entity);
    if (const auto geometric = Handle(
            StepGeom_GeometricRepresentationContextAndGlobalUnitAssignedContext)::DownCast(entity);
        !geometric.IsNull()) {
      context = geometric->GlobalUnitAssignedContext();
    } else if (const auto with_uncertainty =
                   Handle(StepGeom_GeomRepContextAndGlobUnitAssCtxAndGlobUncertaintyAssCtx)::
                       DownCast(entity);
               !with_uncertainty.IsNull()) {
      context = with_uncertainty->GlobalUnitAssignedContext();
    }
    if (context.IsNull()) continue;
    for (int u = 1; u <= context->NbUnits(); ++u) {
      std::string name = LengthUnitName(context->UnitsValue(u));
      if (!name.empty() && std::find(units.begin(), units.end(), name) == units.end()) {
        units.push_back(std::move(name));
      }
    }
  }
  return units;
}

// The solids of `file`; `messages` (Open CASCADE's, collected while reading) name the entity
// at fault when it cannot be read. `progress` and `length_units` as ReadStep's.
std::vector<StepSolid> ReadSolids(const std::filesystem::path& file,
                                  std::vector<StepMessage>* messages, const StepProgress& progress,
                                  std::vector<std::string>* length_units) {
  const auto report = [&progress](double fraction) {
    if (progress) progress(fraction);
  };
  Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
  Handle(TDocStd_Document) document;
  app->NewDocument("MDTV-XCAF", document);
  STEPCAFControl_Reader reader;  // initialises the reader's processing (XSAlgo) first
  reader.SetNameMode(true);
  reader.ChangeReader().WS()->SetLibrary(new Part21WorkLibrary);
  const Handle(DeferredHealing) healing = new DeferredHealing();
  const HealingDeferred deferred(healing);
  const IFSelect_ReturnStatus status = reader.ReadFile(file.string().c_str());
  NameUndefinedReferences(file, messages);
  if (status != IFSelect_RetDone) {
    app->Close(document);
    throw std::runtime_error(fmt::format("cannot read it as STEP (AP203, AP214 or AP242): {}{}",
                                         ReadFailure(status, file), FirstError(*messages)));
  }
  report(kParsed);
  if (length_units) *length_units = LengthUnits(*reader.ChangeReader().WS()->Model());
  if (!reader.Transfer(document)) {
    app->Close(document);
    throw std::runtime_error(
        fmt::format("cannot read it as STEP (AP203, AP214 or AP242): its entities give no shape{}",
                    Fault(*messages)));
  }
  // Parts left out would change the answer unseen (free bolts where the nuts went missing).
  if (const std::vector<std::string> unread = UnreadPartFiles(reader, file); !unread.empty()) {
    app->Close(document);
    throw std::runtime_error(fmt::format(
        "it refers to part files (an assembly exported one file per part), and {} cannot be "
        "read: {}",
        unread.size() == 1 ? "one" : std::to_string(unread.size()), fmt::join(unread, ", ")));
  }
  report(kTransferred);
  const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(document->Main());
  TDF_LabelSequence roots;
  tool->GetFreeShapes(roots);
  std::vector<StepSolid> solids;
  Walker walker(tool, &solids);
  for (int i = 1; i <= roots.Length(); ++i) {
    walker.Walk(roots(i), Sanitised(NameOf(roots(i))), TopLoc_Location());
  }
  walker.ConvertAll(*healing, messages,
                    progress ? StepProgress([&report](double converted) {
                      report(kTransferred + (1 - kTransferred) * converted);
                    })
                             : StepProgress());
  app->Close(document);
  if (solids.empty()) throw std::runtime_error("the STEP file holds no solid");
  // An instance without a solid whose path holds solids is no product left without one: an
  // unnamed component beside a solid takes its parent's path (AS1 gives each part such a
  // component, an empty compound). An unnamed product instance that lost its solid beside
  // others that hold theirs is not told from it.
  static const std::regex kBodyOf("_solid[0-9]+");
  for (const std::string& path : walker.no_solid()) {
    const bool holds_solids = std::any_of(solids.begin(), solids.end(), [&](const StepSolid& s) {
      return s.path == path || s.path.rfind(path + ".", 0) == 0 ||
             (s.path.rfind(path, 0) == 0 && std::regex_match(s.path.substr(path.size()), kBodyOf));
    });
    if (holds_solids) continue;
    StepMessage m;
    m.text = path;
    m.no_solid = true;
    messages->push_back(std::move(m));
  }
  // Unique paths (two solids named alike at the top level).
  std::map<std::string, int> count;
  for (StepSolid& s : solids) {
    if (++count[s.path] > 1) s.path += fmt::format("_{}", count[s.path]);
  }
  // The bodies of one instance take its first solid's (unique) path as their part's name.
  std::map<std::string, std::string> first_path;
  for (StepSolid& s : solids) {
    if (!s.body_of.empty()) s.body_of = first_path.emplace(s.body_of, s.path).first->second;
  }
  report(1.0);
  return solids;
}

}  // namespace

std::string UndefinedReferenceWords(const std::vector<StepMessage>& messages) {
  std::vector<std::string> references;
  for (const StepMessage& m : messages) {
    if (m.undefined_reference) references.push_back(m.text);
  }
  if (references.empty()) return "";
  const std::size_t shown = std::min<std::size_t>(3, references.size());
  return fmt::format(
      "{} {} to entities the file does not define ({}{}): it is damaged or cut short",
      references.size(), references.size() == 1 ? "reference" : "references",
      fmt::join(references.begin(), references.begin() + shown, "; "),
      references.size() > shown ? "; ..." : "");
}

std::vector<StepSolid> ReadStep(const std::filesystem::path& file,
                                std::vector<StepMessage>* messages, const StepProgress& progress,
                                std::vector<std::string>* length_units) {
  if (!std::filesystem::exists(file)) throw std::runtime_error("no such file");
  if (std::filesystem::is_regular_file(file) && std::filesystem::file_size(file) == 0) {
    throw std::runtime_error("the file is empty");
  }
  std::vector<StepMessage> ignored;
  std::vector<StepMessage>& kept = messages ? *messages : ignored;
  const MessageCapture capture(&kept);
  const SignalsAsExceptions signals;
  try {
    OCC_CATCH_SIGNALS
    return ReadSolids(file, &kept, progress, length_units);
  } catch (const Standard_Failure& failure) {
    // A crash inside Open CASCADE (a null entity of a damaged file dereferenced) or one of its
    // exceptions: the file cannot be read, and the process goes on.
    const char* what = failure.GetMessageString();
    throw std::runtime_error(
        fmt::format("Open CASCADE failed reading it ({}{}){}", failure.DynamicType()->Name(),
                    what && *what ? fmt::format(": {}", what) : std::string(), Fault(kept)));
  }
}

}  // namespace mechanist
