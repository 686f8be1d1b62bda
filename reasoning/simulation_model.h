#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/collision/collision_model.h"
#include "kernel/mesh/triangle_mesh.h"
#include "reasoning/analysis.h"

namespace mechanist {

/// One mesh source of the simulator model, written once however many parts use it.
struct SimMesh {
  std::string name;  ///< a file name stem: the first part (by id) that uses it
  std::shared_ptr<const TriangleMesh> mesh;  ///< part coordinates, mm
};

/// A part drawn in a link: its mesh at its pose in the link frame.
struct SimVisual {
  std::size_t part = 0;
  std::size_t mesh = 0;  ///< index into SimulationModel::meshes
  Eigen::Matrix3d R_LP = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p_LP = Eigen::Vector3d::Zero();  ///< metres
};

/// A rigid body of the simulator: one subassembly (or the world when no part is ground). Its
/// frame L has the world's axes and its origin on the axis of the joint that moves it, so that
/// URDF's joint frame and the link frame coincide.
struct SimLink {
  std::string name;                   ///< the main part's id (the largest by volume), or "world"
  std::vector<std::size_t> parts;     ///< by part id
  bool ground = false;                ///< fixed to the world (the root)
  std::optional<std::size_t> parent;  ///< index into links; empty for the root
  Eigen::Vector3d p_WL = Eigen::Vector3d::Zero();   ///< frame origin, metres
  double mass = 0.0;                                ///< kg
  Eigen::Vector3d p_LCm = Eigen::Vector3d::Zero();  ///< centre of mass, metres
  Eigen::Matrix3d I_Cm = Eigen::Matrix3d::Zero();   ///< about the centre of mass, kg m^2
  /// True when no part gave mass (features-only parts, open meshes): mass and inertia are the
  /// small defaults kDefaultMass and kDefaultInertia.
  bool default_inertia = false;
  std::vector<std::size_t> open_parts;  ///< parts whose meshes are not closed: no mass
  std::vector<SimVisual> visuals;
};

/// One freedom of the simulator: a hinge (radians about `axis_W`), a slide (metres along it),
/// a ball (MJCF ball; URDF three hinges about the world axes) or a floating body (six
/// freedoms). A pair with several freedoms gives several consecutive joints moving one link
/// (a cylindrical pair: a hinge and a slide; a screw: a hinge and a slide coupled; a planar
/// pair: two slides and a hinge).
struct SimJoint {
  enum class Kind { kHinge, kSlide, kBall, kFree };
  std::string name;
  Kind kind = Kind::kHinge;
  std::size_t link = 0;  ///< the link it moves relative to that link's parent
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();      ///< on the axis, metres
  Eigen::Vector3d axis_W = Eigen::Vector3d::UnitZ();  ///< unit
  std::optional<std::size_t> pair;                    ///< the pair it comes from
  /// The movable range from the swept check: radians or metres in the joint's sense; empty
  /// where no contact bounds the motion (or the range was not searched).
  std::optional<double> lower, upper;
  /// For a limited joint: the parts that meet at each end (part indices).
  std::optional<std::pair<std::size_t, std::size_t>> lower_contact, upper_contact;
};

/// A coupling the simulator keeps as an equality: sum of coefficient * joint position = 0
/// (radians, metres), holonomic because gear, worm, rack, cycloidal and thread ratios do not
/// change as the mechanism moves.
struct SimCoupling {
  std::size_t pair = 0;  ///< the coupling pair, or the screw pair of a hinge and its slide
  std::vector<std::pair<std::size_t, double>> terms;  ///< (joint index, coefficient)
};

/// A pair off the spanning tree: the simulator closes the loop with an equality between its
/// links. Revolute pairs become two point constraints on the axis, spherical pairs one;
/// others have no MJCF equality (`anchors_W` empty) and are left open.
struct SimLoop {
  std::size_t pair = 0;
  std::size_t link_a = 0, link_b = 0;
  std::vector<Eigen::Vector3d> anchors_W;  ///< metres
};

/// A driver as the simulator's actuator: on the joint it turns or slides, or on the sum of the
/// parallel joints between its part and the part it moves against (a side gear held still
/// while it turns on a turning carrier: carrier + side gear = 0).
struct SimActuator {
  std::size_t driver = 0;
  /// (joint index, +1 or -1): the driver's rate is the sum of coefficient x joint rate. One
  /// term: an actuator on that joint. Empty: no joints of the tree move as the driver.
  std::vector<std::pair<std::size_t, double>> terms;
  double rate = 0.0;   ///< rad/s or m/s; 0 for a held driver
  std::string reason;  ///< why there are no joints

  /// rad/s or m/s: what the actuator runs at, its one joint's rate in that joint's own sense,
  /// or the rate of the sum of its terms.
  double ActingRate() const { return terms.size() == 1 ? terms.front().second * rate : rate; }
};

/// The analysed mechanism as a simulator sees it: links, a spanning tree of joints from the
/// ground, couplings, loop closures and actuators, in SI units (metres, kilograms, radians).
struct SimulationModel {
  std::vector<SimLink> links;    ///< the root first, then parents before children
  std::vector<SimJoint> joints;  ///< parents before children
  std::vector<SimMesh> meshes;
  std::vector<SimCoupling> couplings;
  std::vector<SimLoop> loops;
  std::vector<SimActuator> actuators;
  /// The assembly's bounding-box diagonal, metres: how far a slide that nothing stops may go.
  double reach = 0.0;
  /// What the model leaves out or approximates, one sentence each, for the output's comments
  /// and the command's report.
  std::vector<std::string> notes;
};

/// Options of BuildSimulationModel.
struct SimulationOptions {
  double density = 7850.0;  ///< kg/m^3 (steel)
  /// When given, each hinge's and slide's movable range is found by sweeping its motion (the
  /// joint alone turning or sliding, what it couples following, other freedoms held) both ways
  /// until the first contact with a part that cannot yield (not one a free motion moves, which
  /// the swept check carries along): over one revolution or the assembly's diagonal.
  const CollisionModel* collision = nullptr;
  /// Called with the fraction of the joints whose ranges are searched, when given.
  std::function<void(double)> progress;
};

/// A link that no part gives mass to gets this mass (kg) and this inertia (kg m^2) on each
/// axis: a simulator needs positive values.
inline constexpr double kDefaultMass = 1e-3;
inline constexpr double kDefaultInertia = 1e-7;

/// The simulator model of `analysis`. Links are the subassemblies; the tree is the breadth-first
/// spanning tree from the ground preferring pairs with fewer freedoms, so that the pairs left
/// to close loops are the simplest; a body nothing holds floats. Coupling rows of the
/// kinematic model become equalities between the joints they really relate (a planet's gear
/// with a fixed ring relates the planet's hinge and the carrier's). Mass, centre of mass and
/// inertia from the parts' closed meshes at `options.density`. Throws std::invalid_argument
/// for a density that is not positive and finite.
SimulationModel BuildSimulationModel(const Assembly& assembly, const Analysis& analysis,
                                     const SimulationOptions& options = {});

}  // namespace mechanist
