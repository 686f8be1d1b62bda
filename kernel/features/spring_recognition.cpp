#include "kernel/features/spring_recognition.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <vector>

#include "kernel/geometry/circle_fit.h"

namespace mechanist {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Sample {
  double t, rho, angle;  // along the axis, from it, about it
};

}  // namespace

std::optional<HelicalSpring> RecognizeHelicalSpring(const TriangleMesh& mesh) {
  const std::size_t n = mesh.vertices.size();
  if (n < 100 || mesh.faces.empty()) return std::nullopt;
  const std::size_t stride = std::max<std::size_t>(1, n / 4096);
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : mesh.vertices) centroid += v / static_cast<double>(n);
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& v : mesh.vertices) C += (v - centroid) * (v - centroid).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(C);
  const double volume = std::abs(mesh.SignedVolume());
  const double area = mesh.Area();
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d a = eigen.eigenvectors().col(k).normalized();
    // A coil's principal axis leans a little, and its centroid lies off the axis unless the
    // turns are whole: the axis through the centres of circles fitted (Kasa) to the lower and
    // the upper half of the vertices, twice.
    Eigen::Vector3d c = centroid;
    for (int round = 0; round < 2; ++round) {
      const Eigen::Vector3d u = a.unitOrthogonal(), w = a.cross(u);
      std::array<std::vector<Eigen::Vector2d>, 2> halves;
      std::array<double, 2> mid = {0.0, 0.0};
      for (std::size_t i = 0; i < n; i += stride) {
        const Eigen::Vector3d d = mesh.vertices[i] - c;
        const int half = d.dot(a) < 0 ? 0 : 1;
        halves[half].emplace_back(d.dot(u), d.dot(w));
        mid[half] += d.dot(a);
      }
      if (halves[0].size() < 3 || halves[1].size() < 3) break;
      std::array<Eigen::Vector3d, 2> centres;
      for (int h = 0; h < 2; ++h) {
        const FittedCircle circle = FitCircle(halves[h]);
        centres[h] = c + circle.center.x() * u + circle.center.y() * w +
                     mid[h] / static_cast<double>(halves[h].size()) * a;
      }
      if ((centres[1] - centres[0]).norm() == 0) break;
      a = (centres[1] - centres[0]).normalized();
      c = (centres[0] + centres[1]) / 2;
    }
    const Eigen::Vector3d u = a.unitOrthogonal(), w = a.cross(u);
    std::vector<Sample> samples;
    double rho_lo = 1e300, rho_hi = 0.0, t_lo = 1e300, t_hi = -1e300;
    for (std::size_t i = 0; i < n; i += stride) {
      const Eigen::Vector3d d = mesh.vertices[i] - c;
      const double t = d.dot(a), x = d.dot(u), y = d.dot(w);
      samples.push_back({t, std::hypot(x, y), std::atan2(y, x)});
      rho_lo = std::min(rho_lo, samples.back().rho);
      rho_hi = std::max(rho_hi, samples.back().rho);
      t_lo = std::min(t_lo, t);
      t_hi = std::max(t_hi, t);
    }
    const double wire = rho_hi - rho_lo, mean_radius = (rho_hi + rho_lo) / 2;
    const double length = t_hi - t_lo;
    // A spring's index (coil over wire) lies between 1 and 50; a rod or tube whose vertices
    // are all on its rims has next to no "wire".
    if (rho_lo < 0.25 * rho_hi || wire < 0.04 * mean_radius || wire >= mean_radius ||
        length < 1.5 * wire) {
      continue;
    }
    // The pitch: turns from 2.5 to (length - wire) / (0.95 wire) in twentieths, both hands, then
    // the best in two-hundredths (the peak is about a third of a turn wide: a phase error of 2 pi
    // x turns over the length).
    // Only the wire's outermost and innermost vertices (within a tenth of its radius of the
    // annulus' rims) lie on the helix through its centre; the others stand up to half the wire
    // above or below it, which would blur the phase of a close coil.
    std::erase_if(samples,
                  [&](const Sample& s) { return std::abs(s.rho - mean_radius) < 0.9 * wire / 2; });
    if (samples.size() < 16) continue;
    double best = 0.0, best_turns = 0.0, best_sign = 1.0;
    auto resultant = [&](double turns, double sign) {
      const double p = (length - wire) / turns;
      std::complex<double> sum = 0.0;
      for (const Sample& s : samples) sum += std::polar(1.0, 2 * kPi * (s.t / p) - sign * s.angle);
      const double r = std::abs(sum) / static_cast<double>(samples.size());
      if (r > best) {
        best = r;
        best_turns = turns;
        best_sign = sign;
      }
    };
    // A closely wound (extension) spring's coils touch: pitch = wire, or a little less where
    // the CAD model lets them overlap.
    const double most_turns = std::min((length - wire) / (0.95 * wire), 200.0);
    for (double turns = 2.5; turns <= most_turns; turns += 0.05) {
      resultant(turns, 1.0);
      resultant(turns, -1.0);
    }
    if (best_turns < 2.5) continue;  // too short for two and a half turns
    const double coarse = best_turns, sign = best_sign;
    for (int k = -10; k <= 10; ++k) resultant(std::max(2.5, coarse + 0.005 * k), sign);
    const double best_pitch = best_sign * (length - wire) / best_turns;
    if (best < 0.5) continue;
    const double pitch = std::abs(best_pitch), turns = (length - wire) / pitch;
    const double mean_diameter = 2 * mean_radius;
    const double wire_volume =
        kPi * wire * wire / 4 * turns * std::hypot(kPi * mean_diameter, pitch);
    // A wire's volume and surface (pi d times the helix' length), within 30% each.
    const double wire_area = kPi * wire * turns * std::hypot(kPi * mean_diameter, pitch);
    if (!(std::abs(volume - wire_volume) <= 0.3 * wire_volume) ||
        !(std::abs(area - wire_area) <= 0.3 * wire_area)) {
      continue;
    }
    HelicalSpring spring;
    spring.axis = a;
    spring.origin = c + t_lo * a;
    spring.length = length;
    spring.mean_diameter = mean_diameter;
    spring.wire_diameter = wire;
    spring.pitch = pitch;
    spring.turns = turns;
    // Right-handed: the phase t / p - angle is constant along the wire, so t grows with the
    // angle about +axis.
    spring.hand = best_pitch > 0 ? Hand::kRight : Hand::kLeft;
    return spring;
  }
  return std::nullopt;
}

}  // namespace mechanist
