#include "viz/display_colors.h"

#include <array>

namespace mechanist {

DisplayColors ColorParts(const Analysis& analysis) {
  // Tableau 10 without its red (kept for clashes) and grey (kept for the ground).
  static const std::array<Eigen::Vector3d, 8> kPalette = {
      Eigen::Vector3d(0.122, 0.467, 0.706), Eigen::Vector3d(1.000, 0.498, 0.055),
      Eigen::Vector3d(0.173, 0.627, 0.173), Eigen::Vector3d(0.580, 0.404, 0.741),
      Eigen::Vector3d(0.549, 0.337, 0.294), Eigen::Vector3d(0.890, 0.467, 0.761),
      Eigen::Vector3d(0.737, 0.741, 0.133), Eigen::Vector3d(0.090, 0.745, 0.812)};
  const Eigen::Vector3d ground(0.62, 0.62, 0.60);
  DisplayColors colors;
  colors.part.assign(analysis.subassembly_of.size(), ground);
  std::size_t next = 0;
  for (const Subassembly& s : analysis.subassemblies) {
    if (s.ground) continue;
    const Eigen::Vector3d& c = kPalette[next++ % kPalette.size()];
    for (const std::size_t p : s.parts) colors.part[p] = c;
  }
  return colors;
}

}  // namespace mechanist
