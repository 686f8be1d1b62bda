// Spheres and faces: a ball in its socket, planar face contacts.

#include <fmt/format.h>

#include "reasoning/internal/recognizer.h"

namespace mechanist::internal {

void Recognizer::BallSocket(const WorldFeature& b, const WorldFeature& s) {
  const double offset = (b.axis.origin - s.axis.origin).norm();
  const double difference = std::abs(b.f.diameter - s.f.diameter);
  if (offset <= L_ && difference <= L_) {
    AddPair(PairType::kSpherical, b, s);
  } else if (offset < std::min(b.f.diameter, s.f.diameter) / 2) {
    Near("ball_socket_mismatch", b, s,
         fmt::format("centres {} apart and diameters {} and {} (required same centre and diameter "
                     "within {})",
                     Mm(offset), Mm(b.f.diameter), Mm(s.f.diameter), Mm(L_)));
  }
}

void Recognizer::FaceFace(const WorldFeature& x, const WorldFeature& y) {
  const Eigen::Vector3d& n1 = x.axis.direction;
  const Eigen::Vector3d& n2 = y.axis.direction;
  if (n1.dot(n2) >= 0 || AngleBetweenLines(n1, n2) > A_) return;
  const Eigen::Vector3d d = y.axis.origin - x.axis.origin;
  if (std::abs(d.dot(n1)) > L_) return;
  auto extent = [](const Feature& f) { return std::hypot(f.width, f.height) / 2; };
  if (x.f.width > 0 && x.f.height > 0 && y.f.width > 0 && y.f.height > 0) {
    const double in_plane = (d - d.dot(n1) * n1).norm();
    if (in_plane >= extent(x.f) + extent(y.f) - L_) return;
  }
  const bool swap = NameLess(y, x);
  const std::string& body_of = assembly_.part(x.ref.part).body_of;
  if (!body_of.empty() && body_of == assembly_.part(y.ref.part).body_of) {
    // Bodies of one CAD part (a multi-body part exported as several solids) that touch face to
    // face are one piece of it.
    AddPair(PairType::kFixed, swap ? y : x, swap ? x : y);
    pairs_.back().source = PairSource::kOnePart;
    return;
  }
  AddPair(PairType::kPlanar, swap ? y : x, swap ? x : y);
}

}  // namespace mechanist::internal
