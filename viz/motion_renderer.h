#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "kernel/assembly/assembly.h"
#include "kernel/mesh/triangle_mesh.h"
#include "reasoning/analysis.h"
#include "reasoning/animation.h"
#include "viz/image.h"

namespace mechanist {

/// Where the camera looks from: iso (+x, -y, +z towards the centre), front (from -y), top (from
/// +z), side (from +x); z is up except from the top, where y is.
enum class View { kIso, kFront, kTop, kSide };

/// "iso", "front", "top", "side"; nothing for another name.
std::optional<View> ParseView(std::string_view name);

/// How to render.
struct RenderOptions {
  int width = 800;   ///< pixels
  int height = 600;  ///< pixels
  View view = View::kIso;
  bool feature_axes = true;  ///< draw every feature's axis as a thin line
  std::string title;         ///< before each frame's label; empty: the assembly's name
};

/// Renders the frames of an animation off screen (VTK behind this facade): parts coloured by
/// subassembly (ColorParts), ground parts muted, parts in a clash red from their first
/// contact on, feature axes as thin lines moving with their parts, a title with the assembly
/// name and the frame's label (driver angle or travel). The camera frames the union of the
/// parts' world boxes over all frames and stays put. With `gap_surface_W` the gaps' walls are
/// drawn opaque and the parts translucent, so that gaps inside show. Needs an X display
/// (DisplayAvailable, which also keeps the server from resetting between renderers); throws
/// std::runtime_error without one, std::invalid_argument for a size below 16 or above 8192 pixels.
class MotionRenderer {
 public:
  MotionRenderer(const Assembly& assembly, const Analysis& analysis, const Animation& animation,
                 const RenderOptions& options, const TriangleMesh* gap_surface_W = nullptr);
  ~MotionRenderer();
  MotionRenderer(const MotionRenderer&) = delete;
  MotionRenderer& operator=(const MotionRenderer&) = delete;

  /// The image of frame `frame` (< animation.frame_count()).
  Image Render(std::size_t frame);
  /// Where p_W (world, mm) appears in the images: column and row from the top-left, pixels.
  Eigen::Vector2d PixelOf(const Eigen::Vector3d& p_W) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mechanist
