// SPDX-License-Identifier: MIT
// ddfcam: reading VTK XML PolyData (.vtp) and UnstructuredGrid (.vtu) surfaces without VTK.
#include <ddfcam/io/mesh/vtk_xml_mesh.h>

#include <ddfcam/error.h>

#include "../common/file_access.h"
#include "vtk_xml_arrays.h"
#include "vtk_xml_cells.h"
#include "vtk_xml_document.h"

#include <charconv>
#include <cmath>
#include <filesystem>

namespace ddfcam::io {
namespace {

using detail::CellTriangulator;
using detail::VtkArrayContext;
using detail::XmlDocument;

// A scalar field gathered over the pieces; kept only if every piece has it.
struct FieldAccumulator {
  planning::MeshField field;
  int pieces = 0;
};

class VtkXmlReader {
 public:
  VtkXmlReader(std::string_view text, const std::string& source) : doc_(), source_(source) {
    ctx_.text = text;
    ctx_.source = source;
  }

  VtkXmlMesh run() {
    doc_ = detail::parseXml(ctx_.text, source_);
    ctx_.doc = &doc_;
    const std::string type = readFileAttributes();
    const auto dataset = doc_.child(0, type);
    if (!dataset) fail("VTKFile has no <" + type + "> element");
    const std::vector<int> pieces = doc_.children(*dataset, "Piece");
    if (pieces.empty()) fail("<" + type + "> has no Piece");
    for (std::size_t p = 0; p < pieces.size(); ++p) readPiece(pieces[p], p, type == "PolyData");
    cells_.addBoundaryFaces();
    return finish(static_cast<int>(pieces.size()));
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw IoError(source_ + ": " + what); }

  std::string readFileAttributes() {
    const detail::XmlElement& root = doc_.elements[0];
    if (root.name != "VTKFile") fail("root element is <" + root.name + ">, not <VTKFile>");
    const std::string type = root.attribute("type").value_or("");
    if (type != "PolyData" && type != "UnstructuredGrid")
      fail("VTKFile type '" + type + "' is not PolyData or UnstructuredGrid");
    const std::string order = root.attribute("byte_order").value_or("LittleEndian");
    if (order != "LittleEndian" && order != "BigEndian") fail("unknown byte_order '" + order + "'");
    ctx_.bigEndian = order == "BigEndian";
    const std::string header = root.attribute("header_type").value_or("UInt32");
    if (header != "UInt32" && header != "UInt64") fail("unsupported header_type '" + header + "'");
    ctx_.headerBytes = header == "UInt64" ? 8 : 4;
    const std::string compressor = root.attribute("compressor").value_or("");
    if (!compressor.empty() && compressor != "vtkZLibDataCompressor")
      fail("unsupported compressor '" + compressor + "' (only vtkZLibDataCompressor)");
    ctx_.compressed = !compressor.empty();
    if (doc_.appendedElement >= 0) {
      const std::string encoding =
          doc_.elements[doc_.appendedElement].attribute("encoding").value_or("raw");
      if (encoding != "raw" && encoding != "base64")
        fail("AppendedData encoding '" + encoding + "' is not raw or base64");
      ctx_.appendedBase64 = encoding == "base64";
    }
    return type;
  }

  std::size_t count(int element, const char* key, const std::string& where) const {
    const auto text = doc_.elements[element].attribute(key);
    if (!text) return 0;
    std::size_t n = 0;
    const auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), n);
    if (ec != std::errc() || end != text->data() + text->size() || n > kMaxVtkXmlItems)
      fail(where + ": bad " + key + " '" + *text + "'");
    return n;
  }

  int namedArray(int parent, const std::string& name, const std::string& where) const {
    for (const int a : doc_.children(parent, "DataArray"))
      if (doc_.elements[a].attribute("Name") == name) return a;
    fail(where + " has no DataArray '" + name + "'");
  }

  void readPoints(int piece, std::size_t points, const std::string& where) {
    if (points == 0) return;
    const auto pts = doc_.child(piece, "Points");
    const auto array = pts ? doc_.child(*pts, "DataArray") : std::nullopt;
    if (!array) fail(where + " has no Points DataArray");
    if (detail::vtkArrayInfo(ctx_, *array).components != 3)
      fail(where + " Points: NumberOfComponents is not 3");
    const auto xyz = detail::decodeVtkArray(ctx_, *array, points, where + " Points");
    for (std::size_t i = 0; i < points; ++i) {
      const Eigen::Vector3d p(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
      if (!p.allFinite()) fail(where + " Points: point " + std::to_string(i) + " is not finite");
      vertices_.push_back(p);
    }
  }

  // Offsets (end of each cell) and connectivity of a cell block, checked and made global.
  std::pair<std::vector<double>, std::vector<int>> cellArrays(int block, std::size_t cells,
                                                              std::size_t points,
                                                              const std::string& where) {
    const auto offsets = detail::decodeVtkArray(ctx_, namedArray(block, "offsets", where), cells,
                                                where + " offsets");
    double previous = 0.0;
    for (const double o : offsets) {
      if (!(o >= previous) || o > 1e10 || o != std::floor(o)) fail(where + " offsets: bad value");
      previous = o;
    }
    const auto total = static_cast<std::size_t>(previous);
    const auto conn = detail::decodeVtkArray(ctx_, namedArray(block, "connectivity", where), total,
                                             where + " connectivity");
    std::vector<int> nodes(conn.size());
    for (std::size_t i = 0; i < conn.size(); ++i) {
      if (!(conn[i] >= 0 && conn[i] < static_cast<double>(points)) ||
          conn[i] != std::floor(conn[i]))
        fail(where + " connectivity: node " + std::to_string(i) + " out of range");
      nodes[i] = static_cast<int>(conn[i]) + vertexBase_;
    }
    return {offsets, nodes};
  }

  template <typename AddCell>
  void forEachCell(const std::vector<double>& offsets, const std::vector<int>& nodes,
                   AddCell&& add) {
    std::size_t begin = 0;
    for (std::size_t c = 0; c < offsets.size(); ++c) {
      const auto end = static_cast<std::size_t>(offsets[c]);
      add(c, std::span<const int>(nodes.data() + begin, end - begin));
      begin = end;
    }
  }

  void readPolyCells(int piece, std::size_t points, const std::string& where) {
    const std::size_t verts = count(piece, "NumberOfVerts", where);
    const std::size_t lines = count(piece, "NumberOfLines", where);
    const std::size_t strips = count(piece, "NumberOfStrips", where);
    const std::size_t polys = count(piece, "NumberOfPolys", where);
    cells_.vertexCells += static_cast<int>(verts);
    cells_.lineCells += static_cast<int>(lines);
    const std::int64_t base = cellBase_ + static_cast<std::int64_t>(verts + lines);
    if (polys > 0) {
      const auto block = doc_.child(piece, "Polys");
      if (!block) fail(where + " has no Polys");
      const auto [offsets, nodes] = cellArrays(*block, polys, points, where + " Polys");
      forEachCell(offsets, nodes, [&](std::size_t c, std::span<const int> n) {
        cells_.addPolygon(n, base + static_cast<std::int64_t>(c));
      });
    }
    if (strips > 0) {
      const auto block = doc_.child(piece, "Strips");
      if (!block) fail(where + " has no Strips");
      const auto [offsets, nodes] = cellArrays(*block, strips, points, where + " Strips");
      const std::int64_t stripBase = base + static_cast<std::int64_t>(polys);
      forEachCell(offsets, nodes, [&](std::size_t c, std::span<const int> n) {
        cells_.addStrip(n, stripBase + static_cast<std::int64_t>(c));
      });
    }
    pieceCells_ = verts + lines + strips + polys;
  }

  void readGridCells(int piece, std::size_t points, const std::string& where) {
    const std::size_t cells = count(piece, "NumberOfCells", where);
    pieceCells_ = cells;
    if (cells == 0) return;
    const auto block = doc_.child(piece, "Cells");
    if (!block) fail(where + " has no Cells");
    const auto [offsets, nodes] = cellArrays(*block, cells, points, where + " Cells");
    const auto types = detail::decodeVtkArray(ctx_, namedArray(*block, "types", where + " Cells"),
                                              cells, where + " Cells types");
    forEachCell(offsets, nodes, [&](std::size_t c, std::span<const int> n) {
      const double t = types[c];
      const int type = (t >= 0 && t < 256) ? static_cast<int>(t) : -1;
      if (!cells_.addCell(type, n, cellBase_ + static_cast<std::int64_t>(c)))
        fail(where + " cell " + std::to_string(c) + ": " + std::to_string(n.size()) +
             " nodes do not fit VTK cell type " + std::to_string(type));
    });
  }

  void readFields(int piece, const char* section, bool perCell, std::size_t tuples,
                  const std::string& where) {
    const auto data = doc_.child(piece, section);
    if (!data) return;
    for (const int array : doc_.children(*data, "DataArray")) {
      const auto info = detail::vtkArrayInfo(ctx_, array);
      if (info.components != 1 && info.components != 3) {
        if (pieceIndex_ == 0)
          warnings_.push_back(std::string(section) + " array '" + info.name + "' has " +
                              std::to_string(info.components) + " components; skipped");
        continue;
      }
      const auto values = detail::decodeVtkArray(ctx_, array, tuples,
                                                 where + " " + section + " '" + info.name + "'");
      const std::string name = info.components == 3 ? "|" + info.name + "|" : info.name;
      FieldAccumulator& acc = accumulator(name, perCell);
      if (acc.pieces != pieceIndex_) continue;  // missing in an earlier piece
      ++acc.pieces;
      for (std::size_t i = 0; i < tuples; ++i) {
        if (info.components == 1) {
          acc.field.values.push_back(static_cast<float>(values[i]));
        } else {
          const Eigen::Vector3d v(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
          acc.field.values.push_back(static_cast<float>(v.norm()));
        }
      }
    }
  }

  FieldAccumulator& accumulator(const std::string& name, bool perCell) {
    for (auto& acc : fields_)
      if (acc.field.name == name && acc.field.perCell == perCell) return acc;
    fields_.push_back({{name, "", perCell, {}}, 0});
    return fields_.back();
  }

  void readPiece(int piece, std::size_t index, bool polyData) {
    const std::string where = "Piece " + std::to_string(index);
    pieceIndex_ = static_cast<int>(index);
    const std::size_t points = count(piece, "NumberOfPoints", where);
    if (vertices_.size() + points > kMaxVtkXmlItems) fail(where + ": too many points");
    readPoints(piece, points, where);
    if (polyData)
      readPolyCells(piece, points, where);
    else
      readGridCells(piece, points, where);
    readFields(piece, "PointData", false, points, where);
    readFields(piece, "CellData", true, pieceCells_, where);
    vertexBase_ += static_cast<int>(points);
    cellBase_ += static_cast<std::int64_t>(pieceCells_);
  }

  VtkXmlMesh finish(int pieceCount) {
    if (cells_.triangles.empty()) fail("no surface or volume cells (only lines or vertices?)");
    if (cells_.triangles.size() > kMaxVtkXmlItems) fail("too many triangles");
    VtkXmlMesh out;
    out.mesh.vertices = std::move(vertices_);
    out.mesh.triangles = std::move(cells_.triangles);
    out.ignoredLineCells = cells_.lineCells;
    out.ignoredVertexCells = cells_.vertexCells;
    out.ignoredOtherCells = cells_.otherCells;
    out.warnings = std::move(warnings_);
    for (const auto& [type, n] : cells_.unsupportedTypes)
      out.warnings.push_back(std::to_string(n) + " cells of unsupported VTK type " +
                             std::to_string(type) + " skipped");
    for (auto& acc : fields_) {
      if (acc.pieces != pieceCount) {
        out.warnings.push_back("array '" + acc.field.name + "' is missing in some pieces; skipped");
        continue;
      }
      if (acc.field.perCell) {
        std::vector<float> perTriangle(cells_.cellOfTriangle.size());
        for (std::size_t t = 0; t < perTriangle.size(); ++t)
          perTriangle[t] = acc.field.values[cells_.cellOfTriangle[t]];
        acc.field.values = std::move(perTriangle);
      }
      out.fields.push_back(std::move(acc.field));
    }
    return out;
  }

  XmlDocument doc_;
  VtkArrayContext ctx_;
  std::string source_;
  std::vector<Eigen::Vector3d> vertices_;
  CellTriangulator cells_;
  std::vector<FieldAccumulator> fields_;
  std::vector<std::string> warnings_;
  int vertexBase_ = 0;
  std::int64_t cellBase_ = 0;
  std::size_t pieceCells_ = 0;
  int pieceIndex_ = 0;
};

}  // namespace

VtkXmlMesh decodeVtkXmlMesh(std::string_view text, const std::string& source) {
  return VtkXmlReader(text, source).run();
}

VtkXmlMesh readVtkXmlMesh(const std::filesystem::path& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxVtkXmlFileBytes)
    throw IoError(path.string() + ": file larger than " + std::to_string(kMaxVtkXmlFileBytes) +
                  " bytes");
  const std::string bytes = detail::readFileBytes(path);
  return decodeVtkXmlMesh(bytes, path.string());
}

}  // namespace ddfcam::io
