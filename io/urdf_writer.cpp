#include "io/urdf_writer.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <iterator>
#include <map>
#include <sstream>

#include "io/internal/simulator_text.h"
#include "io/internal/xml_text.h"

namespace mechanist {
namespace {

using internal::Number;
using internal::Numbers;
using internal::XmlComment;
using internal::XmlEscape;

// URDF's fixed-axis roll, pitch, yaw of R = Rz(yaw) Ry(pitch) Rx(roll).
std::string Rpy(const Eigen::Matrix3d& R) {
  const Eigen::Vector3d ypr = R.eulerAngles(2, 1, 0);
  return fmt::format("{} {} {}", Number(ypr.z()), Number(ypr.y()), Number(ypr.x()));
}

struct Mimic {
  std::size_t joint = 0;
  double multiplier = 0.0;
};

class UrdfWriter {
 public:
  UrdfWriter(const Assembly& assembly, const Analysis& analysis, const SimulationModel& model,
             const std::string& mesh_dir)
      : assembly_(assembly), analysis_(analysis), model_(model), mesh_dir_(mesh_dir) {}

  std::string Write() {
    ChooseMimics();
    out_ << "<?xml version=\"1.0\"?>\n" << XmlComment(internal::Provenance(assembly_)) << "\n";
    for (const std::string& note : model_.notes) out_ << XmlComment(note) << "\n";
    for (const std::string& c : unexpressed_) out_ << XmlComment(c) << "\n";
    for (const SimLoop& loop : model_.loops) {
      out_ << XmlComment(fmt::format(
                  "loop cut: the {} between links {} and {} is not a joint here: URDF cannot "
                  "close a loop",
                  internal::PairLabel(assembly_, analysis_, loop.pair),
                  model_.links[loop.link_a].name, model_.links[loop.link_b].name))
           << "\n";
    }
    for (const SimActuator& a : model_.actuators) {
      const Driver& d = assembly_.drivers()[a.driver];
      if (!a.terms.empty()) {
        // One joint at its own rate; several as their signed sum (URDF cannot drive a sum).
        const bool single = a.terms.size() == 1;
        std::string joints;
        for (const auto& [j, coefficient] : a.terms) {
          const bool minus = !single && coefficient < 0;
          fmt::format_to(std::back_inserter(joints), "{}{}",
                         joints.empty() ? (minus ? "-" : "") : (minus ? " - " : " + "),
                         model_.joints[j].name);
        }
        const SimJoint& first = model_.joints[a.terms.front().first];
        out_ << XmlComment(fmt::format("driver {}: {} {} at {} {}{}", d.id,
                                       single ? "joint" : "the sum of joints", joints,
                                       Number(a.ActingRate()),
                                       first.kind == SimJoint::Kind::kSlide ? "m/s" : "rad/s",
                                       a.rate == 0.0 ? " (held)" : ""))
             << "\n";
      } else {
        out_ << XmlComment(a.reason) << "\n";
      }
    }
    out_ << "<robot name=\"" << XmlEscape(assembly_.name().empty() ? "assembly" : assembly_.name())
         << "\">\n";
    for (std::size_t l = 0; l < model_.links.size(); ++l) WriteLink(l);
    for (std::size_t l = 1; l < model_.links.size(); ++l) WriteJoints(l);
    out_ << "</robot>\n";
    return out_.str();
  }

 private:
  // Couplings of two joints become mimics, one per joint (URDF allows no more); the others are
  // said in comments.
  void ChooseMimics() {
    for (const SimCoupling& c : model_.couplings) {
      const std::string label = internal::PairLabel(assembly_, analysis_, c.pair);
      if (c.terms.size() == 2) {
        auto [j1, c1] = c.terms[0];
        auto [j2, c2] = c.terms[1];
        if (mimic_.count(j1) && !mimic_.count(j2)) {
          std::swap(j1, j2);
          std::swap(c1, c2);
        }
        const bool cycle = mimic_.count(j2) && mimic_.at(j2).joint == j1;
        if (!mimic_.count(j1) && !cycle && IsSingle(j1) && IsSingle(j2)) {
          mimic_[j1] = {j2, -c2 / c1};
          continue;
        }
      }
      std::string terms;
      for (const auto& [j, coefficient] : c.terms) {
        fmt::format_to(std::back_inserter(terms), "{}{} * {}", terms.empty() ? "" : " + ",
                       Number(coefficient), model_.joints[j].name);
      }
      unexpressed_.push_back(
          fmt::format("coupling not expressed in URDF ({}): {} = 0", label, terms));
    }
  }

  bool IsSingle(std::size_t joint) const {
    const SimJoint::Kind k = model_.joints[joint].kind;
    return k == SimJoint::Kind::kHinge || k == SimJoint::Kind::kSlide;
  }

  void WriteLink(std::size_t l) {
    const SimLink& link = model_.links[l];
    out_ << "  "
         << XmlComment(fmt::format("link {}: {}", link.name, internal::LinkLabel(assembly_, link)))
         << "\n";
    out_ << "  <link name=\"" << XmlEscape(link.name) << "\">\n";
    if (!link.ground) {
      const Eigen::Matrix3d& I = link.I_Cm;
      out_ << "    <inertial>\n"
           << "      <origin xyz=\"" << Numbers(link.p_LCm) << "\" rpy=\"0 0 0\"/>\n"
           << "      <mass value=\"" << Number(link.mass) << "\"/>\n"
           << "      <inertia ixx=\"" << Number(I(0, 0)) << "\" ixy=\"" << Number(I(0, 1))
           << "\" ixz=\"" << Number(I(0, 2)) << "\" iyy=\"" << Number(I(1, 1)) << "\" iyz=\""
           << Number(I(1, 2)) << "\" izz=\"" << Number(I(2, 2)) << "\"/>\n"
           << "    </inertial>\n";
    }
    for (const SimVisual& v : link.visuals) {
      const std::string name = XmlEscape(assembly_.part(v.part).id);
      const std::string body = fmt::format(
          "      <origin xyz=\"{}\" rpy=\"{}\"/>\n"
          "      <geometry><mesh filename=\"{}.stl\"/></geometry>\n",
          Numbers(v.p_LP), Rpy(v.R_LP),
          XmlEscape(fmt::format("{}/{}", mesh_dir_, model_.meshes[v.mesh].name)));
      out_ << "    <visual name=\"" << name << "\">\n" << body << "    </visual>\n";
      out_ << "    <collision name=\"" << name << "\">\n" << body << "    </collision>\n";
    }
    out_ << "  </link>\n";
  }

  // The joints that move link l, from its parent: one URDF joint per freedom, with a massless
  // link between consecutive ones (a cylindrical pair's hinge and slide, a ball's three hinges).
  void WriteJoints(std::size_t l) {
    const SimLink& link = model_.links[l];
    struct Step {
      std::string name, type;
      Eigen::Vector3d axis;
      const SimJoint* joint;
      std::optional<std::size_t> index;
    };
    std::vector<Step> steps;
    for (std::size_t k = 0; k < model_.joints.size(); ++k) {
      const SimJoint& j = model_.joints[k];
      if (j.link != l) continue;
      switch (j.kind) {
        case SimJoint::Kind::kHinge:
          steps.push_back(
              {j.name, j.lower && j.upper ? "revolute" : "continuous", j.axis_W, &j, k});
          break;
        case SimJoint::Kind::kSlide:
          steps.push_back({j.name, "prismatic", j.axis_W, &j, k});
          break;
        case SimJoint::Kind::kBall:
          // URDF has no ball joint: three hinges about the world axes through the centre.
          for (int i = 0; i < 3; ++i) {
            steps.push_back({fmt::format("{}_{}", j.name, "xyz"[i]), "continuous",
                             Eigen::Vector3d::Unit(i), &j, std::nullopt});
          }
          break;
        case SimJoint::Kind::kFree:
          steps.push_back({j.name, "floating", Eigen::Vector3d::UnitX(), &j, std::nullopt});
          break;
      }
    }
    std::string parent = model_.links[*link.parent].name;
    for (std::size_t s = 0; s < steps.size(); ++s) {
      const Step& step = steps[s];
      const bool last = s + 1 == steps.size();
      const std::string child = last ? link.name : step.name + "_link";
      if (!last) out_ << "  <link name=\"" << XmlEscape(child) << "\"/>\n";
      if (step.joint->kind == SimJoint::Kind::kBall && s % 3 == 0) {
        out_ << "  "
             << XmlComment(fmt::format(
                    "ball joint {}: three hinges about the world axes through its centre",
                    step.joint->name))
             << "\n";
      }
      const Eigen::Vector3d origin =
          s == 0 ? Eigen::Vector3d(link.p_WL - model_.links[*link.parent].p_WL)
                 : Eigen::Vector3d::Zero();
      out_ << "  <joint name=\"" << XmlEscape(step.name) << "\" type=\"" << step.type << "\">\n"
           << "    <parent link=\"" << XmlEscape(parent) << "\"/>\n"
           << "    <child link=\"" << XmlEscape(child) << "\"/>\n"
           << "    <origin xyz=\"" << Numbers(origin) << "\" rpy=\"0 0 0\"/>\n";
      if (step.type != "floating") out_ << "    <axis xyz=\"" << Numbers(step.axis) << "\"/>\n";
      WriteLimit(step.type, *step.joint);
      if (step.index && mimic_.count(*step.index)) {
        const Mimic& m = mimic_.at(*step.index);
        out_ << "    <mimic joint=\"" << XmlEscape(model_.joints[m.joint].name)
             << "\" multiplier=\"" << Number(m.multiplier) << "\" offset=\"0\"/>\n";
      }
      out_ << "  </joint>\n";
      parent = child;
    }
  }

  void WriteLimit(const std::string& type, const SimJoint& j) {
    if (type != "revolute" && type != "prismatic") return;
    // URDF requires effort and velocity; mechanist knows neither, so they are not bounds.
    const double lower = j.lower.value_or(-model_.reach);
    const double upper = j.upper.value_or(model_.reach);
    const std::string stops = internal::LimitLabel(assembly_, j);
    if (!stops.empty()) out_ << "    " << XmlComment(stops) << "\n";
    if (!j.lower || !j.upper) {
      out_ << "    "
           << XmlComment(
                  fmt::format("no contact stops this slide within the assembly's size on the {}",
                              !j.lower && !j.upper ? "both sides"
                              : j.lower            ? "upper side"
                                                   : "lower side"))
           << "\n";
    }
    out_ << "    <limit lower=\"" << Number(lower) << "\" upper=\"" << Number(upper)
         << "\" effort=\"1e6\" velocity=\"1e3\"/>\n";
  }

  const Assembly& assembly_;
  const Analysis& analysis_;
  const SimulationModel& model_;
  const std::string& mesh_dir_;
  std::map<std::size_t, Mimic> mimic_;  // by joint
  std::vector<std::string> unexpressed_;
  std::ostringstream out_;
};

}  // namespace

std::string UrdfText(const Assembly& assembly, const Analysis& analysis,
                     const SimulationModel& model, const std::string& mesh_dir) {
  return UrdfWriter(assembly, analysis, model, mesh_dir).Write();
}

}  // namespace mechanist
