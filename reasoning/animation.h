#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/assembly_state.h"
#include "reasoning/interference.h"
#include "reasoning/motion_run.h"
#include "reasoning/operation_check.h"

namespace mechanist {

/// A run of the mechanism sampled into frames: what every animation output (rendered frames,
/// video, ParaView series, glTF) shows, so that they all show the same poses.
struct Animation {
  MotionRun run;
  std::vector<double> s;              ///< per frame: the run's parameter (FrameParameter)
  std::vector<AssemblyState> states;  ///< per frame: StateAt(s)
  std::vector<std::string> labels;    ///< per frame: DescribeParameter(s)
  /// Per part: the parameter from which it is in a clash (0 for a clash at rest), or nothing.
  std::vector<std::optional<double>> clash_from;

  std::size_t frame_count() const { return s.size(); }
  /// True when part `part` is in a clash at frame `frame`.
  bool InClash(std::size_t part, std::size_t frame) const {
    return clash_from[part] && *clash_from[part] <= s[frame];
  }
};

/// Samples `run` into `frames` frames (at least 1). Throws std::invalid_argument for 0 frames.
Animation SampleRun(const Assembly& assembly, const MotionRun& run, std::size_t frames);

/// Marks the parts of the clashes at rest (contacts with the verdict kClash) and of the
/// running mechanism's clashes (from their first contact on) in `animation`.
void MarkClashes(const std::vector<PartContact>& contacts, const OperationCheck& check,
                 Animation* animation);

}  // namespace mechanist
