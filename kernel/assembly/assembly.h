#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/assembly/diagnostic.h"
#include "kernel/assembly/pair_type.h"
#include "kernel/assembly/part.h"
#include "kernel/features/feature_ref.h"

namespace mechanist {

/// The file's units: names as written and factors to millimetres and radians.
struct Units {
  std::string length = "mm";
  std::string angle = "deg";
  double mm_per_length = 1.0;
  double rad_per_angle = 0.017453292519943295;
};

/// Recognition tolerances in mm and radians (file: `tolerance`, in the file's units).
struct Tolerance {
  double length = 0.05;
  double angle = 0.008726646259971648;  ///< 0.5 degrees
};

/// A driver (spec, "Drivers"). Rotation rates are revolutions per second about the feature
/// axis (right-hand rule); translation rates are mm/s along it. `amount` is revolutions or mm.
struct Driver {
  enum class Motion { kRotation, kTranslation };
  std::string id;
  FeatureRef feature;                      ///< the driven part's feature whose axis is used
  std::optional<std::size_t> relative_to;  ///< part index; nothing: the ground
  Motion motion = Motion::kRotation;
  double rate = 1.0;
  double amount = 1.0;
};

/// A bounded freedom the designer may use (spec, "Adjustments").
struct Adjustment {
  enum class Kind { kRotate, kTranslate };
  std::string id;
  std::size_t moves = 0;  ///< part index
  Kind kind = Kind::kRotate;
  FeatureRef axis;                  ///< the feature whose axis is the adjustment's axis
  double lower = 0.0, upper = 0.0;  ///< radians or mm
};

/// A goal for the adjustments: two features must mesh or be coaxial.
struct Goal {
  enum class Kind { kMesh, kCoaxial };
  Kind kind = Kind::kMesh;
  std::array<FeatureRef, 2> features;
};

/// One step of an assembly sequence: insert one feature into another.
struct AssemblyStep {
  FeatureRef insert;
  FeatureRef into;
};

/// A user override: force a pair type, or forbid any pair (`type` empty).
struct PairOverride {
  std::array<FeatureRef, 2> features;
  std::optional<PairType> type;
  /// Not written in the file: an axle of the frame ImplyGearFrame adds.
  bool implied_frame = false;
  /// A screw pair's lead: mm one feature advances along the axis per revolution relative to
  /// the other, positive for a right-hand thread. Empty: the thread feature's own.
  std::optional<double> lead = std::nullopt;
};

/// A ratio as written in an expectation: exact `numerator/denominator` (reduced, positive
/// denominator) or a decimal `value`.
struct ExpectedRatio {
  bool exact = false;
  std::int64_t numerator = 0;
  std::int64_t denominator = 1;
  double value = 0.0;  ///< the number (also set for exact ratios)
  std::string text;    ///< as written
};

/// One mechanism test of `expect` (spec, "Expectations").
struct Expectation {
  enum class Kind { kRatio, kMoves, kMobility, kPair, kSameSubassembly, kAssemblable, kDiagnostic };
  Kind kind = Kind::kRatio;
  std::string pointer;                ///< JSON pointer of the entry, for messages ("/expect/2")
  std::optional<std::size_t> part;    ///< ratio, moves
  std::optional<FeatureRef> feature;  ///< ratio: the axis the rate is measured about or along
  ExpectedRatio ratio;
  bool flag = false;  ///< moves, assemblable
  int mobility = 0;
  std::array<FeatureRef, 2> pair{};
  std::optional<PairType> pair_type;  ///< pair: nothing means any pair
  std::vector<std::size_t> parts;     ///< same_subassembly, diagnostic
  std::string diagnostic;             ///< diagnostic: a code or a substring of the message
};

/// Which of the engine's guesses at what a CAD export leaves out may run (file: `infer`, our
/// addition to the format); all on by default.
struct Inference {
  /// Two parts' coaxial holes with nothing in them turn on a pin the file leaves out.
  bool implied_pins = true;
  /// Gears exported without frame or shafts turn on a frame's axles (ImplyGearFrame).
  bool implied_frame = true;
  /// A part whose faces or pin leave it only a slide that the parts around stop within a small
  /// play is held there (SeatParts).
  bool seated_parts = true;
  /// A part in no pair that is sunk into another part is fixed to it (embedded parts).
  bool embedded_parts = true;
  /// A floating part whose shaft or hole stands on a wider hole's or thinner shaft's axis is
  /// fixed there (CentreFloatingParts).
  bool centred_parts = true;
};

/// A STEP file an assembly reads (alone, imported or as a part's mesh) and the length units it
/// declares: lower case, as the file names them ("metre", "millimetre", "inch"), several when
/// its parts carry their own. Informational: its values are read in mm.
struct StepFileUnits {
  std::string file;  ///< as the assembly file writes it (the STEP file's name when alone)
  std::vector<std::string> length;
};

/// Everything an assembly file describes, as plain data; Assembly checks and indexes it.
struct AssemblySpec {
  std::string name;
  std::string source;  ///< the file it was read from, if any
  Units units;
  Tolerance tolerance;
  double friction = 0.1;
  Inference inference;
  std::vector<Part> parts;
  std::vector<Driver> drivers;
  std::vector<Adjustment> adjustments;
  std::vector<Goal> goals;
  std::vector<AssemblyStep> steps;
  std::vector<PairOverride> overrides;
  std::vector<Expectation> expectations;
  /// What loading did beyond reading the file's words, and says so (features recognised,
  /// the nut-on-bolt heuristic, adjustments locked, the STEP reader's messages; see
  /// LoadAssembly), reported with the description checks.
  std::vector<Diagnostic> findings;
  std::vector<StepFileUnits> step_units;  ///< of each STEP file read, in reading order
};

/// The immutable description of an assembly (Pinocchio's Model): parts, features and the
/// file's drivers, adjustments, goals, steps, overrides and expectations. Changing state
/// (poses during motion) lives in AssemblyState.
class Assembly {
 public:
  /// Takes the description; a part without a mesh (null) gets an empty one: a features-only
  /// part (Part::HasGeometry). Throws std::invalid_argument for duplicate part or feature ids,
  /// or an index that refers to no part or feature.
  /// Throws std::length_error beyond 2^32 - 1 parts, or features in a part (FeatureRef).
  explicit Assembly(AssemblySpec spec);

  /// The description it holds (to derive a changed assembly from).
  const AssemblySpec& spec() const { return spec_; }
  const std::string& name() const { return spec_.name; }
  const std::string& source() const { return spec_.source; }
  const Units& units() const { return spec_.units; }
  const std::vector<StepFileUnits>& step_units() const { return spec_.step_units; }
  const Tolerance& tolerance() const { return spec_.tolerance; }
  const Inference& inference() const { return spec_.inference; }
  double friction() const { return spec_.friction; }
  const std::vector<Part>& parts() const { return spec_.parts; }
  const Part& part(std::size_t index) const { return spec_.parts.at(index); }
  const std::vector<Driver>& drivers() const { return spec_.drivers; }
  const std::vector<Adjustment>& adjustments() const { return spec_.adjustments; }
  const std::vector<Goal>& goals() const { return spec_.goals; }
  const std::vector<AssemblyStep>& steps() const { return spec_.steps; }
  const std::vector<PairOverride>& overrides() const { return spec_.overrides; }
  const std::vector<Expectation>& expectations() const { return spec_.expectations; }
  const std::vector<Diagnostic>& findings() const { return spec_.findings; }

  /// Index of the part `id`, or nothing.
  std::optional<std::size_t> FindPart(const std::string& id) const;
  /// The feature written "part_id/feature_id", or nothing.
  std::optional<FeatureRef> FindFeature(const std::string& path) const;
  const Feature& feature(FeatureRef ref) const {
    return spec_.parts.at(ref.part).features.at(ref.feature);
  }
  /// "part_id/feature_id", from the compact table of names (see PartId).
  std::string FeatureName(FeatureRef ref) const;
  /// The part's id, from a compact table of all names made with the assembly: reports name
  /// thousands of parts and features in no particular order, and at 100,000 parts the table
  /// stays in the cache where reading the parts themselves would go to memory for each name.
  std::string_view PartId(std::size_t part) const;
  /// The part's position when the parts are ordered by id: sorting by it orders by id (so that
  /// reports do not depend on the file's order) without comparing strings.
  std::size_t PartRank(std::size_t part) const { return part_rank_.at(part); }
  /// The feature's position when the features of all parts are ordered by name "id/feature"
  /// (which differs from ordering by (part id, feature id) where an id extends another with a
  /// character below '/', as "gear-2" does "gear").
  std::size_t FeatureNameRank(FeatureRef ref) const {
    return feature_name_rank_[FeatureIndex(ref)];
  }
  /// The features of one kind, parts and features in order: a check that concerns one kind
  /// need not read every feature.
  const std::vector<FeatureRef>& FeaturesOfKind(FeatureKind kind) const;
  /// The number of features of all parts.
  std::size_t feature_count() const { return feature_rank_.size(); }
  /// The feature's position among the features of all parts, parts in order: an index into
  /// flat per-feature arrays of size feature_count().
  /// Whether part `part` is fixed to the world, from a compact per-part table.
  bool IsGround(std::size_t part) const { return ground_.at(part); }
  /// Whether part `part` is compliant (Part::compliant), from a compact per-part table.
  bool IsCompliant(std::size_t part) const { return compliant_.at(part); }
  /// Whether any part is compliant: checks that concern them need not read every part.
  bool HasCompliantParts() const { return has_compliant_; }
  /// The kind of feature `ref`, from a compact per-feature table: loops over pairs read it
  /// without touching the Feature itself.
  FeatureKind kind(FeatureRef ref) const { return feature_kind_[FeatureIndex(ref)]; }
  /// The number of features of part `part`, from the compact per-part table.
  std::size_t FeatureCount(std::size_t part) const {
    return (part + 1 < first_feature_.size() ? first_feature_[part + 1] : feature_count()) -
           first_feature_.at(part);
  }
  std::size_t FeatureIndex(FeatureRef ref) const {
    return first_feature_.at(ref.part) + ref.feature;
  }
  /// The origin of feature `ref` in its part's frame (mm), from a compact per-feature table:
  /// checks over every feature read it without touching the Feature itself.
  const Eigen::Vector3d& FeatureOrigin(FeatureRef ref) const {
    return feature_origin_[FeatureIndex(ref)];
  }
  /// Every part's pose in the file (Part::X_WP), contiguous: the initial state is a copy, and
  /// recognition at the file's poses reads them without one.
  const std::vector<RigidTransform>& FilePoses() const { return file_poses_; }
  /// The part's mesh box in part coordinates (mm), computed once per distinct mesh when the
  /// assembly is made: instances share one mesh, and each analysis asks for every part's box.
  const Aabb& MeshBox(std::size_t part) const { return mesh_box_.at(part); }

 private:
  void CheckRef(FeatureRef ref, const char* what) const;
  void CheckPart(std::size_t part, const char* what) const;
  struct NameSpan;
  /// Appends the pieces to names_, as one name.
  NameSpan AppendName(std::initializer_list<std::string_view> pieces);

  AssemblySpec spec_;
  std::map<std::string, std::size_t, std::less<>> part_index_;
  std::vector<std::size_t> part_rank_;
  std::vector<std::size_t> first_feature_;      ///< per part: the FeatureIndex of its first feature
  std::vector<std::uint32_t> feature_rank_;     ///< per feature: its rank by id in its part
  std::vector<std::size_t> feature_name_rank_;  ///< per feature: FeatureNameRank
  std::vector<FeatureKind> feature_kind_;       ///< per feature: its kind
  std::vector<Eigen::Vector3d> feature_origin_;  ///< per feature: Feature::origin
  std::vector<bool> ground_;                     ///< per part: Part::ground
  std::vector<bool> compliant_;                  ///< per part: Part::compliant
  bool has_compliant_ = false;
  std::vector<RigidTransform> file_poses_;  ///< per part: Part::X_WP
  std::vector<Aabb> mesh_box_;              ///< per part: its mesh's Bounds()
  std::map<FeatureKind, std::vector<FeatureRef>> features_of_kind_;
  /// Where a name lies in names_.
  struct NameSpan {
    std::uint32_t offset = 0, size = 0;
  };
  std::string names_;                   ///< every part id and "part_id/feature_id", in order
  std::vector<NameSpan> part_id_;       ///< per part: its id in names_
  std::vector<NameSpan> feature_name_;  ///< per feature: its "part_id/feature_id" in names_
};

/// The part that a group of parts moving as one (a subassembly) is named after: the largest by
/// mesh volume (a part without a mesh counts as none), the first in `parts` among equals, so
/// that a pendulum's turn is the rod's and not its bearing ring's. `parts` are indices into
/// `assembly.parts()`; throws std::logic_error when there is none.
std::size_t MainPart(const Assembly& assembly, std::span<const std::size_t> parts);

}  // namespace mechanist
