// Test fixtures built with Open CASCADE: the only test translation unit that includes it.
#include "io/occt/step_fixtures.h"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRep_Builder.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Ax2.hxx>
#include <stdexcept>

namespace mechanist::testing {

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
  Message::DefaultMessenger()->ChangePrinters().Clear();  // the writer's statistics
  STEPControl_Writer writer;
  if (writer.Transfer(all, STEPControl_AsIs) != IFSelect_RetDone ||
      writer.Write(file.string().c_str()) != IFSelect_RetDone) {
    throw std::runtime_error("cannot write " + file.string());
  }
}

}  // namespace mechanist::testing
