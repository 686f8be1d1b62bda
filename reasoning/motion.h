#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/diagnostic.h"
#include "kernel/geometry/screw_path.h"
#include "kernel/support/compressed_rows.h"
#include "reasoning/exact_real.h"
#include "reasoning/pair.h"
#include "reasoning/pair_graph.h"

namespace mechanist {

/// How a part moves relative to the ground: not at all, turning about a line, sliding along a
/// direction, turning and advancing along one line (screw), or as a twist of a floating body.
enum class MotionKind { kNone, kRotation, kTranslation, kScrew };

/// "none", "rotation", "translation", "screw".
std::string_view ToString(MotionKind kind);

/// A feature's rates per unit driver rate (world frame, relative to the ground): revolutions
/// about its axis (right-hand rule) and the file's length units of its origin along its axis.
struct FeatureRate {
  ExactReal rotation;
  ExactReal translation;
  /// The expectation's "ratio" of a part that turns (rotation), else its translation.
  const ExactReal& Ratio(bool part_turns) const { return part_turns ? rotation : translation; }
};

/// A part's motion per unit driver rate.
struct PartMotion {
  MotionKind kind = MotionKind::kNone;
  /// Rotation axis or translation direction (unit, world). When a feature of the part has
  /// this axis, it is that feature's axis with its sense, and `axis_feature` names it.
  Eigen::Vector3d axis_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d point_W = Eigen::Vector3d::Zero();  ///< on the rotation or screw axis, mm
  std::optional<FeatureRef> axis_feature;
  ExactReal rotation;     ///< revolutions about axis_W
  ExactReal translation;  ///< the file's length units along axis_W
  /// The finite motion per unit driver parameter: the screws of the joints from the ground
  /// to this part at their rates (a planet turns on its pin while its carrier turns), so that
  /// the part's pose after s is path.At(s) * X_WP. Exact for gear, worm, screw and rack
  /// trains, whose ratios do not change as they move; a linkage's path is its motion
  /// continued at the ratios of the file pose. Lengths in mm.
  ScrewPath path;
};

/// The motion of every part when one driver runs at unit rate and the others are held, or when
/// all drivers run at their own rates (`driver` empty).
struct DrivenMotion {
  std::optional<std::size_t> driver;
  /// False when the drivers cannot run so (a locked driver, drivers that contradict each
  /// other, a worm gear driven from its wheel); `reason` says why and the parts stay still.
  bool possible = true;
  bool contradiction = false;  ///< not possible because drivers contradict each other
  std::string reason;
  std::vector<PartMotion> parts;         ///< per part
  CompressedRows<FeatureRate> features;  ///< per part: its features' rates, in feature order
};

/// Constraints of a pair implied by the other pairs (an over-constrained mechanism).
struct RedundantConstraint {
  std::size_t pair = 0;
  int count = 0;
};

/// A freedom that nothing drives or holds: one basis motion of the undriven mechanism.
struct FreeMotion {
  std::size_t part = 0;             ///< the part that makes the motion (MainPart of its body)
  std::optional<std::size_t> pair;  ///< the pair that allows it; empty: the part floats
  std::string freedom;              ///< "turns about shaft/axis", "slides along ..."
  std::vector<std::size_t> parts;   ///< parts that move with it, by part id
  /// An idle spin: the parts turn together about a line around which each is round (a wheel,
  /// a bearing, a spacer turning in place), so the motion moves nothing else.
  bool idle = false;
};

/// Mobility by the rank of the velocity constraints, which stays right for over-constrained
/// mechanisms where the Gruebler-Kutzbach count is wrong (a train with three planets).
struct Mobility {
  int dof = 0;        ///< independent freedoms with the drivers released
  int redundant = 0;  ///< constraint rows implied by the rows before them
  std::vector<RedundantConstraint> redundant_pairs;
  std::vector<FreeMotion> free_motions;  ///< with the drivers applied
  /// Of free_motions, those of parts held by face contacts alone (planar pairs: a part
  /// resting on faces whose fasteners the file leaves out).
  int on_faces = 0;
  /// Of free_motions, the idle spins (FreeMotion::idle): dof - idle counts the motions that
  /// change the assembly's shape, as a mechanism's mobility leaves out a roller's spin.
  int idle = 0;
  std::vector<int> part_freedoms;  ///< per part: dimension of its allowable motion
};

/// The velocity model an analysis solved (its kinematic model and constraint rows reduced
/// once), kept so that further imposed motions (a drag, a joint's range) are solved without
/// rebuilding it. Opaque; it refers to the analysed assembly, which must outlive it.
class MotionModel;

/// The motion analysis of an assembly at its file poses.
struct MotionAnalysis {
  Mobility mobility;
  /// One entry per driver (unit rate, others held), then, with several drivers, all of them
  /// at their rates (one driver at its rate is its unit-rate entry scaled, so it has no such
  /// entry); empty without drivers.
  std::vector<DrivenMotion> driven;
  /// Jams, free motions, redundant constraints, locked drivers, non-back-drivable worms.
  std::vector<Diagnostic> diagnostics;

  /// The model the analysis solved, for SolveImposed; shared by copies of the analysis.
  std::shared_ptr<const MotionModel> model;

  /// The motion an expectation's "ratio" refers to: the only driver's at unit rate, or all
  /// drivers at their rates (the last entry of `driven`); nullptr without drivers.
  const DrivenMotion* ForExpectations() const;
};

/// A motion imposed on a part, as a driver or by `mechanist drag`.
struct ImposedMotion {
  FeatureRef feature;  ///< the axis (the feature's, at the file pose)
  bool rotation = true;
  double rate = 1.0;                       ///< rev/s or mm/s
  std::optional<std::size_t> relative_to;  ///< part; empty: the ground
  /// False: the rate about (along) the axis' direction alone, as a driver imposes it. True, as
  /// a hand on the part means it: where the pairs leave a choice, the part turns about the
  /// axis' own line, not a parallel one (a finger's middle segment about its own hinge, not
  /// with the whole finger about the knuckle), and slides without turning. Each freedom that
  /// would move the line (turn the part) is held still, in the model's order, where the pairs
  /// allow it (a planet spun about its own axis still orbits with its carrier); the rates stay
  /// exact.
  bool about_line = false;
};

/// Velocity analysis (joint space, see KinematicModel) of the recognised `pairs`: mobility,
/// redundant constraints, jams, free motions and each driver's motion, exact where the
/// mechanism's ratios are rational (tooth counts, thread leads). `graph`: the pair graph of
/// `pairs` (its subassemblies are the bodies; the model keeps it for the walks of later
/// scenarios). `axes_W`: the features' world axes at the file's poses when recognition gave
/// them (see KinematicModel); empty: computed.
MotionAnalysis AnalyzeMotion(const Assembly& assembly, const std::vector<Pair>& pairs,
                             std::shared_ptr<const PairGraph> graph,
                             std::vector<AxisSegment> axes_W = {});

/// The motion when `imposed` run together (the first at its rate, the others as given) and
/// every free motion is held still, solved on `motion`'s model. Worm gears that are not
/// back-drivable lock when the motion enters them from the wheel. Throws std::invalid_argument
/// for a motion analysis without its model.
DrivenMotion SolveImposed(const MotionAnalysis& motion, const std::vector<ImposedMotion>& imposed);

}  // namespace mechanist
