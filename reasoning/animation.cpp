#include "reasoning/animation.h"

#include <algorithm>
#include <stdexcept>

namespace mechanist {

Animation SampleRun(const Assembly& assembly, const MotionRun& run, std::size_t frames) {
  if (frames == 0) throw std::invalid_argument("SampleRun: at least one frame is needed");
  Animation animation;
  animation.run = run;
  animation.clash_from.assign(assembly.parts().size(), std::nullopt);
  for (std::size_t k = 0; k < frames; ++k) {
    const double s = FrameParameter(run, k, frames);
    animation.s.push_back(s);
    animation.states.push_back(StateAt(assembly, run, s));
    animation.labels.push_back(DescribeParameter(assembly, run, s));
  }
  return animation;
}

void MarkClashes(const std::vector<PartContact>& contacts, const OperationCheck& check,
                 Animation* animation) {
  auto mark = [&](std::size_t part, double at) {
    auto& from = animation->clash_from[part];
    from = from ? std::min(*from, at) : at;
  };
  for (const PartContact& c : contacts) {
    if (c.verdict != ContactVerdict::kClash) continue;
    mark(c.part_a, 0.0);
    mark(c.part_b, 0.0);
  }
  for (const OperationClash& c : check.clashes) {
    mark(c.part_a, c.at);
    mark(c.part_b, c.at);
  }
}

}  // namespace mechanist
