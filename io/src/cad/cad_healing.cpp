// SPDX-License-Identifier: MIT
// ddfcam: healing a CAD shape read from a file (ShapeFix, sewing) and saying what changed.
#include "cad_model_impl.h"

#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Tool.hxx>
#include <Message_ListIteratorOfListOfMsg.hxx>
#include <Message_Msg.hxx>
#include <ShapeExtend.hxx>
#include <ShapeExtend_DataMapIteratorOfDataMapOfShapeListOfMsg.hxx>
#include <ShapeExtend_MsgRegistrator.hxx>
#include <ShapeFix_Shape.hxx>
#include <TCollection_AsciiString.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <map>
#include <utility>

namespace ddfcam::io::detail {
namespace {

int solids(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(shape, TopAbs_SOLID, map);
  return map.Extent();
}

// Pieces sewing may join: faces outside any shell, and open shells.
int sewablePieces(const TopoDS_Shape& shape) {
  int pieces = 0;
  for (TopExp_Explorer it(shape, TopAbs_FACE, TopAbs_SHELL); it.More(); it.Next()) ++pieces;
  TopTools_IndexedMapOfShape shells;
  TopExp::MapShapes(shape, TopAbs_SHELL, shells);
  for (int i = 1; i <= shells.Extent(); ++i)
    if (!BRep_Tool::IsClosed(shells(i))) ++pieces;
  return pieces;
}

// ShapeFix's own messages ("Wire was closed", ...) say what it changed, per sub-shape; its
// status flags are set for untouched shells too, so they would report fixes that never happened.
void fixShape(TopoDS_Shape& shape, double toleranceMm, std::vector<std::string>& lines) {
  ShapeExtend::Init();
  Handle(ShapeFix_Shape) fix = new ShapeFix_Shape(shape);
  Handle(ShapeExtend_MsgRegistrator) messages = new ShapeExtend_MsgRegistrator;
  fix->SetMsgRegistrator(messages);
  fix->SetMaxTolerance(toleranceMm);
  fix->Perform();
  std::map<std::string, int> counts;
  for (ShapeExtend_DataMapIteratorOfDataMapOfShapeListOfMsg it(messages->MapShape()); it.More();
       it.Next())
    for (Message_ListIteratorOfListOfMsg msg(it.Value()); msg.More(); msg.Next()) {
      Message_Msg text = msg.Value();
      ++counts[TCollection_AsciiString(text.Get(), '?').ToCString()];
    }
  for (const auto& [text, count] : counts)
    lines.push_back("ShapeFix: " + text + " (" + std::to_string(count) + "x)");
  shape = fix->Shape();
}

void sew(TopoDS_Shape& shape, double toleranceMm, std::vector<std::string>& lines) {
  const int pieces = sewablePieces(shape);
  BRepBuilderAPI_Sewing sewing(toleranceMm);
  sewing.Load(shape);
  sewing.Perform();
  const TopoDS_Shape sewn = sewing.SewedShape();
  if (sewn.IsNull()) return;
  TopTools_IndexedMapOfShape shells;
  TopExp::MapShapes(sewn, TopAbs_SHELL, shells);
  int closed = 0;
  for (int i = 1; i <= shells.Extent(); ++i) closed += BRep_Tool::IsClosed(shells(i)) ? 1 : 0;
  lines.push_back("sewed " + std::to_string(pieces) + " loose faces and open shells into " +
                  std::to_string(shells.Extent()) + " shell(s), " + std::to_string(closed) +
                  " closed, at " + std::to_string(toleranceMm) + " mm (" +
                  std::to_string(sewing.NbFreeEdges()) + " free edges remain)");
  shape = sewn;
}

}  // namespace

TopoDS_Shape healShape(const TopoDS_Shape& shape, double sewingToleranceMm,
                       std::vector<std::string>& lines) {
  const bool validBefore = BRepCheck_Analyzer(shape).IsValid();
  TopoDS_Shape out = shape;
  fixShape(out, sewingToleranceMm, lines);
  // A solid's faces are already joined; sewing is for surface models made of separate pieces.
  if (solids(out) == 0 && sewablePieces(out) > 1) sew(out, sewingToleranceMm, lines);
  const bool validAfter = BRepCheck_Analyzer(out).IsValid();
  if (!validBefore)
    lines.push_back(validAfter ? "the shape failed BRepCheck as read and passes after healing"
                               : "the shape fails BRepCheck even after healing");
  return out;
}

}  // namespace ddfcam::io::detail
