// SPDX-License-Identifier: MIT
// ddfcam: reading STEP and IGES files through OpenCASCADE into a CadModel.
#include "cad_model_impl.h"

#include <ddfcam/error.h>

#include <BRepBuilderAPI_Transform.hxx>
#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Trsf.hxx>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <mutex>

namespace ddfcam::io {
namespace {

enum class CadFormat { Step, Iges };

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::optional<CadFormat> cadFormatOf(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".step" || ext == ".stp") return CadFormat::Step;
  if (ext == ".iges" || ext == ".igs") return CadFormat::Iges;
  return std::nullopt;
}

// The readers report through OpenCASCADE's default messenger, which prints to stdout; the core
// never prints, so its console printers go once, process-wide.
void silenceOcct() {
  static std::once_flag once;
  std::call_once(once, [] {
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  });
}

/// Millimetres per one unit named @p name (the names STEP and IGES files use).
std::optional<double> millimetresPerName(const std::string& name) {
  if (const auto unit = parseLengthUnit(name)) return millimetresPer(*unit);
  std::string key = name;
  std::transform(key.begin(), key.end(), key.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (key == "foot" || key == "feet" || key == "ft") return 304.8;
  if (key == "micrometre" || key == "micrometer" || key == "micron" || key == "um") return 1e-3;
  if (key == "kilometre" || key == "kilometer" || key == "km") return 1e6;
  if (key == "mil") return 0.0254;
  return std::nullopt;
}

// The first bytes tell a STEP or IGES file from anything else renamed to its suffix, with a
// clearer message than the readers' generic failure.
void checkSignature(const std::filesystem::path& path, CadFormat format) {
  std::ifstream in(path, std::ios::binary);
  std::string head(400, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (format == CadFormat::Step) {
    const auto start = head.find_first_not_of(" \t\r\n");
    if (start == std::string::npos || head.compare(start, 12, "ISO-10303-21") != 0)
      throw IoError(path.string() + " is not a STEP file (no ISO-10303-21 header)");
    // The reader accepts a file cut short and transfers what it parsed: a silently partial
    // part, so a missing trailer is an error.
    in.clear();
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    const std::streamoff tailSize = std::min<std::streamoff>(size, 256);
    std::string tail(static_cast<std::size_t>(tailSize), '\0');
    in.seekg(size - tailSize);
    in.read(tail.data(), tailSize);
    if (tail.find("END-ISO-10303-21") == std::string::npos)
      throw IoError(path.string() + " is damaged: truncated (no END-ISO-10303-21 trailer)");
    return;
  }
  // IGES: 80-column records, the first one of the start section ('S' in column 73).
  const auto eol = head.find_first_of("\r\n");
  const std::string first = head.substr(0, eol);
  if (first.size() < 73 || first[72] != 'S')
    throw IoError(path.string() + " is not an IGES file (no start section in column 73)");
}

struct ReadShape {
  TopoDS_Shape shape;
  std::string unitName;
  std::optional<double> fileMmPerUnit;
};

ReadShape readStep(const std::filesystem::path& path) {
  STEPControl_Reader reader;
  if (reader.ReadFile(path.string().c_str()) != IFSelect_RetDone)
    throw IoError(path.string() + " is damaged: the STEP reader failed to parse it");
  ReadShape out;
  TColStd_SequenceOfAsciiString lengths, angles, solidAngles;
  reader.FileUnits(lengths, angles, solidAngles);
  if (lengths.Length() > 0) out.unitName = lengths.First().ToCString();
  out.fileMmPerUnit =
      out.unitName.empty() ? std::optional<double>(1.0) : millimetresPerName(out.unitName);
  if (reader.NbRootsForTransfer() == 0 || reader.TransferRoots() == 0)
    throw IoError(path.string() + " is damaged: no STEP entity could be transferred to a shape");
  out.shape = reader.OneShape();
  return out;
}

// IGES global section unit flags (IGES 5.3, table 3).
std::string igesUnitName(int flag, const Handle(TCollection_HAsciiString) & name) {
  switch (flag) {
    case 1:
      return "inch";
    case 2:
      return "millimetre";
    case 4:
      return "foot";
    case 5:
      return "mile";
    case 6:
      return "metre";
    case 7:
      return "kilometre";
    case 8:
      return "mil";
    case 9:
      return "micron";
    case 10:
      return "centimetre";
    case 11:
      return "microinch";
    default:
      return name.IsNull() ? std::string() : std::string(name->ToCString());
  }
}

ReadShape readIges(const std::filesystem::path& path) {
  IGESControl_Reader reader;
  if (reader.ReadFile(path.string().c_str()) != IFSelect_RetDone)
    throw IoError(path.string() + " is damaged: the IGES reader failed to parse it");
  ReadShape out;
  const IGESData_GlobalSection& global = reader.IGESModel()->GlobalSection();
  out.unitName = igesUnitName(global.UnitFlag(), global.UnitName());
  out.fileMmPerUnit = millimetresPerName(out.unitName);
  if (global.UnitFlag() == 5) out.fileMmPerUnit = 1609344.0;
  if (global.UnitFlag() == 11) out.fileMmPerUnit = 2.54e-5;
  if (reader.NbRootsForTransfer() == 0 || reader.TransferRoots() == 0)
    throw IoError(path.string() + " is damaged: no IGES entity could be transferred to a shape");
  out.shape = reader.OneShape();
  return out;
}

TopoDS_Shape scaled(const TopoDS_Shape& shape, double factor) {
  gp_Trsf scale;
  scale.SetScale(gp_Pnt(0, 0, 0), factor);
  return BRepBuilderAPI_Transform(shape, scale, true).Shape();
}

int countOf(const TopoDS_Shape& shape, TopAbs_ShapeEnum type) {
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(shape, type, map);
  return map.Extent();
}

int looseFaces(const TopoDS_Shape& shape) {
  int count = 0;
  for (TopExp_Explorer it(shape, TopAbs_FACE, TopAbs_SHELL); it.More(); it.Next()) ++count;
  return count;
}

double largestTolerance(const TopoDS_Shape& shape) {
  double largest = 0.0;
  for (TopExp_Explorer it(shape, TopAbs_EDGE); it.More(); it.Next())
    largest = std::max(largest, BRep_Tool::Tolerance(TopoDS::Edge(it.Current())));
  for (TopExp_Explorer it(shape, TopAbs_VERTEX); it.More(); it.Next())
    largest = std::max(largest, BRep_Tool::Tolerance(TopoDS::Vertex(it.Current())));
  return largest;
}

void describeFaces(CadModel::Impl& model) {
  TopExp::MapShapes(model.shape, TopAbs_FACE, model.faceMap);
  for (int i = 1; i <= model.faceMap.Extent(); ++i) {
    CadFace face;
    face.surfaceType = detail::cadSurfaceTypeName(model.faceMap(i));
    face.name = "face " + std::to_string(i) + " (" + face.surfaceType + ")";
    GProp_GProps props;
    BRepGProp::SurfaceProperties(model.faceMap(i), props);
    face.areaMm2 = props.Mass();
    model.areaMm2 += face.areaMm2;
    model.faces.push_back(std::move(face));
  }
}

void applyUnit(CadModel::Impl& model, ReadShape& read, const CadReadParams& params,
               const std::filesystem::path& path) {
  model.fileUnitName = read.unitName;
  model.fileUnit = parseLengthUnit(read.unitName);
  model.unit = params.unit.value_or(model.fileUnit.value_or(ddfcam::LengthUnit::Millimetre));
  model.unitFromFile = !params.unit && model.fileUnit.has_value();
  if (!params.unit) return;
  // OpenCASCADE already converted the coordinates from the stated unit to mm.
  const double statedMm = read.fileMmPerUnit.value_or(1.0);
  if (!read.fileMmPerUnit && !read.unitName.empty())
    model.healing.push_back(path.filename().string() + ": unit '" + read.unitName +
                            "' unknown; the override assumes the file was read in mm");
  const double factor = millimetresPer(*params.unit) / statedMm;
  if (factor != 1.0) read.shape = scaled(read.shape, factor);
}

}  // namespace

bool isCadFile(const std::filesystem::path& path) {
  return cadFormatOf(path).has_value();
}

CadModel readCadModel(const std::filesystem::path& path, const CadReadParams& params) {
  const auto format = cadFormatOf(path);
  if (!format)
    throw IoError(path.string() + ": unsupported CAD file suffix '" + path.extension().string() +
                  "' (expected .step, .stp, .iges or .igs)");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw IoError(path.string() + " does not exist or is not a file");
  if (std::filesystem::file_size(path, ec) == 0) throw IoError(path.string() + " is empty");
  checkSignature(path, *format);
  silenceOcct();
  auto model = std::make_shared<CadModel::Impl>();
  reportProgress(params.progress, 0.0);
  try {
    ReadShape read = *format == CadFormat::Step ? readStep(path) : readIges(path);
    reportProgress(params.progress, 0.4);
    if (read.shape.IsNull() || countOf(read.shape, TopAbs_FACE) == 0)
      throw IoError(path.string() + " has no faces");
    applyUnit(*model, read, params, path);
    model->solids = countOf(read.shape, TopAbs_SOLID);
    model->looseFaces = looseFaces(read.shape);
    const auto readBounds = detail::exactBounds(read.shape);
    const double diagonal = (readBounds[1] - readBounds[0]).norm();
    const double sewing = params.sewingToleranceMm > 0 ? params.sewingToleranceMm : 1e-4 * diagonal;
    reportProgress(params.progress, 0.55);
    model->shape = params.heal ? detail::healShape(read.shape, sewing, model->healing) : read.shape;
    reportProgress(params.progress, 0.8);
    model->shells = countOf(model->shape, TopAbs_SHELL);
    model->boundsMm = detail::exactBounds(model->shape);
    model->toleranceMm = largestTolerance(model->shape);
    describeFaces(*model);
    reportProgress(params.progress, 1.0);
  } catch (const Standard_Failure& failure) {
    throw IoError(path.string() + " is damaged: OpenCASCADE failed (" + failure.GetMessageString() +
                  ")");
  }
  if (model->faces.empty()) throw IoError(path.string() + " has no faces");
  return CadModel(std::move(model));
}

}  // namespace ddfcam::io
