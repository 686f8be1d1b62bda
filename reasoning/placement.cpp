#include "reasoning/placement.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "kernel/solvers/least_squares.h"
#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// A feature's axis in the world (origin, unit direction, length) and its part's pose.
struct Target {
  const Feature* f;
  RigidTransform X_WQ;
  Vector3d origin, axis;
  Vector3d Mid() const { return origin + 0.5 * f->length * axis; }
};

Target TargetOf(const AssemblySpec& spec, FeatureRef ref) {
  const Part& q = spec.parts[ref.part];
  const Feature& f = q.features[ref.feature];
  return {&f, q.X_WP, q.X_WP * f.origin, q.X_WP.RotateDirection(f.axis)};
}

// The shortest rotation taking unit u to unit v; for opposite vectors the half turn about the
// part's x axis made perpendicular to u (its y when x is along u), so that the choice is the
// same on every machine.
Matrix3d Shortest(const Vector3d& u, const Vector3d& v) {
  if (u.dot(v) > -1.0 + 1e-12) return ShortestRotation(u, v);
  Vector3d w = Vector3d::UnitX() - u.x() * u;
  if (w.norm() < 1e-6) w = Vector3d::UnitY() - u.y() * u;
  return Eigen::AngleAxisd(M_PI, w.normalized()).toRotationMatrix();
}

// The rotation taking the orthonormal frame (u, v, u x v) to (U, V, U x V).
Matrix3d Align(const Vector3d& u, const Vector3d& v, const Vector3d& U, const Vector3d& V) {
  Matrix3d local, world;
  local << u, v, u.cross(v);
  world << U, V, U.cross(V);
  return world * local.transpose();
}

// Unit vector perpendicular to `axis`, from `x` (or `y` when x is along the axis).
Vector3d Radial(const Vector3d& axis, const Vector3d& x, const Vector3d& y) {
  Vector3d e = x - x.dot(axis) * axis;
  if (e.norm() < 1e-9) e = y - y.dot(axis) * axis;
  return e.normalized();
}

// What a mesh condition asks for: the own feature's world axis and mid-face centre (and a
// rack's tooth normal).
struct MeshGoal {
  Vector3d axis, mid;
  std::optional<Vector3d> normal;
};

MeshGoal MeshTarget(const Part& part, const PlacementCondition& c, const Target& t) {
  const Feature& own = part.features[c.feature];
  const Feature& tf = *t.f;
  auto is = [](const Feature& f, FeatureKind k) { return f.kind == k; };
  const bool ok = (is(own, FeatureKind::kGear) && is(tf, FeatureKind::kGear)) ||
                  (is(own, FeatureKind::kBevelGear) && is(tf, FeatureKind::kBevelGear)) ||
                  (is(own, FeatureKind::kWormWheel) && is(tf, FeatureKind::kWorm)) ||
                  (is(own, FeatureKind::kWorm) && is(tf, FeatureKind::kWormWheel)) ||
                  (is(own, FeatureKind::kRack) && is(tf, FeatureKind::kGear)) ||
                  (is(own, FeatureKind::kGear) && is(tf, FeatureKind::kRack));
  if (!ok) {
    throw std::invalid_argument(
        fmt::format("cannot mesh a {} with a {}", ToString(own.kind), ToString(tf.kind)));
  }
  MeshGoal g;
  const Vector3d e0 = Radial(t.axis, t.X_WQ.RotateDirection(Vector3d::UnitX()),
                             t.X_WQ.RotateDirection(Vector3d::UnitY()));
  const Vector3d e = std::cos(c.angle) * e0 + std::sin(c.angle) * t.axis.cross(e0);
  if (is(own, FeatureKind::kBevelGear)) {
    // Apex on apex, the axis tilted from the target's toward `e` by the sum of the pitch
    // angles; PoseFor puts the point half a face width up the own axis at `mid`.
    const double shaft_angle = own.pitch_angle + tf.pitch_angle;
    g.axis = std::cos(shaft_angle) * t.axis + std::sin(shaft_angle) * e;
    g.mid = t.origin + 0.5 * own.length * g.axis;
    return g;
  }
  const double a = MeshCentreDistance(own, tf);
  if (is(tf, FeatureKind::kRack)) {  // a pinion on a rack, at the rack's middle
    const Vector3d n = t.X_WQ.RotateDirection(tf.normal).normalized();
    g.axis = t.axis.cross(n);
    g.mid = t.Mid() + a * n;
    return g;
  }
  g.mid = t.Mid() + a * e;
  g.axis = t.axis;
  if (is(own, FeatureKind::kWorm) || is(own, FeatureKind::kWormWheel) ||
      is(own, FeatureKind::kRack)) {
    g.axis = t.axis.cross(e);
  }
  if (is(own, FeatureKind::kRack)) g.normal = -e;
  return g;
}

// The pose that makes the own feature (local origin o, axis u, length L) take axis U with its
// mid-face at M (and a rack's normal n to N).
RigidTransform PoseFor(const Feature& own, const MeshGoal& g) {
  const Matrix3d R = g.normal
                         ? Align(own.axis.normalized(), own.normal.normalized(), g.axis, *g.normal)
                         : Shortest(own.axis.normalized(), g.axis);
  const Vector3d mid_P = own.origin + 0.5 * own.length * own.axis.normalized();
  return RigidTransform(R, g.mid - R * mid_P);
}

double DefaultDepth(const Feature& own, const Feature& target) {
  return std::min(own.length, target.length);
}

// The closed-form pose for one condition.
RigidTransform ClosedForm(const AssemblySpec& spec, const Part& part, const PlacementCondition& c) {
  const Target t = TargetOf(spec, c.target);
  const Feature& own = part.features[c.feature];
  switch (c.kind) {
    case PlacementCondition::Kind::kInsert: {
      const Matrix3d R = Eigen::AngleAxisd(c.angle, t.axis).toRotationMatrix() *
                         Shortest(own.axis.normalized(), t.axis);
      const double depth = c.depth ? *c.depth : DefaultDepth(own, *t.f);
      return RigidTransform(R, t.origin + depth * t.axis - R * own.origin);
    }
    case PlacementCondition::Kind::kMesh:
      return PoseFor(own, MeshTarget(part, c, t));
    case PlacementCondition::Kind::kAgainst: {
      const Matrix3d R = Shortest(own.axis.normalized(), -t.axis);
      return RigidTransform(R, t.origin - R * own.origin);
    }
  }
  return RigidTransform();
}

// Residuals (mm) of one condition at pose X.
void Residuals(const AssemblySpec& spec, const Part& part, const PlacementCondition& c,
               const RigidTransform& X, std::vector<double>* r) {
  const Target t = TargetOf(spec, c.target);
  const Feature& own = part.features[c.feature];
  const double scale = std::max({own.length, own.diameter, t.f->length, 1.0});
  const Vector3d u = X.RotateDirection(own.axis.normalized());
  const Vector3d o = X * own.origin;
  auto push = [r](const Vector3d& v) { r->insert(r->end(), {v.x(), v.y(), v.z()}); };
  switch (c.kind) {
    case PlacementCondition::Kind::kInsert: {
      push(scale * (u - t.axis));  // collinear, same sense
      const Vector3d d = o - t.origin;
      push(d - d.dot(t.axis) * t.axis);
      if (c.depth) r->push_back(d.dot(t.axis) - *c.depth);
      break;
    }
    case PlacementCondition::Kind::kMesh: {
      const MeshGoal g = MeshTarget(part, c, t);
      push(scale * (u - g.axis));
      push(X * (own.origin + 0.5 * own.length * own.axis.normalized()) - g.mid);
      if (g.normal) push(scale * (X.RotateDirection(own.normal.normalized()) - *g.normal));
      break;
    }
    case PlacementCondition::Kind::kAgainst:
      push(scale * (u + t.axis));  // normals opposite
      r->push_back((o - t.origin).dot(t.axis));
      break;
  }
}

RigidTransform Solve(const AssemblySpec& spec, std::size_t index) {
  const Part& part = spec.parts[index];
  const RigidTransform X0 = ClosedForm(spec, part, part.placement.front());
  if (part.placement.size() == 1) return X0;
  auto pose = [&](const double* x) {
    const Vector3d w(x[0], x[1], x[2]);
    const Matrix3d R = w.norm() > 0 ? Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix()
                                    : Matrix3d::Identity();
    return RigidTransform(R * X0.rotation(), X0.translation() + Vector3d(x[3], x[4], x[5]));
  };
  std::vector<double> probe;
  for (const PlacementCondition& c : part.placement) Residuals(spec, part, c, X0, &probe);
  LeastSquaresProblem problem;
  problem.residuals = probe.size();
  problem.evaluate = [&](const double* x, double* out) {
    std::vector<double> r;
    const RigidTransform X = pose(x);
    for (const PlacementCondition& c : part.placement) Residuals(spec, part, c, X, &r);
    std::copy(r.begin(), r.end(), out);
    return true;
  };
  std::vector<double> x(6, 0.0);
  const LeastSquaresSummary summary = SolveLeastSquares(problem, &x);
  const double residual = std::sqrt(2.0 * summary.final_cost);
  if (summary.status == LeastSquaresSummary::Status::kFailure || residual > spec.tolerance.length) {
    throw PlacementError(index, fmt::format("the placement conditions of part \"{}\" cannot all "
                                            "hold: {} mm left after least squares ({})",
                                            part.id, FormatNumber(residual, 4), summary.message));
  }
  return pose(x.data());
}

}  // namespace

void ResolvePlacements(AssemblySpec* spec) {
  std::vector<bool> done(spec->parts.size(), false);
  std::function<void(std::size_t)> place = [&](std::size_t i) {
    if (done[i]) return;
    done[i] = true;
    Part& part = spec->parts[i];
    if (part.placement.empty()) return;
    for (const PlacementCondition& c : part.placement) place(c.target.part);
    try {
      part.X_WP = Solve(*spec, i);
    } catch (const PlacementError&) {
      throw;
    } catch (const std::invalid_argument& e) {
      throw PlacementError(i, fmt::format("part \"{}\" cannot be placed: {}", part.id, e.what()));
    }
  };
  for (std::size_t i = 0; i < spec->parts.size(); ++i) place(i);
}

}  // namespace mechanist
