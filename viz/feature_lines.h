#pragma once

#include <Eigen/Core>
#include <vector>

#include "kernel/assembly/part.h"

namespace mechanist {

/// The lines that draw a part's features (the seeds' auxiliary lines), in the part's frame (mm),
/// each a polyline of two or more points: every feature's axis segment except a face's (a plane
/// has no axis), lengthened at both ends by a quarter of the feature's size so that it shows
/// outside the material. With `pitch_circles` (a features-only part, drawn by these lines
/// alone), also every gear's and worm wheel's pitch circle and every pin ring's pin circle at
/// its mid-face (72 segments), so that a kinematic sketch shows which axes mesh.
std::vector<std::vector<Eigen::Vector3d>> FeatureLines(const Part& part, bool pitch_circles);

}  // namespace mechanist
