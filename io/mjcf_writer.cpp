#include "io/mjcf_writer.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <iterator>
#include <sstream>

#include "io/internal/simulator_text.h"
#include "io/internal/xml_text.h"

namespace mechanist {
namespace {

using internal::Number;
using internal::Numbers;
using internal::XmlComment;
using internal::XmlEscape;

// The impedance of the constraints that must hold (loop closures, brakes): near 1, so that a
// light part held to a heavy one is not left loose by MuJoCo's default (0.9).
constexpr const char* kStiff = "0.9999 0.9999 0.001";

// The time constant of a driver's velocity servo, seconds.
constexpr double kDriveTimeConstant = 0.02;

std::string Quaternion(const Eigen::Matrix3d& R) {
  Eigen::Quaterniond q(R);
  q.normalize();
  if (q.w() < 0) q.coeffs() *= -1.0;  // one of the two for the same rotation, always the same
  return fmt::format("{} {} {} {}", Number(q.w()), Number(q.x()), Number(q.y()), Number(q.z()));
}

class MjcfWriter {
 public:
  MjcfWriter(const Assembly& assembly, const Analysis& analysis, const SimulationModel& model,
             const MjcfOptions& options)
      : assembly_(assembly), analysis_(analysis), model_(model), options_(options) {}

  std::string Write() {
    out_ << "<mujoco model=\""
         << XmlEscape(assembly_.name().empty() ? "assembly" : assembly_.name()) << "\">\n";
    out_ << "  " << XmlComment(internal::Provenance(assembly_)) << "\n";
    for (const std::string& note : model_.notes) out_ << "  " << XmlComment(note) << "\n";
    out_ << "  <compiler angle=\"radian\" inertiafromgeom=\"false\"/>\n"
         << "  " << XmlComment("the assembly file does not say which way is up: set gravity here")
         << "\n  <option gravity=\"0 0 0\"/>\n";
    WriteAssets();
    out_ << "  <worldbody>\n";
    WriteBody(0, 2);
    out_ << "  </worldbody>\n";
    WriteCouplingsAndLoops();
    WriteActuators();
    out_ << "</mujoco>\n";
    return out_.str();
  }

 private:
  std::string BodyName(std::size_t link) const {
    return link == 0 ? "world" : XmlEscape(model_.links[link].name);
  }

  void WriteAssets() {
    if (model_.meshes.empty()) return;
    out_ << "  <asset>\n";
    for (const SimMesh& m : model_.meshes) {
      out_ << "    <mesh name=\"" << XmlEscape(m.name) << "\" file=\""
           << XmlEscape(fmt::format("{}/{}", options_.mesh_dir, m.name)) << ".stl\"/>\n";
    }
    out_ << "  </asset>\n";
  }

  void WriteBody(std::size_t l, int depth) {
    const SimLink& link = model_.links[l];
    const std::string pad(2 * depth, ' ');
    const std::string inner(2 * depth + (l == 0 ? 0 : 2), ' ');
    out_ << pad
         << XmlComment(fmt::format("link {}: {}", link.name, internal::LinkLabel(assembly_, link)))
         << "\n";
    if (l != 0) {
      const Eigen::Vector3d p = link.p_WL - model_.links[*link.parent].p_WL;
      out_ << pad << "<body name=\"" << BodyName(l) << "\" pos=\"" << Numbers(p) << "\">\n";
      const Eigen::Matrix3d& I = link.I_Cm;
      out_ << inner << "<inertial pos=\"" << Numbers(link.p_LCm) << "\" mass=\""
           << Number(link.mass) << "\" fullinertia=\"" << Number(I(0, 0)) << " " << Number(I(1, 1))
           << " " << Number(I(2, 2)) << " " << Number(I(0, 1)) << " " << Number(I(0, 2)) << " "
           << Number(I(1, 2)) << "\"/>\n";
      for (const SimJoint& j : model_.joints) {
        if (j.link == l) WriteJoint(j, inner);
      }
    }
    for (const SimVisual& v : link.visuals) {
      out_ << inner << "<geom name=\"" << XmlEscape(assembly_.part(v.part).id)
           << "\" type=\"mesh\" mesh=\"" << XmlEscape(model_.meshes[v.mesh].name) << "\" pos=\""
           << Numbers(v.p_LP) << "\" quat=\"" << Quaternion(v.R_LP)
           << "\" contype=\"0\" conaffinity=\"0\"/>\n";
    }
    for (std::size_t c = 0; c < model_.links.size(); ++c) {
      if (model_.links[c].parent == l) WriteBody(c, depth + (l == 0 ? 0 : 1));
    }
    if (l != 0) out_ << pad << "</body>\n";
  }

  void WriteJoint(const SimJoint& j, const std::string& pad) {
    const SimLink& link = model_.links[j.link];
    if (j.kind == SimJoint::Kind::kFree) {
      out_ << pad << "<freejoint name=\"" << XmlEscape(j.name) << "\"/>\n";
      return;
    }
    const std::string stops = internal::LimitLabel(assembly_, j);
    if (!stops.empty()) out_ << pad << XmlComment(stops) << "\n";
    static constexpr const char* kType[] = {"hinge", "slide", "ball"};
    out_ << pad << "<joint name=\"" << XmlEscape(j.name) << "\" type=\""
         << kType[static_cast<int>(j.kind)] << "\" pos=\"" << Numbers(j.p_W - link.p_WL) << "\"";
    if (j.kind != SimJoint::Kind::kBall) out_ << " axis=\"" << Numbers(j.axis_W) << "\"";
    const bool slide = j.kind == SimJoint::Kind::kSlide;
    if (j.lower && j.upper) {
      out_ << " limited=\"true\" range=\"" << Number(*j.lower) << " " << Number(*j.upper) << "\"";
    } else if (slide && (j.lower || j.upper)) {
      out_ << " limited=\"true\" range=\"" << Number(j.lower.value_or(-model_.reach)) << " "
           << Number(j.upper.value_or(model_.reach)) << "\"";
    }
    out_ << "/>\n";
  }

  static std::string DriveTendon(const Driver& d) { return d.id + "_drive"; }

  void WriteCouplingsAndLoops() {
    std::ostringstream tendons, equality;
    for (std::size_t k = 0; k < model_.couplings.size(); ++k) {
      // Every coupling is a fixed tendon, sum of coef * joint, held at its file-pose length 0.
      // (An <equality><joint> of two joints says the same, but MuJoCo 2.2 softens it by the
      // joints' inverse inertias added without the ratio, which leaves a screw's slide or a
      // light pinion's rack almost free; a tendon's softness comes from its own Jacobian.)
      const SimCoupling& c = model_.couplings[k];
      const std::string name = fmt::format("coupling_{}", k + 1);
      std::string relation = fmt::format("{} =", model_.joints[c.terms[0].first].name);
      for (std::size_t t = 1; t < c.terms.size(); ++t) {
        fmt::format_to(std::back_inserter(relation), "{}{} * {}", t > 1 ? " + " : " ",
                       Number(-c.terms[t].second / c.terms[0].second),
                       model_.joints[c.terms[t].first].name);
      }
      if (c.terms.size() == 1) relation += " 0";
      equality << "    "
               << XmlComment(fmt::format(
                      "{}: {}", internal::PairLabel(assembly_, analysis_, c.pair), relation))
               << "\n    <tendon tendon1=\"" << name << "\" polycoef=\"0 0 0 0 0\"/>\n";
      tendons << "    <fixed name=\"" << name << "\">\n";
      for (const auto& [j, coefficient] : c.terms) {
        tendons << "      <joint joint=\"" << XmlEscape(model_.joints[j].name) << "\" coef=\""
                << Number(coefficient / c.terms[0].second) << "\"/>\n";
      }
      tendons << "    </fixed>\n";
    }
    for (const SimActuator& a : model_.actuators) {
      const Driver& d = assembly_.drivers()[a.driver];
      // A driver across several joints acts on their sum: a fixed tendon.
      if (a.terms.size() > 1) {
        tendons << "    <fixed name=\"" << XmlEscape(DriveTendon(d)) << "\">\n";
        for (const auto& [j, coefficient] : a.terms) {
          tendons << "      <joint joint=\"" << XmlEscape(model_.joints[j].name) << "\" coef=\""
                  << Number(coefficient) << "\"/>\n";
        }
        tendons << "    </fixed>\n";
      }
      if (a.terms.empty() || a.rate != 0.0) continue;
      // A held driver is a brake: an equality holds its joint (or sum) at the file pose.
      equality << "    "
               << XmlComment(fmt::format("driver {} held (rate 0): deactivate to release", d.id))
               << "\n    ";
      if (a.terms.size() == 1) {
        equality << "<joint name=\"" << XmlEscape(d.id) << "\" joint1=\""
                 << XmlEscape(model_.joints[a.terms[0].first].name) << "\"";
      } else {
        equality << "<tendon name=\"" << XmlEscape(d.id) << "\" tendon1=\""
                 << XmlEscape(DriveTendon(d)) << "\"";
      }
      equality << " polycoef=\"0 0 0 0 0\" solimp=\"" << kStiff << "\"/>\n";
    }
    for (const SimLoop& loop : model_.loops) {
      const std::string label = internal::PairLabel(assembly_, analysis_, loop.pair);
      if (loop.anchors_W.empty()) {
        equality << "    " << XmlComment(fmt::format("loop left open: {}", label)) << "\n";
        continue;
      }
      equality << "    " << XmlComment(fmt::format("loop closed: {}", label)) << "\n";
      for (const Eigen::Vector3d& anchor : loop.anchors_W) {
        equality << "    <connect body1=\"" << BodyName(loop.link_a) << "\" body2=\""
                 << BodyName(loop.link_b) << "\" anchor=\""
                 << Numbers(anchor - model_.links[loop.link_a].p_WL) << "\" solimp=\"" << kStiff
                 << "\"/>\n";
      }
    }
    if (!tendons.str().empty()) out_ << "  <tendon>\n" << tendons.str() << "  </tendon>\n";
    if (!equality.str().empty()) out_ << "  <equality>\n" << equality.str() << "  </equality>\n";
  }

  // The moment of inertia about joint j's axis of its link and every link below it, kg m^2.
  double InertiaAbout(const SimJoint& j) const {
    double inertia = 0.0;
    for (std::size_t l = 1; l < model_.links.size(); ++l) {
      bool below = false;
      for (std::optional<std::size_t> k = l; k && !below; k = model_.links[*k].parent) {
        below = *k == j.link;
      }
      if (!below) continue;
      const SimLink& link = model_.links[l];
      if (j.kind == SimJoint::Kind::kSlide) {
        inertia += link.mass;
        continue;
      }
      const Eigen::Vector3d r = link.p_WL + link.p_LCm - j.p_W;
      const Eigen::Vector3d off_axis = r - r.dot(j.axis_W) * j.axis_W;
      inertia += j.axis_W.dot(link.I_Cm * j.axis_W) + link.mass * off_axis.squaredNorm();
    }
    return inertia;
  }

  void WriteActuators() {
    std::string controls;
    std::ostringstream actuators;
    for (const SimActuator& a : model_.actuators) {
      const Driver& d = assembly_.drivers()[a.driver];
      if (a.terms.empty()) {
        actuators << "    " << XmlComment(a.reason) << "\n";
        continue;
      }
      if (a.rate == 0.0) continue;  // held: an equality, above
      // The joint nearest the driver's part sets the gain; a single joint is driven in its own
      // sense, a sum through its tendon.
      const SimJoint& j = model_.joints[a.terms.front().first];
      const double kv = InertiaAbout(j) / kDriveTimeConstant;
      const bool single = a.terms.size() == 1;
      const double rate = a.ActingRate();
      actuators << "    "
                << XmlComment(fmt::format("driver {}: {} {}{}", d.id, Number(rate),
                                          j.kind == SimJoint::Kind::kSlide ? "m/s" : "rad/s",
                                          single ? "" : " (the sum of its tendon's joints)"))
                << "\n";
      actuators << "    <velocity name=\"" << XmlEscape(d.id) << "\" "
                << (single ? "joint" : "tendon") << "=\""
                << XmlEscape(single ? j.name : DriveTendon(d)) << "\" kv=\"" << Number(kv)
                << "\"/>\n";
      controls += (controls.empty() ? "" : " ") + Number(rate);
    }
    if (!actuators.str().empty()) out_ << "  <actuator>\n" << actuators.str() << "  </actuator>\n";
    if (options_.drive && !controls.empty()) {
      out_ << "  <keyframe>\n"
           << "    " << XmlComment("the file pose, every driver at its rate") << "\n"
           << "    <key name=\"drive\" ctrl=\"" << controls << "\"/>\n"
           << "  </keyframe>\n";
    }
  }

  const Assembly& assembly_;
  const Analysis& analysis_;
  const SimulationModel& model_;
  const MjcfOptions& options_;
  std::ostringstream out_;
};

}  // namespace

std::string MjcfText(const Assembly& assembly, const Analysis& analysis,
                     const SimulationModel& model, const MjcfOptions& options) {
  return MjcfWriter(assembly, analysis, model, options).Write();
}

}  // namespace mechanist
