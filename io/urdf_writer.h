#pragma once

#include <string>

#include "kernel/assembly/assembly.h"
#include "reasoning/analysis.h"
#include "reasoning/simulation_model.h"

namespace mechanist {

/// The URDF text of `model` (analysed from `assembly`): a link per SimLink (massless links
/// between the freedoms of a pair with several), joints with their axes, origins and limits
/// (continuous where nothing stops a hinge), couplings of two joints as `<mimic>`, and as
/// comments what URDF cannot express: couplings of three joints, cut loops, drivers and the
/// model's notes. Meshes are referred to as `mesh_dir`/NAME.stl, relative to the URDF file.
std::string UrdfText(const Assembly& assembly, const Analysis& analysis,
                     const SimulationModel& model, const std::string& mesh_dir);

}  // namespace mechanist
