// Test fixtures built with Open CASCADE: the only test translation unit that includes it.
#include "io/occt/step_fixtures.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Builder.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Interface_Check.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <StepData_Protocol.hxx>
#include <StepData_StepModel.hxx>
#include <StepData_StepWriter.hxx>
#include <StepSelect_WorkLibrary.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSControl_WorkSession.hxx>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <gp_Ax2.hxx>
#include <gp_Trsf.hxx>
#include <gp_Vec.hxx>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/occt/part21_work_library.h"
#include "kernel/features/involute_gear.h"

namespace mechanist::testing {

namespace {

void WriteStep(const TopoDS_Shape& shape, const std::filesystem::path& file) {
  Message::DefaultMessenger()->ChangePrinters().Clear();  // the writer's statistics
  STEPControl_Writer writer;
  if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone ||
      writer.Write(file.string().c_str()) != IFSelect_RetDone) {
    throw std::runtime_error("cannot write " + file.string());
  }
}

// A B-spline edge through `points` (at least two), or a straight one through two.
TopoDS_Edge Through(const std::vector<gp_Pnt>& points) {
  if (points.size() == 2) return BRepBuilderAPI_MakeEdge(points[0], points[1]).Edge();
  Handle(TColgp_HArray1OfPnt) array = new TColgp_HArray1OfPnt(1, static_cast<int>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    array->SetValue(static_cast<int>(i) + 1, points[i]);
  GeomAPI_Interpolate interpolate(array, false, 1e-7);
  interpolate.Perform();
  return BRepBuilderAPI_MakeEdge(interpolate.Curve()).Edge();
}

// The transverse outline of a gear of normal module `module` and helix angle `helix` (0: a
// spur gear): involute teeth of module m / cos(helix), pressure angle atan(tan 20 deg /
// cos(helix)), addendum m, dedendum 1.25 m.
Ring2d GearOutline(int teeth, double module, double helix) {
  InvoluteOutlineSpec spec;
  spec.teeth = teeth;
  spec.module = module / std::cos(helix);
  spec.pressure_angle = std::atan(std::tan(20.0 * M_PI / 180.0) / std::cos(helix));
  spec.addendum = module;
  spec.dedendum = 1.25 * module;
  spec.max_arc_step = 2.0 * M_PI / teeth / 12.0;
  spec.flank_points = 12;
  return InvoluteOutline(spec);
}

// The outline `ring` turned by `angle` about z at height `z` as a closed wire: split at its
// corners (where it turns by more than 20 degrees), each smooth run an interpolated B-spline.
TopoDS_Wire OutlineWire(const Ring2d& ring, double z, double angle) {
  const std::size_t n = ring.size();
  const auto corner = [&](std::size_t i) {
    const Eigen::Vector2d a = ring[i] - ring[(i + n - 1) % n], b = ring[(i + 1) % n] - ring[i];
    return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) >
           20.0 * M_PI / 180.0;
  };
  const double c = std::cos(angle), s = std::sin(angle);
  const auto point = [&](std::size_t i) {
    return gp_Pnt(c * ring[i].x() - s * ring[i].y(), s * ring[i].x() + c * ring[i].y(), z);
  };
  std::size_t start = 0;
  while (!corner(start)) ++start;
  BRepBuilderAPI_MakeWire wire;
  std::vector<gp_Pnt> run = {point(start)};
  for (std::size_t k = 1; k <= n; ++k) {
    const std::size_t i = (start + k) % n;
    run.push_back(point(i));
    if (corner(i)) {
      wire.Add(Through(run));
      run = {run.back()};
    }
  }
  return wire.Wire();
}

// A bore of 0.3 times the gear's pitch diameter through `body`.
TopoDS_Shape Bored(const TopoDS_Shape& body, int teeth, double module) {
  const double bore = 0.15 * module * teeth;
  return BRepAlgoAPI_Cut(body,
                         BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -1), gp::DZ()), bore, 12))
      .Shape();
}

// A spur gear about the z axis, extruded from z = 0 to 10, with a bore.
TopoDS_Shape SpurGear(int teeth, double module) {
  const TopoDS_Face face =
      BRepBuilderAPI_MakeFace(OutlineWire(GearOutline(teeth, module, 0.0), 0.0, 0.0)).Face();
  return Bored(BRepPrimAPI_MakePrism(face, gp_Vec(0, 0, 10)).Shape(), teeth, module);
}

// A helical gear about the z axis from z = 0 to 10, with a bore: a loft (B-spline flanks)
// through the transverse outline at 5 heights, turned by z tan(helix) / r at height z.
TopoDS_Shape HelicalGear(int teeth, double module, double helix) {
  const double pitch_radius = module * teeth / (2.0 * std::cos(helix));
  const Ring2d ring = GearOutline(teeth, module, helix);
  BRepOffsetAPI_ThruSections loft(true, false, 1e-6);
  loft.CheckCompatibility(false);
  for (int k = 0; k <= 4; ++k) {
    const double z = 2.5 * k;
    loft.AddWire(OutlineWire(ring, z, z * std::tan(helix) / pitch_radius));
  }
  loft.Build();
  if (!loft.IsDone()) throw std::runtime_error("cannot loft a helical gear");
  return Bored(loft.Shape(), teeth, module);
}

// A straight or spiral bevel gear about +z with its pitch cone's apex at the origin (see
// WriteBevelGearPairStep).
TopoDS_Shape BevelGear(int teeth, double module, double pitch_angle, double spiral) {
  const double L = module * teeth / (2.0 * std::sin(pitch_angle)), toe = 2.0 / 3.0;
  const Ring2d heel = GearOutline(teeth, module, 0.0);
  // Straight: a ruled loft from toe to heel. Spiral: a smooth one through 7 sections, each
  // turned by theta(s) = tan(spiral) ln(s / L) / sin(pitch angle) at cone distance s, which
  // keeps the teeth at the spiral angle all along the pitch cone.
  const int sections = spiral == 0.0 ? 2 : 7;
  BRepOffsetAPI_ThruSections loft(true, spiral == 0.0, 1e-6);
  loft.CheckCompatibility(false);
  for (int i = 0; i < sections; ++i) {
    const double scale = toe + (1.0 - toe) * i / (sections - 1);
    Ring2d ring = heel;
    for (Eigen::Vector2d& p : ring) p *= scale;
    const double theta = std::tan(spiral) * std::log(scale) / std::sin(pitch_angle);
    loft.AddWire(OutlineWire(ring, scale * L * std::cos(pitch_angle), theta));
  }
  loft.Build();
  if (!loft.IsDone()) throw std::runtime_error("cannot loft a bevel gear");
  const double bore = 0.15 * toe * module * teeth;
  return BRepAlgoAPI_Cut(
             loft.Shape(),
             BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, 0), gp::DZ()), bore, 2 * L).Shape())
      .Shape();
}

// A cylindrical worm about +z from z = 0 to `length`: `starts` threads of axial module
// `module` (axial pitch pi m, lead starts pi m), hand `right`, pitch diameter 10 m, addendum m,
// dedendum 1.25 m, the axial section's flanks at 20 degrees. A ruled loft (B-spline faces)
// through its transverse section at 32 heights per lead, each the one at z = 0 turned by
// 2 pi z / lead (the other way for a left hand); each section is split where the profile
// meets the tip and the root, each piece an interpolated B-spline.
TopoDS_Shape Worm(int starts, double module, bool right, double length) {
  const double pitch = M_PI * module, lead = starts * pitch, r_pitch = 5 * module;
  const double tan_a = std::tan(20.0 * M_PI / 180.0);
  const double tip_half = pitch / 4 - module * tan_a, root_half = pitch / 4 + 1.25 * module * tan_a;
  // The radius where the section at z = 0 meets the thread at axial offset u from a tooth's
  // middle (within half a pitch).
  const auto radius = [&](double u) {
    return std::clamp(r_pitch + (pitch / 4 - std::abs(u)) / tan_a, r_pitch - 1.25 * module,
                      r_pitch + module);
  };
  // At angle theta the section at z = 0 shows the thread at axial offset -lead theta / 2 pi
  // (the profile is symmetric, so the offset's sign does not matter): per period of 2 pi /
  // starts, the pieces between these offsets (root, flank, tip, flank, root).
  const std::vector<double> breaks = {-pitch / 2, -root_half, -tip_half, tip_half, root_half};
  const double hand = right ? 1.0 : -1.0;
  const auto section = [&](double z) {
    BRepBuilderAPI_MakeWire wire;
    for (int period = 0; period < starts; ++period) {
      for (std::size_t k = 0; k < breaks.size(); ++k) {
        const double u0 = breaks[k], u1 = k + 1 < breaks.size() ? breaks[k + 1] : pitch / 2;
        std::vector<gp_Pnt> run;
        for (int i = 0; i <= 8; ++i) {
          const double u = u0 + (u1 - u0) * i / 8;
          const double theta =
              2 * M_PI * (period + (u + pitch / 2) / pitch) / starts + hand * 2 * M_PI * z / lead;
          run.emplace_back(radius(u) * std::cos(theta), radius(u) * std::sin(theta), z);
        }
        wire.Add(Through(run));
      }
    }
    return wire.Wire();
  };
  BRepOffsetAPI_ThruSections loft(true, true, 1e-6);
  loft.CheckCompatibility(false);
  const int sections = static_cast<int>(std::ceil(32 * length / lead));
  for (int k = 0; k <= sections; ++k) loft.AddWire(section(length * k / sections));
  loft.Build();
  if (!loft.IsDone()) throw std::runtime_error("cannot loft a worm");
  return loft.Shape();
}

}  // namespace

void WriteWormAndWheelStep(const std::filesystem::path& file, int starts, bool right,
                           int wheel_teeth, double module) {
  const double centre = module * (10 + wheel_teeth) / 2.0;
  const double length = 6 * M_PI * module;
  gp_Trsf across, place;
  across.SetRotation(gp::OY(), M_PI / 2);  // +z onto +x
  place.SetTranslation(gp_Vec(-length / 2, -centre, 5));
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  builder.Add(
      all,
      BRepBuilderAPI_Transform(Worm(starts, module, right, length), place * across, true).Shape());
  builder.Add(all, SpurGear(wheel_teeth, module));
  WriteStep(all, file);
}

void WriteSpurGearPairStep(const std::filesystem::path& file, int teeth_a, int teeth_b,
                           double module) {
  gp_Trsf place;
  place.SetRotation(gp::OZ(), M_PI / teeth_b);  // a tooth space of b faces a tooth of a
  gp_Trsf shift;
  shift.SetTranslation(gp_Vec(module * (teeth_a + teeth_b) / 2.0, 0, 0));
  const TopoDS_Shape b =
      BRepBuilderAPI_Transform(SpurGear(teeth_b, module), shift * place, true).Shape();
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  builder.Add(all, SpurGear(teeth_a, module));
  builder.Add(all, b);
  WriteStep(all, file);
}

void WriteHelicalGearPairStep(const std::filesystem::path& file, int teeth_a, int teeth_b,
                              double module, double helix) {
  gp_Trsf place;
  place.SetRotation(gp::OZ(), M_PI / teeth_b);
  gp_Trsf shift;
  shift.SetTranslation(gp_Vec(module / std::cos(helix) * (teeth_a + teeth_b) / 2.0, 0, 0));
  const TopoDS_Shape b =
      BRepBuilderAPI_Transform(HelicalGear(teeth_b, module, -helix), shift * place, true).Shape();
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  builder.Add(all, HelicalGear(teeth_a, module, helix));
  builder.Add(all, b);
  WriteStep(all, file);
}

void WriteBevelGearPairStep(const std::filesystem::path& file, int teeth_a, int teeth_b,
                            double module, double spiral_a, double spiral_b) {
  const double angle_a = std::atan2(teeth_a, teeth_b), angle_b = std::atan2(teeth_b, teeth_a);
  gp_Trsf phase, across;
  phase.SetRotation(gp::OZ(), M_PI / teeth_b);  // a tooth space of b faces a tooth of a
  across.SetRotation(gp::OY(), M_PI / 2);       // +z onto +x
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  builder.Add(all, BevelGear(teeth_a, module, angle_a, spiral_a));
  builder.Add(all, BRepBuilderAPI_Transform(BevelGear(teeth_b, module, angle_b, spiral_b),
                                            across * phase, true)
                       .Shape());
  WriteStep(all, file);
}

void WriteRingGearHousingStep(const std::filesystem::path& file, int ring_teeth, int pinion_teeth,
                              double module) {
  const double side = 2.5 * module * (ring_teeth + 10);
  TopoDS_Shape housing =
      BRepPrimAPI_MakeBox(gp_Pnt(-side / 2, -side / 2, 0), side, side, 10).Shape();
  InvoluteOutlineSpec spaces;
  spaces.teeth = ring_teeth;
  spaces.module = module;
  spaces.pressure_angle = 20.0 * M_PI / 180.0;
  spaces.addendum = 1.25 * module;
  spaces.dedendum = module;
  spaces.max_arc_step = 2.0 * M_PI / ring_teeth / 12.0;
  spaces.flank_points = 12;
  const TopoDS_Face cavity =
      BRepBuilderAPI_MakeFace(OutlineWire(InvoluteOutline(spaces), -1.0, 0.0)).Face();
  housing = BRepAlgoAPI_Cut(housing, BRepPrimAPI_MakePrism(cavity, gp_Vec(0, 0, 12)).Shape());
  const double corner = 0.4 * side, bolt = 0.3 * module * ring_teeth / 4;
  for (const double x : {-corner, corner}) {
    for (const double y : {-corner, corner}) {
      housing = BRepAlgoAPI_Cut(
          housing, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, -1), gp::DZ()), bolt, 12).Shape());
    }
  }
  gp_Trsf shift;
  shift.SetTranslation(gp_Vec(module * (ring_teeth - pinion_teeth) / 2.0, 0, 0));
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  builder.Add(all, housing);
  builder.Add(all, BRepBuilderAPI_Transform(SpurGear(pinion_teeth, module), shift, true).Shape());
  WriteStep(all, file);
}

void WriteRackAndPinionStep(const std::filesystem::path& file, int pinion_teeth, double module,
                            int rack_teeth) {
  // The rack: straight flanks at 20 degrees, addendum m above the pitch line y = 0, dedendum
  // 1.25 m below it, its body down to y = -4.25 m, teeth centred on x = (k + 1/2) pi m.
  const double m = module, pitch = M_PI * m, tan_flank = std::tan(20.0 * M_PI / 180.0);
  const double tip_half = pitch / 4 - m * tan_flank, root_half = pitch / 4 + 1.25 * m * tan_flank;
  const double length = rack_teeth * pitch;
  BRepBuilderAPI_MakePolygon outline;
  outline.Add(gp_Pnt(0, -4.25 * m, 0));
  outline.Add(gp_Pnt(length, -4.25 * m, 0));
  outline.Add(gp_Pnt(length, -1.25 * m, 0));
  for (int k = rack_teeth - 1; k >= 0; --k) {
    const double centre = (k + 0.5) * pitch;
    outline.Add(gp_Pnt(centre + root_half, -1.25 * m, 0));
    outline.Add(gp_Pnt(centre + tip_half, m, 0));
    outline.Add(gp_Pnt(centre - tip_half, m, 0));
    outline.Add(gp_Pnt(centre - root_half, -1.25 * m, 0));
  }
  outline.Add(gp_Pnt(0, -1.25 * m, 0));
  outline.Close();
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(outline.Wire()).Face();
  const TopoDS_Shape rack = BRepPrimAPI_MakePrism(face, gp_Vec(0, 0, 10)).Shape();
  // The pinion above the rack's middle, its pitch circle on the pitch line.
  gp_Trsf shift;
  shift.SetTranslation(gp_Vec(length / 2, m * pinion_teeth / 2.0, 0));
  const TopoDS_Shape pinion =
      BRepBuilderAPI_Transform(SpurGear(pinion_teeth, module), shift, true).Shape();
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  builder.Add(all, rack);
  builder.Add(all, pinion);
  WriteStep(all, file);
}

void WriteMisorientedBoxesStep(const std::filesystem::path& file) {
  BRep_Builder builder;
  TopoDS_Compound all;
  builder.MakeCompound(all);
  for (int k = 0; k < 3; ++k) {
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(50.0 * k, 0, 0), 10, 20, 30).Shape();
    TopoDS_Shell shell;
    builder.MakeShell(shell);
    for (TopExp_Explorer e(box, TopAbs_FACE); e.More(); e.Next()) {
      const TopoDS_Face& face = TopoDS::Face(e.Current());
      const bool top = BRepAdaptor_Surface(face).Plane().Location().Z() > 29.9 &&
                       std::abs(BRepAdaptor_Surface(face).Plane().Axis().Direction().Z()) > 0.5;
      builder.Add(shell, (k == 1 && top) || k == 2 ? face.Reversed() : TopoDS_Shape(face));
    }
    TopoDS_Solid solid;
    builder.MakeSolid(solid);
    builder.Add(solid, shell);
    builder.Add(all, solid);
  }
  WriteStep(all, file);
}

namespace {

// The STEP file `in` read into a new XCAF document of `app`, with its names (the reader's and
// writer's statistics silenced). Throws std::runtime_error when it cannot read.
Handle(TDocStd_Document)
    ReadXcaf(const std::filesystem::path& in, const Handle(XCAFApp_Application) & app) {
  Message::DefaultMessenger()->ChangePrinters().Clear();
  Handle(TDocStd_Document) document;
  app->NewDocument("MDTV-XCAF", document);
  STEPCAFControl_Reader reader;
  reader.SetNameMode(true);
  if (reader.ReadFile(in.string().c_str()) != IFSelect_RetDone || !reader.Transfer(document)) {
    throw std::runtime_error("cannot read " + in.string());
  }
  return document;
}

// The entities of the STEP text `text` as written (lines joined): their numbers, types and
// the text after "#n = " up to the closing ';'; and the text before and after them.
struct StepText {
  std::string head, tail;
  std::map<int, std::string> entities;
};

StepText ParseStepText(const std::string& text) {
  StepText t;
  const std::size_t data = text.find("DATA;");
  const std::size_t end = text.find("ENDSEC;", data);
  if (data == std::string::npos || end == std::string::npos) {
    throw std::runtime_error("no DATA section");
  }
  t.head = text.substr(0, data + 5);
  t.tail = text.substr(end);
  std::string body = text.substr(data + 5, end - data - 5);
  std::erase(body, '\n');
  std::erase(body, '\r');
  for (std::size_t at = body.find('#'); at != std::string::npos;) {
    const std::size_t eq = body.find('=', at), semi = body.find(';', at);
    const int id = std::stoi(body.substr(at + 1, eq - at - 1));
    std::size_t from = eq + 1;
    while (body[from] == ' ') ++from;
    t.entities[id] = body.substr(from, semi - from);
    at = body.find('#', semi);
  }
  return t;
}

// The entity numbers `text` refers to.
std::vector<int> References(const std::string& text) {
  std::vector<int> ids;
  for (std::size_t at = text.find('#'); at != std::string::npos; at = text.find('#', at + 1)) {
    ids.push_back(std::stoi(text.substr(at + 1)));
  }
  return ids;
}

// `text` (an entity's arguments) with its real numbers whose position `scaled(k)` accepts
// (k counting the real numbers from 0) divided by `factor`.
std::string Rescaled(const std::string& text, double factor,
                     const std::function<bool(int)>& scaled) {
  std::string out;
  int k = 0;
  for (std::size_t i = 0; i < text.size();) {
    const bool starts_number =
        (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '-') && i > 0 &&
        (text[i - 1] == '(' || text[i - 1] == ',');
    if (!starts_number) {
      out += text[i++];
      continue;
    }
    std::size_t length = 0;
    const double value = std::stod(text.substr(i), &length);
    const std::string number = text.substr(i, length);
    i += length;
    if (number.find_first_of(".E") == std::string::npos || !scaled(k++)) {
      out += number;  // an integer (a degree, a count) or a real left as it is
      continue;
    }
    char written[64];
    std::snprintf(written, sizeof written, "%.17G", value / factor);
    std::string r = written;
    if (r.find('.') == std::string::npos) {
      const std::size_t e = r.find('E');
      r.insert(e == std::string::npos ? r.size() : e, ".");
    }
    out += r;
  }
  return out;
}

// Rewrites the single STEP file `file` (written by Open CASCADE in millimetres, without curves
// on surfaces) so that every other solid's shape representation declares inches and holds its
// lengths in inches. Throws std::runtime_error on an entity whose lengths it does not know.
void DeclareInchesInEveryOtherSolid(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  StepText t = ParseStepText(
      std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()));
  in.close();
  auto type_of = [&](int id) { return t.entities.at(id).substr(0, t.entities.at(id).find('(')); };
  std::vector<int> solids;
  for (const auto& [id, text] : t.entities) {
    if (text.rfind("ADVANCED_BREP_SHAPE_REPRESENTATION(", 0) == 0) solids.push_back(id);
  }
  // Which real arguments are lengths, by entity type (directions and angles are not).
  const std::map<std::string, std::function<bool(int)>> lengths = {
      {"CARTESIAN_POINT", [](int) { return true; }},
      {"VECTOR", [](int) { return true; }},
      {"CIRCLE", [](int) { return true; }},
      {"CYLINDRICAL_SURFACE", [](int) { return true; }},
      {"SPHERICAL_SURFACE", [](int) { return true; }},
      {"TOROIDAL_SURFACE", [](int) { return true; }},
      {"CONICAL_SURFACE", [](int k) { return k == 0; }}};
  int next = t.entities.rbegin()->first + 1;
  std::set<int> done;
  for (std::size_t k = 0; k < solids.size(); k += 2) {
    std::string& representation = t.entities[solids[k]];
    const int context = References(representation).back();
    // Its geometry, everything it refers to short of its context, in inches.
    std::vector<int> stack = References(representation);
    stack.pop_back();
    while (!stack.empty()) {
      const int id = stack.back();
      stack.pop_back();
      if (!done.insert(id).second) continue;
      std::string& text = t.entities.at(id);
      for (const int r : References(text)) stack.push_back(r);
      const std::string type = type_of(id);
      const auto known = lengths.find(type);
      if (known != lengths.end()) {
        text = Rescaled(text, 25.4, known->second);
      } else if (type != "DIRECTION") {
        int reals = 0;
        Rescaled(text, 1.0, [&](int) { return ++reals, false; });
        if (reals > 0) throw std::runtime_error("cannot rewrite the lengths of " + type);
      }
    }
    // Its own context, the length unit an inch.
    // Whatever else lies in that context must be that geometry too.
    for (const auto& [id, text] : t.entities) {
      std::vector<int> refers = References(text);
      if (id == solids[k] || std::find(refers.begin(), refers.end(), context) == refers.end()) {
        continue;
      }
      std::erase(refers, context);
      if (!std::all_of(refers.begin(), refers.end(), [&](int r) { return done.count(r) > 0; })) {
        throw std::runtime_error("a representation context shared with other items");
      }
    }
    std::string& units = t.entities.at(context);
    const std::size_t list = units.find("GLOBAL_UNIT_ASSIGNED_CONTEXT((");
    if (list == std::string::npos) throw std::runtime_error("no units in a context");
    const std::size_t mm = units.find('#', list);
    const int millimetre = std::stoi(units.substr(mm + 1));
    units.replace(mm, units.find(',', mm) - mm, "#" + std::to_string(next));
    t.entities[next] = "( CONVERSION_BASED_UNIT('INCH',#" + std::to_string(next + 1) +
                       ") LENGTH_UNIT() NAMED_UNIT(#" + std::to_string(next + 2) + ") )";
    t.entities[next + 1] =
        "LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),#" + std::to_string(millimetre) + ")";
    t.entities[next + 2] = "DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.)";
    next += 3;
  }
  std::ofstream out(file, std::ios::binary);
  out << t.head << "\n";
  for (const auto& [id, text] : t.entities) out << "#" << id << " = " << text << ";\n";
  out << t.tail;
}

// Writes `document` as an assembly file `out` whose products are each in a file of their own
// beside it, every other one (by name) in inches; returns the part files' names.
std::vector<std::string> WritePartFiles(const Handle(TDocStd_Document) & document,
                                        const std::filesystem::path& out) {
  // Written twice, in each unit, into directories of their own (the writer names the part
  // files after their shapes); then the references lose the directories, as exporters write
  // them, and the files are taken from either.
  const std::filesystem::path dir = out.parent_path();
  std::map<std::string, std::filesystem::path> written;  // unit -> directory
  for (const char* unit : {"MM", "INCH"}) {
    const std::filesystem::path into = dir / (out.stem().string() + "_" + unit);
    std::filesystem::create_directories(into);
    Interface_Static::SetCVal("write.step.unit", unit);
    STEPCAFControl_Writer writer;
    writer.SetNameMode(true);
    const std::string prefix = into.string() + "/";
    const bool ok = writer.Transfer(document, STEPControl_AsIs, prefix.c_str()) &&
                    writer.Write((into / out.filename()).string().c_str()) == IFSelect_RetDone;
    Interface_Static::SetCVal("write.step.unit", "MM");
    if (!ok) throw std::runtime_error("cannot write " + (into / out.filename()).string());
    written[unit] = into;
  }
  std::vector<std::string> parts;
  for (const auto& entry : std::filesystem::directory_iterator(written["MM"])) {
    if (entry.path().filename() != out.filename()) parts.push_back(entry.path().filename());
  }
  std::sort(parts.begin(), parts.end());
  auto copy_bare = [&](const std::filesystem::path& from, const std::filesystem::path& to) {
    std::ifstream in(from, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const auto& [unit, into] : written) {
      const std::string prefix = into.string() + "/";
      for (std::size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix))
        text.erase(at, prefix.size());
    }
    std::ofstream(to, std::ios::binary) << text;
  };
  copy_bare(written["MM"] / out.filename(), out);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    copy_bare(written[k % 2 == 0 ? "INCH" : "MM"] / parts[k], dir / parts[k]);
  }
  for (const auto& [unit, into] : written) std::filesystem::remove_all(into);
  return parts;
}

}  // namespace

std::vector<std::string> WriteStepVariant(const std::filesystem::path& in,
                                          const std::filesystem::path& out, StepVariant variant) {
  const Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
  const Handle(TDocStd_Document) document = ReadXcaf(in, app);
  const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(document->Main());
  TDF_LabelSequence roots;
  tool->GetFreeShapes(roots);
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  for (int i = 1; i <= roots.Length(); ++i) builder.Add(all, tool->GetShape(roots(i)));
  bool written = false;
  std::vector<std::string> part_files;
  if (variant == StepVariant::kPartFiles) {
    part_files = WritePartFiles(document, out);
    written = true;
  } else if (variant == StepVariant::kMixedUnits) {
    Interface_Static::SetIVal("write.surfacecurve.mode", 0);  // only 3D geometry to rewrite
    STEPCAFControl_Writer writer;
    writer.SetNameMode(true);
    // No colours, layers or validation properties: their lengths would stay in millimetres.
    writer.SetColorMode(false);
    writer.SetLayerMode(false);
    writer.SetPropsMode(false);
    written = writer.Transfer(document, STEPControl_AsIs) &&
              writer.Write(out.string().c_str()) == IFSelect_RetDone;
    Interface_Static::SetIVal("write.surfacecurve.mode", 1);
    if (written) DeclareInchesInEveryOtherSolid(out);
  } else if (variant == StepVariant::kInches) {
    Interface_Static::SetCVal("write.step.unit", "INCH");
    STEPCAFControl_Writer writer;
    writer.SetNameMode(true);
    written = writer.Transfer(document, STEPControl_AsIs) &&
              writer.Write(out.string().c_str()) == IFSelect_RetDone;
    Interface_Static::SetCVal("write.step.unit", "MM");
  } else if (variant == StepVariant::kAp203 || variant == StepVariant::kAp242) {
    // Open CASCADE's schema numbers: 1 AP214 (its default), 3 AP203, 5 AP242; a writer takes
    // it when it is made.
    Interface_Static::SetIVal("write.step.schema", variant == StepVariant::kAp203 ? 3 : 5);
    STEPCAFControl_Writer writer;
    writer.SetNameMode(true);
    written = writer.Transfer(document, STEPControl_AsIs) &&
              writer.Write(out.string().c_str()) == IFSelect_RetDone;
    Interface_Static::SetIVal("write.step.schema", 1);
  } else if (variant == StepVariant::kFlat) {
    TopoDS_Compound solids;
    builder.MakeCompound(solids);
    for (TopExp_Explorer e(all, TopAbs_SOLID); e.More(); e.Next()) builder.Add(solids, e.Current());
    STEPControl_Writer writer;
    written = writer.Transfer(solids, STEPControl_AsIs) == IFSelect_RetDone &&
              writer.Write(out.string().c_str()) == IFSelect_RetDone;
  } else {
    TopoDS_Shape nested = all;
    for (int level = 0; level < 3; ++level) {
      TopoDS_Compound outer;
      builder.MakeCompound(outer);
      builder.Add(outer, nested);
      nested = outer;
    }
    Handle(TDocStd_Document) deep;
    app->NewDocument("MDTV-XCAF", deep);
    XCAFDoc_DocumentTool::ShapeTool(deep->Main())->AddShape(nested, true);
    STEPCAFControl_Writer writer;
    written = writer.Transfer(deep, STEPControl_AsIs) &&
              writer.Write(out.string().c_str()) == IFSelect_RetDone;
    app->Close(deep);
  }
  app->Close(document);
  if (!written) throw std::runtime_error("cannot write " + out.string());
  return part_files;
}

void WriteNurbsCopy(const std::filesystem::path& in, const std::filesystem::path& out) {
  const Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
  const Handle(TDocStd_Document) document = ReadXcaf(in, app);
  const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(document->Main());
  TDF_LabelSequence shapes;
  tool->GetShapes(shapes);
  for (int i = 1; i <= shapes.Length(); ++i) {
    if (tool->IsAssembly(shapes(i))) continue;
    tool->SetShape(shapes(i), BRepBuilderAPI_NurbsConvert(tool->GetShape(shapes(i))).Shape());
  }
  tool->UpdateAssemblies();
  STEPCAFControl_Writer writer;
  writer.SetNameMode(true);
  if (!writer.Transfer(document, STEPControl_AsIs) ||
      writer.Write(out.string().c_str()) != IFSelect_RetDone) {
    throw std::runtime_error("cannot write " + out.string());
  }
  app->Close(document);
}

void WritePuckStep(const std::filesystem::path& file, double radius, double height, double fillet,
                   bool bspline) {
  const TopoDS_Shape cylinder = BRepPrimAPI_MakeCylinder(radius, height).Shape();
  BRepFilletAPI_MakeFillet rounded(cylinder);
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(cylinder, TopAbs_EDGE, edges);
  for (int i = 1; i <= edges.Extent(); ++i) {
    if (BRepAdaptor_Curve(TopoDS::Edge(edges(i))).GetType() == GeomAbs_Circle) {
      rounded.Add(fillet, TopoDS::Edge(edges(i)));
    }
  }
  rounded.Build();
  if (!rounded.IsDone()) throw std::runtime_error("cannot round the puck's edges");
  WriteStep(bspline ? BRepBuilderAPI_NurbsConvert(rounded.Shape()).Shape() : rounded.Shape(), file);
}

void WriteConesAndBallStep(const std::filesystem::path& file) {
  const gp_Dir z(0, 0, 1);
  TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40, 40, 10).Shape();
  block = BRepAlgoAPI_Cut(block, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(20, 20, -1), z), 3, 12))
              .Shape();
  // 45 degrees from radius 3 at z = 7 past the top (radius 6 at z = 10).
  block =
      BRepAlgoAPI_Cut(block, BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(20, 20, 7), z), 3, 7, 4)).Shape();
  const TopoDS_Shape pin =
      BRepAlgoAPI_Fuse(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(60, 20, 20), z), 2.5, 20),
                       BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(60, 20, 15), z), 0, 2.5, 5))
          .Shape();
  const TopoDS_Shape ball = BRepPrimAPI_MakeSphere(gp_Pnt(0, 60, 5), 5).Shape();
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  for (const TopoDS_Shape& s : {block, pin, ball}) builder.Add(all, s);
  WriteStep(all, file);
}

void WriteSocketBlockStep(const std::filesystem::path& file, double diameter) {
  const TopoDS_Shape cube = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 20, 20, 20).Shape();
  WriteStep(BRepAlgoAPI_Cut(cube, BRepPrimAPI_MakeSphere(gp_Pnt(10, 10, 18), diameter / 2).Shape())
                .Shape(),
            file);
}

namespace {

// A tube about z from z0 to z1 between radii r_in and r_out.
TopoDS_Shape Tube(double r_in, double r_out, double z0, double z1) {
  const gp_Ax2 axis(gp_Pnt(0, 0, z0), gp_Dir(0, 0, 1));
  return BRepAlgoAPI_Cut(BRepPrimAPI_MakeCylinder(axis, r_out, z1 - z0).Shape(),
                         BRepPrimAPI_MakeCylinder(axis, r_in, z1 - z0).Shape())
      .Shape();
}

// `count` rollers of diameter `d` from z0 to z1, their axes along z on a circle of radius
// `pitch` about it.
void AddRollers(BRep_Builder& builder, TopoDS_Compound& all, int count, double d, double pitch,
                double z0, double z1) {
  for (int k = 0; k < count; ++k) {
    const double a = 2 * M_PI * k / count;
    const gp_Ax2 axis(gp_Pnt(pitch * std::cos(a), pitch * std::sin(a), z0), gp_Dir(0, 0, 1));
    builder.Add(all, BRepPrimAPI_MakeCylinder(axis, d / 2, z1 - z0).Shape());
  }
}

}  // namespace

void WriteBallBearingStep(const std::filesystem::path& file, int balls, int copies, bool cage) {
  const double pitch = 23.5 / 2, ball = 4.762 / 2, groove = 0.52 * 4.762, width = 9;
  const TopoDS_Shape raceway = BRepPrimAPI_MakeTorus(gp_Ax2(), pitch, groove).Shape();
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  for (int copy = 0; copy < copies; ++copy) {
    gp_Trsf shift;
    shift.SetTranslation(gp_Vec(0, 0, width * copy));
    auto add = [&](const TopoDS_Shape& shape) {
      builder.Add(all, BRepBuilderAPI_Transform(shape, shift, true).Shape());
    };
    add(BRepAlgoAPI_Cut(Tube(7.5, 20.5 / 2, -width / 2, width / 2), raceway).Shape());
    add(BRepAlgoAPI_Cut(Tube(26.7 / 2, 16, -width / 2, width / 2), raceway).Shape());
    TopoDS_Shape retainer = Tube(10.6, 12.9, -3, 3);
    for (int k = 0; k < balls; ++k) {
      const double a = 2 * M_PI * k / balls;
      const gp_Pnt centre(pitch * std::cos(a), pitch * std::sin(a), 0);
      add(BRepPrimAPI_MakeSphere(centre, ball).Shape());
      if (cage) retainer = BRepAlgoAPI_Cut(retainer, BRepPrimAPI_MakeSphere(centre, 2.5)).Shape();
    }
    if (cage) add(retainer);
  }
  WriteStep(all, file);
}

void WriteThreeSolidBallBearingStep(const std::filesystem::path& file) {
  const double pitch = 23.5 / 2, ball = 4.762 / 2, groove = 0.52 * 4.762, width = 9;
  const TopoDS_Shape raceway = BRepPrimAPI_MakeTorus(gp_Ax2(), pitch, groove).Shape();
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  builder.Add(all, BRepAlgoAPI_Cut(Tube(7.5, 20.5 / 2, -width / 2, width / 2), raceway).Shape());
  builder.Add(all, BRepAlgoAPI_Cut(Tube(26.7 / 2, 16, -width / 2, width / 2), raceway).Shape());
  // Each ball a sphere of its own, as a CAD system places copies: the seams of the balls at 80
  // and 280 degrees run through the cage, so that the faces of those balls have two wires, one
  // running along the seam, and read from STEP their outer bound is turned over.
  TopoDS_Shape balls_and_cage = Tube(11, 12.5, -1.5, 1.5);
  for (int k = 0; k < 9; ++k) {
    const double angle = 2 * M_PI * k / 9;
    const gp_Pnt centre(pitch * std::cos(angle), pitch * std::sin(angle), 0);
    balls_and_cage =
        BRepAlgoAPI_Fuse(balls_and_cage, BRepPrimAPI_MakeSphere(centre, ball).Shape()).Shape();
  }
  builder.Add(all, balls_and_cage);
  WriteStep(all, file);
}

void WriteRollerBearingStep(const std::filesystem::path& file) {
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  builder.Add(all, Tube(12.5, 16, -7.5, 7.5));
  TopoDS_Shape outer = BRepAlgoAPI_Fuse(Tube(22.5, 26, -7.5, 7.5), Tube(19.5, 22.5, -7.5, -4.5));
  outer = BRepAlgoAPI_Fuse(outer, Tube(19.5, 22.5, 4.5, 7.5));
  builder.Add(all, outer);
  AddRollers(builder, all, 13, 6.5, 19.25, -4, 4);
  WriteStep(all, file);
}

namespace {

// The solid swept by the closed polygon `rz` (radius, z) turning once about z.
TopoDS_Shape Revolved(const std::vector<std::array<double, 2>>& rz) {
  BRepBuilderAPI_MakePolygon outline;
  for (const auto& [r, z] : rz) outline.Add(gp_Pnt(r, 0, z));
  outline.Close();
  return BRepPrimAPI_MakeRevol(BRepBuilderAPI_MakeFace(outline.Wire()).Face(), gp::OZ()).Shape();
}

}  // namespace

void WriteTaperedRollerBearingStep(const std::filesystem::path& file,
                                   const TaperedRollerBearingOptions& options) {
  const double tilt = 15 * M_PI / 180, taper = 2.5 * M_PI / 180, pitch = 19.5;
  const double apex = -pitch / std::tan(tilt);  // z where every cone's apex lies
  // The raceways touch each roller along its lines nearest to and farthest from the axis.
  auto inner_raceway = [&](double z) { return (z - apex) * std::tan(tilt - taper); };
  auto outer_raceway = [&](double z) { return (z - apex) * std::tan(tilt + taper); };
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  if (options.raceway_on_shaft) {
    builder.Add(all, Revolved({{0, -30},
                               {12.5, -30},
                               {12.5, -8},
                               {inner_raceway(-8), -8},
                               {inner_raceway(7), 7},
                               {19, 7},
                               {19, 8},
                               {12.5, 8},
                               {12.5, 30},
                               {2.5, 30},
                               {2.5, 20},
                               {0, 20}}));
  } else {
    builder.Add(all, Revolved({{12.5, -8},
                               {inner_raceway(-8), -8},
                               {inner_raceway(7), 7},
                               {19, 7},
                               {19, 8},
                               {12.5, 8}}));
  }
  builder.Add(all,
              Revolved({{outer_raceway(-7), -7}, {26, -7}, {26, 5.5}, {outer_raceway(5.5), 5.5}}));
  const int rollers = 15;
  const double mid = pitch / std::sin(tilt), length = 12;  // along the roller's axis from the apex
  const double small = mid - length / 2;
  const gp_Dir along(std::sin(tilt), 0, std::cos(tilt));
  const gp_Pnt small_end(small * std::sin(tilt), 0, apex + small * std::cos(tilt));
  TopoDS_Shape roller = BRepPrimAPI_MakeCone(gp_Ax2(small_end, along), small * std::tan(taper),
                                             (small + length) * std::tan(taper), length)
                            .Shape();
  if (options.domed_rollers) {
    // The sphere about the apex through the large end's rim, beyond the large end's plane.
    const double large = small + length, large_r = large * std::tan(taper);
    const gp_Pnt large_end(small_end.XYZ() + length * along.XYZ());
    const TopoDS_Shape beyond =
        BRepPrimAPI_MakeCylinder(gp_Ax2(large_end, along), 2 * large_r, 1).Shape();
    const TopoDS_Shape cap =
        BRepAlgoAPI_Common(
            BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, apex), std::hypot(large, large_r)).Shape(), beyond)
            .Shape();
    roller = BRepAlgoAPI_Fuse(roller, cap).Shape();
  }
  // The cage: a band about the rollers' pitch cone, r = (z - apex) tan(tilt), less a window
  // around each roller (its cone 0.3 mm wider, reaching 0.3 mm past its ends).
  auto on_pitch_cone = [&](double z) { return (z - apex) * std::tan(tilt); };
  TopoDS_Shape band = Revolved({{on_pitch_cone(-6.5) - 0.8, -6.5},
                                {on_pitch_cone(-6.5) + 0.8, -6.5},
                                {on_pitch_cone(6.5) + 0.8, 6.5},
                                {on_pitch_cone(6.5) - 0.8, 6.5}});
  const gp_Pnt window_start(small_end.XYZ() - 0.3 * along.XYZ());
  const TopoDS_Shape window =
      BRepPrimAPI_MakeCone(gp_Ax2(window_start, along), (small - 0.3) * std::tan(taper) + 0.3,
                           (small + length + 0.3) * std::tan(taper) + 0.3, length + 0.6)
          .Shape();
  for (int k = 0; k < rollers; ++k) {
    gp_Trsf turn;
    turn.SetRotation(gp::OZ(), 2 * M_PI * k / rollers);
    builder.Add(all, BRepBuilderAPI_Transform(roller, turn, true).Shape());
    if (options.cage) {
      band = BRepAlgoAPI_Cut(band, BRepBuilderAPI_Transform(window, turn, true)).Shape();
    }
  }
  if (options.cage) builder.Add(all, band);
  WriteStep(all, file);
}

void WriteDoubleRowBallBearingStep(const std::filesystem::path& file) {
  const double pitch = 38.5 / 2, ball = 7.144 / 2, groove = 0.52 * 7.144, row = 4.5;
  TopoDS_Shape inner = Tube(12.5, 17.5, -10, 10), outer = Tube(21, 26, -10, 10);
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  for (const double z : {-row, row}) {
    const TopoDS_Shape raceway =
        BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(0, 0, z), gp_Dir(0, 0, 1)), pitch, groove).Shape();
    inner = BRepAlgoAPI_Cut(inner, raceway).Shape();
    outer = BRepAlgoAPI_Cut(outer, raceway).Shape();
    for (int k = 0; k < 12; ++k) {
      const double a = 2 * M_PI * k / 12;
      builder.Add(all,
                  BRepPrimAPI_MakeSphere(gp_Pnt(pitch * std::cos(a), pitch * std::sin(a), z), ball)
                      .Shape());
    }
  }
  builder.Add(all, inner);
  builder.Add(all, outer);
  WriteStep(all, file);
}

void WriteSphericalRollerBearingStep(const std::filesystem::path& file, bool guide_ring) {
  const double pitch = 19.5, tilt = 13 * M_PI / 180, half = 3.5;
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  builder.Add(all, Tube(12.5, 15.3, -9, 9));
  builder.Add(
      all, BRepAlgoAPI_Cut(
               BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -9), gp_Dir(0, 0, 1)), 26, 18).Shape(),
               BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 0), 23.5).Shape())
               .Shape());
  // A barrel about z from z = -3.5 to 3.5: flat ends of radius 3, an arc through radius 3.25.
  BRepBuilderAPI_MakeWire outline;
  outline.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, -half), gp_Pnt(3, 0, -half)).Edge());
  outline.Add(
      BRepBuilderAPI_MakeEdge(
          GC_MakeArcOfCircle(gp_Pnt(3, 0, -half), gp_Pnt(3.25, 0, 0), gp_Pnt(3, 0, half)).Value())
          .Edge());
  outline.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(3, 0, half), gp_Pnt(0, 0, half)).Edge());
  outline.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, half), gp_Pnt(0, 0, -half)).Edge());
  const TopoDS_Shape barrel =
      BRepPrimAPI_MakeRevol(BRepBuilderAPI_MakeFace(outline.Wire()).Face(), gp::OZ()).Shape();
  for (const double side : {-1.0, 1.0}) {
    // Leaning towards the axis on the side away from the bearing's mid-plane.
    gp_Trsf lean, place;
    lean.SetRotation(gp::OY(), -side * tilt);
    place.SetTranslation(gp_Vec(pitch, 0, side * pitch * std::tan(tilt)));
    for (int k = 0; k < 14; ++k) {
      gp_Trsf turn;
      turn.SetRotation(gp::OZ(), 2 * M_PI * k / 14);
      builder.Add(all, BRepBuilderAPI_Transform(barrel, turn * place * lean, true).Shape());
    }
  }
  if (guide_ring) builder.Add(all, Tube(20.5, 22.5, -0.8, 0.8));
  WriteStep(all, file);
}

void WriteSelfAligningBallBearingStep(const std::filesystem::path& file) {
  const double pitch = 38.5 / 2, ball = 7.144 / 2, groove = 0.52 * 7.144, row = 3.6;
  const int balls = 13;
  TopoDS_Shape inner = Tube(12.5, 17, -7.5, 7.5);
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  for (const double z : {-row, row}) {
    inner = BRepAlgoAPI_Cut(inner, BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(0, 0, z), gp_Dir(0, 0, 1)),
                                                         pitch, groove))
                .Shape();
    const double stagger = z > 0 ? 0.5 : 0.0;
    for (int k = 0; k < balls; ++k) {
      const double a = 2 * M_PI * (k + stagger) / balls;
      builder.Add(all,
                  BRepPrimAPI_MakeSphere(gp_Pnt(pitch * std::cos(a), pitch * std::sin(a), z), ball)
                      .Shape());
    }
  }
  builder.Add(all, inner);
  const double raceway = std::hypot(pitch, row) + ball;
  builder.Add(
      all,
      BRepAlgoAPI_Cut(
          BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -7.5), gp_Dir(0, 0, 1)), 26, 15).Shape(),
          BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 0), raceway).Shape())
          .Shape());
  WriteStep(all, file);
}

void WriteThrustBallBearingStep(const std::filesystem::path& file, bool cage) {
  const double pitch = 33.5 / 2, ball = 6.35 / 2, groove = 0.53 * 6.35;
  const TopoDS_Shape raceway = BRepPrimAPI_MakeTorus(gp_Ax2(), pitch, groove).Shape();
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  builder.Add(all, BRepAlgoAPI_Cut(Tube(12.5, 21, -5.5, -1.5), raceway).Shape());
  builder.Add(all, BRepAlgoAPI_Cut(Tube(13.5, 21, 1.5, 5.5), raceway).Shape());
  TopoDS_Shape retainer = Tube(12.9, 20.5, -1, 1);
  for (int k = 0; k < 12; ++k) {
    const double a = 2 * M_PI * k / 12;
    const gp_Pnt centre(pitch * std::cos(a), pitch * std::sin(a), 0);
    builder.Add(all, BRepPrimAPI_MakeSphere(centre, ball).Shape());
    if (cage) retainer = BRepAlgoAPI_Cut(retainer, BRepPrimAPI_MakeSphere(centre, 3.3)).Shape();
  }
  if (cage) builder.Add(all, retainer);
  WriteStep(all, file);
}

void WriteNeedleBearingStep(const std::filesystem::path& file) {
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  builder.Add(all,
              BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -20), gp_Dir(0, 0, 1)), 6, 40).Shape());
  builder.Add(all, Tube(8, 9.5, -6, 6));
  AddRollers(builder, all, 18, 2, 7, -5, 5);
  WriteStep(all, file);
}

namespace {

// Keeps the messages sent at information gravity and above, and the error reports sent as
// traces.
class KeepingPrinter : public Message_Printer {
 public:
  explicit KeepingPrinter(std::vector<std::string>* kept) : kept_(kept) {
    SetTraceLevel(Message_Trace);
  }

 protected:
  void send(const TCollection_AsciiString& text, const Message_Gravity gravity) const override {
    const std::string line = text.ToCString();
    if (gravity >= Message_Info || line.find("ERR ") != std::string::npos) kept_->push_back(line);
  }

 private:
  std::vector<std::string>* kept_;
};

}  // namespace

StepModelRead ReadStepModel(const std::filesystem::path& file, bool mechanist_parser) {
  STEPControl_Reader reader;  // loads the STEP protocol
  const Handle(StepData_Protocol) protocol =
      Handle(StepData_Protocol)::DownCast(reader.WS()->Protocol());
  const Handle(StepSelect_WorkLibrary) library =
      mechanist_parser ? new Part21WorkLibrary : new StepSelect_WorkLibrary;
  StepModelRead read;
  const Handle(Message_Messenger) messenger = Message::DefaultMessenger();
  const Message_SequenceOfPrinters saved = messenger->Printers();
  messenger->ChangePrinters().Clear();
  messenger->AddPrinter(new KeepingPrinter(&read.messages));
  Handle(Interface_InterfaceModel) model;
  read.status = library->ReadFile(file.string().c_str(), model, protocol);
  messenger->ChangePrinters() = saved;
  const Handle(StepData_StepModel) step = Handle(StepData_StepModel)::DownCast(model);
  if (read.status != 0 || step.IsNull()) return read;
  read.entities = step->NbEntities();
  const auto add_checks = [&](int n, const Handle(Interface_Check) & check) {
    for (int k = 1; k <= check->NbFails(); ++k) {
      read.checks.push_back(std::to_string(n) + ": fail: " + check->CFail(k));
    }
    for (int k = 1; k <= check->NbWarnings(); ++k) {
      read.checks.push_back(std::to_string(n) + ": warning: " + check->CWarning(k));
    }
  };
  add_checks(0, step->GlobalCheck());
  for (int n = 1; n <= read.entities; ++n) {
    if (step->IsErrorEntity(n)) read.error_entities.push_back(n);
    if (step->IsUnknownEntity(n)) read.unknown_entities.push_back(n);
    add_checks(n, step->Check(n, /*syntactic=*/true));
    if (step->HasSemanticChecks()) add_checks(n, step->Check(n, /*syntactic=*/false));
  }
  // Open CASCADE's writer does not return on a model it recovered from syntax errors (an empty
  // data section, a number it split): such a model is not written back.
  if (step->GlobalCheck()->NbFails() > 0) return read;
  StepData_StepWriter writer(step);
  writer.SendModel(protocol);
  std::ostringstream text;
  writer.Print(text);
  read.written = text.str();
  return read;
}

}  // namespace mechanist::testing
