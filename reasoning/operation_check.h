#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/collision/collision_model.h"
#include "kernel/geometry/screw_path.h"
#include "reasoning/analysis.h"

namespace mechanist {

/// Two parts that come into contact while the mechanism runs.
struct OperationClash {
  std::size_t part_a = 0, part_b = 0;  ///< part indices, ordered by part id
  /// Driver parameter at the first contact: revolutions or file length units of the driver
  /// (time units when all drivers run together, each at its rate).
  double at = 0.0;
  double distance = 0.0;                          ///< mm between the surfaces there
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();  ///< where (world, mm, at that instant)
};

/// A contact of a moving part with a part that nothing drives or holds (a free motion): the
/// sweep settles what the pairs leave open.
struct InferredCoupling {
  std::size_t pusher = 0;  ///< the moving part
  std::size_t pushed = 0;  ///< the part of the free subassembly it meets
  double at = 0.0;         ///< driver parameter at the contact
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  /// True: the free subassembly yields (the push has a component along its free motion) and
  /// is carried along from there on. False: it cannot yield, a jam at `at`.
  bool carried = true;
};

/// The swept check of a running mechanism.
struct OperationCheck {
  std::optional<std::size_t> driver;  ///< nothing: all drivers together at their rates
  double amount = 1.0;                ///< how far it ran (units of `at`)
  bool possible = true;               ///< false when the drivers cannot run (see `reason`)
  std::string reason;
  std::vector<OperationClash> clashes;    ///< by `at`, then part ids
  std::vector<OperationClash> undecided;  ///< step budget exhausted while barely clear
  std::size_t pairs_swept = 0;
  /// Pairs of parts that move relative to each other but touch at rest (not recognised as a
  /// pair): not swept, since distance alone cannot tell them parting from pressing on.
  std::vector<std::pair<std::size_t, std::size_t>> touching_at_rest;
  /// Contacts with free subassemblies (the first for each), settled as couplings or jams.
  std::vector<InferredCoupling> inferred;
  /// The analysis with each carried coupling added as a `fixed` pair (source
  /// inferred_from_interference): the motion once the pushed parts are carried along. Empty
  /// when nothing was carried.
  std::optional<Analysis> after;
};

/// Whether the parts `a` and `b` are to be swept against each other.
using PartPairFilter = std::function<bool(std::size_t a, std::size_t b)>;

/// The sweep of CheckOperation along given paths (per part: the pose after s is
/// paths[p].At(s) * X_WP) over s in [0, amount], without settling free motions: the first
/// contact of each pair of parts that move relative to each other (clashes and undecided by
/// `at`), and the pairs touching at rest; with `swept`, only of the pairs it accepts. `driver`
/// is empty and `possible` true.
OperationCheck SweepPaths(const Assembly& assembly, const Analysis& analysis,
                          const CollisionModel& model, const std::vector<ScrewPath>& paths,
                          double amount, const PartPairFilter& swept = {});

/// Runs the mechanism from its file poses as PlanRun says (one driver in the sense of its rate,
/// or all drivers at their rates, over `amount` or the drivers' amounts) and sweeps every pair
/// of parts that move relative to each other (SweepMotion, contact within the file's length
/// tolerance) along the parts' paths (the joint screws from the ground, so a planet turns on
/// its pin while its carrier turns). Not checked: parts of one subassembly, parts joined by a
/// recognised pair (teeth of meshing gears, a shaft in its bearing: their contact is the
/// pair), and parts already in contact at rest (the static check reports those). Throws
/// std::invalid_argument as PlanRun does.
OperationCheck CheckOperation(const Assembly& assembly, const Analysis& analysis,
                              const CollisionModel& model, std::optional<std::size_t> driver,
                              std::optional<double> amount);

}  // namespace mechanist
