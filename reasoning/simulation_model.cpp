#include "reasoning/simulation_model.h"

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>

#include "kernel/geometry/aabb.h"
#include "kernel/mesh/mass_properties.h"
#include "kernel/mesh/mesh_check.h"
#include "reasoning/kinematic_model.h"
#include "reasoning/movable_range.h"

namespace mechanist {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kMetresPerMm = 1e-3;

// The pairs ordered by their freedoms (fewest first, couplings last), stably: the kinematic
// model's breadth-first tree takes the first pair that reaches a new body, so it prefers a
// screw to the cylindrical fit beside it and leaves the looser pair to close the loop.
std::vector<std::size_t> ByFreedoms(const std::vector<Pair>& pairs) {
  std::vector<std::size_t> order(pairs.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return pairs[x].dof.value_or(7) < pairs[y].dof.value_or(7);
  });
  return order;
}

class Builder {
 public:
  Builder(const Assembly& assembly, const Analysis& analysis, const SimulationOptions& options)
      : assembly_(assembly),
        analysis_(analysis),
        options_(options),
        order_(ByFreedoms(analysis.pairs)),
        sorted_pairs_(Sorted(analysis.pairs, order_)),
        km_(assembly, sorted_pairs_, analysis.subassemblies, analysis.subassembly_of) {}

  SimulationModel Build() {
    AddLinks();
    AddJoints();
    AddMeshes();
    AddMass();
    AddCouplings();
    AddLoops();
    AddActuators();
    Aabb bounds;
    for (const Part& part : assembly_.parts()) {
      if (part.HasGeometry()) bounds.Extend(TransformBox(part.X_WP, part.mesh->Bounds()));
    }
    model_.reach = bounds.empty() ? 0.0 : kMetresPerMm * bounds.size().norm();
    if (options_.collision) AddLimits(*options_.collision);
    return std::move(model_);
  }

 private:
  static std::vector<Pair> Sorted(const std::vector<Pair>& pairs,
                                  const std::vector<std::size_t>& order) {
    std::vector<Pair> sorted;
    sorted.reserve(pairs.size());
    for (const std::size_t i : order) sorted.push_back(pairs[i]);
    return sorted;
  }

  std::string PairName(std::size_t pair) const {
    const Pair& p = analysis_.pairs[pair];
    return fmt::format("{} pair {} + {}", ToString(p.type), assembly_.FeatureName(p.a),
                       assembly_.FeatureName(p.b));
  }

  void AddLinks() {
    link_of_body_.assign(km_.body_count(), std::nullopt);
    std::set<std::string> names;
    for (std::size_t p = 0; p < assembly_.parts().size(); ++p) names.insert(assembly_.part(p).id);
    for (const std::size_t body : km_.order()) {
      SimLink link;
      if (body < analysis_.subassemblies.size()) {
        const Subassembly& s = analysis_.subassemblies[body];
        link.parts = s.parts;
        link.ground = s.ground;
        link.name = assembly_.part(MainPart(assembly_, s.parts)).id;
      } else {  // the virtual ground: no part is fixed to the world
        link.ground = true;
        link.name = "world";
        while (names.count(link.name)) link.name += "_";
      }
      if (const auto& j = km_.parent_joint(body)) {
        const Joint& joint = km_.joints()[*j];
        const std::size_t parent = joint.body_a == body ? joint.body_b : joint.body_a;
        link.parent = link_of_body_[parent];
        link.p_WL = kMetresPerMm * joint.point_W;
      }
      link_of_body_[body] = model_.links.size();
      model_.links.push_back(std::move(link));
    }
    for (std::size_t p = 0; p < assembly_.parts().size(); ++p) {
      if (assembly_.IsCompliant(p) && !link_of_body_[km_.body_of_part(p)]) {
        model_.notes.push_back(
            fmt::format("part {} is compliant (a spring, belt or hose): left out of the model",
                        assembly_.part(p).id));
      }
    }
  }

  void AddJoints() {
    joint_of_freedom_.assign(km_.freedoms().size(), std::nullopt);
    for (std::size_t l = 0; l < model_.links.size(); ++l) {
      const std::size_t body = km_.order()[l];
      const auto& j = km_.parent_joint(body);
      if (!j) continue;
      const Joint& joint = km_.joints()[*j];
      // Freedoms give body_a's motion relative to body_b; the joint moves the child.
      const double sign = joint.body_a == body ? 1.0 : -1.0;
      const std::string& name = model_.links[l].name;
      std::optional<std::size_t> pair;
      if (joint.pair) pair = order_[*joint.pair];
      auto add = [&](SimJoint::Kind kind, const std::string& suffix, const Freedom& f) {
        SimJoint s;
        s.name = name + suffix;
        s.kind = kind;
        s.link = l;
        s.p_W = kMetresPerMm * f.point_W;
        s.axis_W = sign * f.direction_W;
        s.pair = pair;
        model_.joints.push_back(s);
        return model_.joints.size() - 1;
      };
      const auto freedoms = joint.freedoms;
      if (!joint.pair) {
        add(SimJoint::Kind::kFree, "_free", km_.freedoms()[freedoms.front()]);
        continue;
      }
      if (joint.type == PairType::kSpherical) {
        add(SimJoint::Kind::kBall, "_ball", km_.freedoms()[freedoms.front()]);
        continue;
      }
      // A planar pair's two slides are named u and v; other pairs have one of each kind.
      int slides = 0;
      const bool planar = joint.type == PairType::kPlanar;
      for (const std::size_t k : freedoms) {
        const Freedom& f = km_.freedoms()[k];
        switch (f.kind) {
          case Freedom::Kind::kRotation:
            joint_of_freedom_[k] = add(SimJoint::Kind::kHinge, "_hinge", f);
            break;
          case Freedom::Kind::kTranslation:
            joint_of_freedom_[k] = add(SimJoint::Kind::kSlide,
                                       planar ? (slides++ ? "_slide_v" : "_slide_u") : "_slide", f);
            break;
          case Freedom::Kind::kScrew: {
            const std::size_t hinge = add(SimJoint::Kind::kHinge, "_hinge", f);
            const std::size_t slide = add(SimJoint::Kind::kSlide, "_slide", f);
            joint_of_freedom_[k] = hinge;
            // One revolution (2 pi rad) advances the lead: slide = lead / (2 pi) * hinge.
            const double lead_m = kMetresPerMm * f.lead.value();
            model_.couplings.push_back({*pair, {{slide, 1.0}, {hinge, -lead_m / kTwoPi}}});
            break;
          }
        }
      }
    }
  }

  // `id` as a file name stem: characters other than letters, digits, '-', '_' and '.' become
  // '_', and a stem taken before gets a number.
  std::string FileStem(const std::string& id) {
    std::string stem = id;
    for (char& c : stem) {
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
    }
    if (stem.empty() || stem[0] == '.') stem = "_" + stem;
    std::string unique = stem;
    for (int k = 2; !stems_.insert(unique).second; ++k) unique = fmt::format("{}_{}", stem, k);
    return unique;
  }

  void AddMeshes() {
    std::map<const TriangleMesh*, std::size_t> index_of;
    for (SimLink& link : model_.links) {
      for (const std::size_t p : link.parts) {
        const Part& part = assembly_.part(p);
        if (!part.HasGeometry()) continue;
        auto [it, added] = index_of.emplace(part.mesh.get(), model_.meshes.size());
        if (added) model_.meshes.push_back({FileStem(part.id), part.mesh});
        SimVisual v;
        v.part = p;
        v.mesh = it->second;
        v.R_LP = part.X_WP.rotation();
        v.p_LP = kMetresPerMm * part.X_WP.translation() - link.p_WL;
        link.visuals.push_back(v);
      }
    }
  }

  void AddMass() {
    // Per unit density the integrals are in mm: volume mm^3, inertia mm^5.
    const double kg_per_mm3 = options_.density * 1e-9;
    const double kgm2_per_mm5 = options_.density * 1e-15;
    std::vector<std::string> sketches, open;
    for (SimLink& link : model_.links) {
      double mass = 0.0;
      Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // sum of m * p_LC
      std::vector<std::pair<double, Eigen::Vector3d>> bodies;
      std::vector<Eigen::Matrix3d> inertias;
      for (const std::size_t p : link.parts) {
        const Part& part = assembly_.part(p);
        if (!part.HasGeometry()) {
          sketches.push_back(part.id);
          continue;
        }
        if (!CheckMesh(*part.mesh).closed()) {
          link.open_parts.push_back(p);
          open.push_back(part.id);
          continue;
        }
        const MassProperties m = ComputeMassProperties(*part.mesh);
        const double sense = m.volume < 0 ? -1.0 : 1.0;  // a mesh wound inside out
        const double part_mass = sense * m.volume * kg_per_mm3;
        const Eigen::Vector3d p_LC = kMetresPerMm * (part.X_WP * m.center) - link.p_WL;
        const Eigen::Matrix3d& R = part.X_WP.rotation();
        bodies.emplace_back(part_mass, p_LC);
        inertias.push_back(sense * kgm2_per_mm5 * R * m.inertia * R.transpose());
        mass += part_mass;
        moment += part_mass * p_LC;
      }
      if (!(mass > 0.0)) {
        link.default_inertia = true;
        link.mass = kDefaultMass;
        link.I_Cm = kDefaultInertia * Eigen::Matrix3d::Identity();
        continue;
      }
      link.mass = mass;
      link.p_LCm = moment / mass;
      // Parallel axis theorem: each part's tensor moved from its centre to the link's.
      for (std::size_t k = 0; k < bodies.size(); ++k) {
        const Eigen::Vector3d d = bodies[k].second - link.p_LCm;
        link.I_Cm +=
            inertias[k] +
            bodies[k].first * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
      }
    }
    if (!sketches.empty()) {
      model_.notes.push_back(
          fmt::format("{} no geometry and no mass: a link with no other part gets the default "
                      "inertia (1 g, 1e-7 kg m^2)",
                      Listed("features-only part", sketches)));
    }
    if (!open.empty()) {
      model_.notes.push_back(fmt::format(
          "warning: {} a mesh that is not closed: left out of its link's mass and inertia",
          Listed("part", open)));
    }
  }

  static std::string Listed(const std::string& what, const std::vector<std::string>& ids) {
    return fmt::format("{}{} {} {}", what, ids.size() > 1 ? "s" : "", fmt::join(ids, ", "),
                       ids.size() > 1 ? "have" : "has");
  }

  void AddCouplings() {
    for (const ConstraintRow& row : km_.rows()) {
      const std::size_t pair = order_[row.pair];
      if (!IsCoupling(analysis_.pairs[pair].type)) continue;
      SimCoupling c;
      c.pair = pair;
      bool expressible = true;
      for (const auto& [k, coefficient] : row.terms) {
        if (coefficient.exact() && coefficient.exact()->is_zero()) continue;
        if (!joint_of_freedom_[k]) {
          expressible = false;
          continue;
        }
        // The row counts revolutions and mm; the joints count radians and metres.
        const Freedom& f = km_.freedoms()[k];
        const double scale =
            f.kind == Freedom::Kind::kTranslation ? 1.0 / kMetresPerMm : 1.0 / kTwoPi;
        const std::size_t joint = *joint_of_freedom_[k];
        auto same = std::find_if(c.terms.begin(), c.terms.end(),
                                 [&](const auto& t) { return t.first == joint; });
        if (same == c.terms.end()) {
          c.terms.emplace_back(joint, coefficient.value() * scale);
        } else {
          same->second += coefficient.value() * scale;
        }
      }
      if (!expressible) {
        model_.notes.push_back(fmt::format(
            "{}: a coupling through a ball or floating joint, left out", PairName(pair)));
        continue;
      }
      if (!c.terms.empty()) model_.couplings.push_back(std::move(c));
    }
    std::stable_sort(model_.couplings.begin(), model_.couplings.end(),
                     [](const SimCoupling& x, const SimCoupling& y) { return x.pair < y.pair; });
  }

  void AddLoops() {
    for (const Joint& j : km_.joints()) {
      if (!j.pair || j.in_tree) continue;
      const std::size_t pair = order_[*j.pair];
      SimLoop loop;
      loop.pair = pair;
      loop.link_a = *link_of_body_[j.body_a];
      loop.link_b = *link_of_body_[j.body_b];
      if (j.type == PairType::kRevolute) {
        // Two points of the axis held together hold the axes together: a hinge.
        const double length = std::max(km_.WorldAxis(analysis_.pairs[pair].a).length, 10.0);
        loop.anchors_W = {kMetresPerMm * j.point_W, kMetresPerMm * (j.point_W + length * j.axis_W)};
      } else if (j.type == PairType::kSpherical) {
        loop.anchors_W = {kMetresPerMm * j.point_W};
      }
      model_.loops.push_back(std::move(loop));
    }
  }

  // The joints whose rates sum to the rate of `link` relative to `base` about (rotation) or
  // along `axis`, each with +1 or -1 for its sense: hinges parallel to the axis for a turn
  // (slides on the way do not turn it), slides along it for a push (hinges parallel to it and
  // slides square to it do not move points along it). Hinges parallel to the axis keep every
  // such direction, so the sum holds in every pose. Empty when `link` is not below `base` or
  // a joint on the way is of another kind or direction.
  std::vector<std::pair<std::size_t, double>> DriverTerms(std::optional<std::size_t> link,
                                                          std::optional<std::size_t> base,
                                                          const Eigen::Vector3d& axis,
                                                          bool rotation) const {
    const double cos_tol = std::cos(assembly_.tolerance().angle);
    const double sin_tol = std::sin(assembly_.tolerance().angle);
    const SimJoint::Kind moving = rotation ? SimJoint::Kind::kHinge : SimJoint::Kind::kSlide;
    std::vector<std::pair<std::size_t, double>> terms;
    if (!link || !base) return {};
    for (std::optional<std::size_t> l = link; l != base; l = model_.links[*l].parent) {
      if (!l || !model_.links[*l].parent) return {};  // the root reached: not below `base`
      for (std::size_t k = 0; k < model_.joints.size(); ++k) {
        const SimJoint& j = model_.joints[k];
        if (j.link != *l) continue;
        const double dot = j.axis_W.dot(axis);
        const bool parallel = std::abs(dot) >= cos_tol;
        if (j.kind == moving && parallel) {
          terms.emplace_back(k, dot > 0 ? 1.0 : -1.0);
          continue;
        }
        const bool idle = rotation
                              ? j.kind == SimJoint::Kind::kSlide
                              : (j.kind == SimJoint::Kind::kHinge && parallel) ||
                                    (j.kind == SimJoint::Kind::kSlide && std::abs(dot) <= sin_tol);
        if (!idle) return {};
      }
    }
    return terms;
  }

  void AddActuators() {
    for (std::size_t d = 0; d < assembly_.drivers().size(); ++d) {
      const Driver& driver = assembly_.drivers()[d];
      SimActuator a;
      a.driver = d;
      const bool rotation = driver.motion == Driver::Motion::kRotation;
      const std::optional<std::size_t> link = link_of_body_[km_.body_of_part(driver.feature.part)];
      const std::optional<std::size_t> base =
          driver.relative_to ? link_of_body_[km_.body_of_part(*driver.relative_to)]
                             : std::optional<std::size_t>(0);
      const Eigen::Vector3d& axis = km_.WorldAxis(driver.feature).direction;
      a.terms = DriverTerms(link, base, axis, rotation);
      a.rate = driver.rate * (rotation ? kTwoPi : kMetresPerMm);
      if (a.terms.empty()) {
        a.reason = fmt::format(
            "driver {}: no joint of the tree {} {} about its axis relative to {}", driver.id,
            rotation ? "turns" : "slides", assembly_.part(driver.feature.part).id,
            driver.relative_to ? assembly_.part(*driver.relative_to).id : "the ground");
        model_.notes.push_back(fmt::format("{}; no actuator", a.reason));
      }
      model_.actuators.push_back(std::move(a));
    }
  }

  void AddLimits(const CollisionModel& collision) {
    const double reach = model_.reach / kMetresPerMm;
    for (std::size_t k = 0; k < model_.joints.size(); ++k) {
      if (options_.progress) options_.progress(static_cast<double>(k) / model_.joints.size());
      SimJoint& j = model_.joints[k];
      if (!j.pair || (j.kind != SimJoint::Kind::kHinge && j.kind != SimJoint::Kind::kSlide)) {
        continue;
      }
      const Pair& pair = analysis_.pairs[*j.pair];
      if (pair.type == PairType::kPlanar || pair.type == PairType::kPinSlot) continue;
      if (pair.type == PairType::kScrew && j.kind == SimJoint::Kind::kSlide) continue;
      const bool a_is_child = km_.body_of_part(pair.a.part) == km_.order()[j.link];
      const FeatureRef child = a_is_child ? pair.a : pair.b;
      const std::size_t parent_part = a_is_child ? pair.b.part : pair.a.part;
      const bool hinge = j.kind == SimJoint::Kind::kHinge;
      const DrivenMotion motion =
          SolveImposed(analysis_.motion, {{child, hinge, 1.0, parent_part}});
      if (!motion.possible) continue;
      std::vector<ScrewPath> paths;
      paths.reserve(motion.parts.size());
      for (const PartMotion& m : motion.parts) paths.push_back(m.path);
      // One revolution either way finds every contact of a turning part; a slide runs the
      // assembly's size.
      const double amount = hinge ? 1.0 : reach;
      if (!(amount > 0.0)) continue;
      const MovableRange range =
          FindMovableRange(assembly_, analysis_, collision, paths, amount, hinge);
      // The feature's axis may point against the joint's.
      const double sign = km_.WorldAxis(child).direction.dot(j.axis_W) > 0 ? 1.0 : -1.0;
      const double unit = hinge ? kTwoPi : kMetresPerMm;
      auto set = [&](const std::optional<OperationClash>& c, double sense) {
        if (!c) return;
        const double q = sign * sense * c->at * unit;
        const std::pair<std::size_t, std::size_t> parts{c->part_a, c->part_b};
        if (q >= 0) {
          j.upper = q;
          j.upper_contact = parts;
        } else {
          j.lower = q;
          j.lower_contact = parts;
        }
      };
      set(range.ahead, 1.0);
      set(range.behind, -1.0);
    }
    if (options_.progress) options_.progress(1.0);
  }

  const Assembly& assembly_;
  const Analysis& analysis_;
  const SimulationOptions& options_;
  std::vector<std::size_t> order_;  // sorted pair index -> analysis pair index
  std::vector<Pair> sorted_pairs_;
  KinematicModel km_;
  std::vector<std::optional<std::size_t>> link_of_body_;
  std::vector<std::optional<std::size_t>> joint_of_freedom_;
  std::set<std::string> stems_;  // mesh file stems taken
  SimulationModel model_;
};

}  // namespace

SimulationModel BuildSimulationModel(const Assembly& assembly, const Analysis& analysis,
                                     const SimulationOptions& options) {
  if (!(options.density > 0.0) || !std::isfinite(options.density)) {
    throw std::invalid_argument("the density must be a positive number of kg/m^3");
  }
  return Builder(assembly, analysis, options).Build();
}

}  // namespace mechanist
