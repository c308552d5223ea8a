// SPDX-License-Identifier: MIT
// ddfcam: PLY reader (ASCII, binary little and big endian; any extra properties) and writer.
#include <ddfcam/error.h>

#include "../common/byte_codec.h"
#include "../common/text_parsing.h"
#include "mesh_formats.h"
#include "ply_header.h"

#include <cmath>
#include <optional>

namespace ddfcam::io::detail {
namespace {

/// Reads the scalars of the PLY body in order, ASCII or binary; errors name the instance.
class BodyReader {
 public:
  BodyReader(std::string_view bytes, const PlyHeader& header, const std::string& name)
      : bytes_(bytes),
        encoding_(header.encoding),
        pos_(header.bodyOffset),
        cursor_(bytes.substr(header.bodyOffset), name, header.bodyFirstLine) {}

  /// Starts instance @p index of @p element (for ASCII: reads its line).
  void startInstance(const std::string& element, std::int64_t index) {
    element_ = &element;
    index_ = index;
    if (encoding_ != PlyEncoding::Ascii) return;
    std::string_view line;
    do {
      if (!cursor_.next(line)) cursor_.failFile("PLY body ends before " + instance());
      splitTokens(line, tokens_);
    } while (tokens_.empty());
    token_ = 0;
  }
  void endInstance() {
    if (encoding_ == PlyEncoding::Ascii && token_ != tokens_.size())
      cursor_.fail(instance() + ": expected " + std::to_string(token_) + " values, found " +
                   std::to_string(tokens_.size()));
  }
  double next(const ScalarType& type) {
    if (encoding_ == PlyEncoding::Ascii) return nextAscii(type);
    if (pos_ + type.bytes > bytes_.size())
      cursor_.failFile("binary PLY body ends early in " + instance());
    const char* p = bytes_.data() + pos_;
    pos_ += type.bytes;
    const std::uint64_t raw = getUnsigned(p, type.bytes, encoding_ == PlyEncoding::BinaryBig);
    if (type.isFloat)
      return type.bytes == 4 ? std::bit_cast<float>(static_cast<std::uint32_t>(raw))
                             : std::bit_cast<double>(raw);
    if (!type.isSigned) return static_cast<double>(raw);
    const int shift = 64 - 8 * type.bytes;  // sign-extend
    return static_cast<double>(static_cast<std::int64_t>(raw << shift) >> shift);
  }
  [[noreturn]] void fail(const std::string& what) const {
    if (encoding_ == PlyEncoding::Ascii) cursor_.fail(instance() + ": " + what);
    cursor_.failFile(instance() + ": " + what);
  }

 private:
  std::string instance() const { return *element_ + " " + std::to_string(index_); }
  double nextAscii(const ScalarType& type) {
    if (token_ >= tokens_.size()) cursor_.fail(instance() + ": too few values");
    const std::string_view t = tokens_[token_++];
    return type.isFloat ? cursor_.toDouble(t) : static_cast<double>(cursor_.toInt(t));
  }

  std::string_view bytes_;
  PlyEncoding encoding_;
  std::size_t pos_;
  LineCursor cursor_;
  std::vector<std::string_view> tokens_;
  std::size_t token_ = 0;
  const std::string* element_ = nullptr;
  std::int64_t index_ = 0;
};

int findProperty(const PlyElement& element, std::initializer_list<std::string_view> names,
                 bool list) {
  for (std::size_t p = 0; p < element.properties.size(); ++p)
    for (const auto name : names)
      if (element.properties[p].name == name && element.properties[p].countType.has_value() == list)
        return static_cast<int>(p);
  return -1;
}

/// Values of one element instance: scalars[p] for scalar property p, lists[p] for list p.
struct Instance {
  std::vector<double> scalars;
  std::vector<std::vector<double>> lists;
};

/// Reads every instance of @p element, calling @p onInstance(index, instance) for each.
template <class Fn>
void readElement(BodyReader& reader, const PlyElement& element, Fn&& onInstance) {
  Instance values;
  values.scalars.assign(element.properties.size(), 0.0);
  values.lists.resize(element.properties.size());
  for (std::int64_t i = 0; i < element.count; ++i) {
    reader.startInstance(element.name, i);
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& property = element.properties[p];
      if (!property.countType) {
        values.scalars[p] = reader.next(property.type);
        continue;
      }
      const double count = reader.next(*property.countType);
      if (count < 0) reader.fail("negative list length");
      values.lists[p].clear();
      for (std::int64_t c = 0; c < static_cast<std::int64_t>(count); ++c)
        values.lists[p].push_back(reader.next(property.type));
    }
    reader.endInstance();
    onInstance(i, values);
  }
}

void readVertices(BodyReader& reader, const PlyElement& element, ddf::TriangleMesh& mesh) {
  const int x = findProperty(element, {"x"}, false);
  const int y = findProperty(element, {"y"}, false);
  const int z = findProperty(element, {"z"}, false);
  if (x < 0 || y < 0 || z < 0) reader.fail("vertex element lacks scalar properties x, y and z");
  mesh.vertices.reserve(static_cast<std::size_t>(element.count));
  readElement(reader, element, [&](std::int64_t, const Instance& values) {
    const Eigen::Vector3d p(values.scalars[x], values.scalars[y], values.scalars[z]);
    if (!p.allFinite()) reader.fail("non-finite coordinate");
    mesh.vertices.push_back(p);
  });
}

void readFaces(BodyReader& reader, const PlyElement& element,
               std::vector<std::vector<int>>& polygons) {
  const int list = findProperty(element, {"vertex_indices", "vertex_index"}, true);
  if (list < 0) reader.fail("face element lacks a vertex_indices list");
  polygons.reserve(static_cast<std::size_t>(element.count));
  readElement(reader, element, [&](std::int64_t, const Instance& values) {
    const auto& corners = values.lists[list];
    if (corners.size() < 3)
      reader.fail("face with " + std::to_string(corners.size()) + " corners, need at least 3");
    std::vector<int> polygon;
    for (const double c : corners) {
      if (c != std::floor(c) || c < 0 || c > 2147483647.0)
        reader.fail("invalid vertex index " + std::to_string(c));
      polygon.push_back(static_cast<int>(c));
    }
    polygons.push_back(std::move(polygon));
  });
}

void appendPolygons(const std::vector<std::vector<int>>& polygons, ddf::TriangleMesh& mesh,
                    const std::string& name) {
  const auto vertexCount = static_cast<int>(mesh.vertices.size());
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    for (const int v : polygons[f])
      if (v >= vertexCount)
        throw IoError(name + ": face " + std::to_string(f) + " refers to vertex " +
                      std::to_string(v) + " of " + std::to_string(vertexCount));
    appendFan(mesh, polygons[f].data(), static_cast<int>(polygons[f].size()));
  }
}

}  // namespace

ddf::TriangleMesh readPly(std::string_view bytes, const std::string& name) {
  const PlyHeader header = readPlyHeader(bytes, name);
  BodyReader reader(bytes, header, name);
  ddf::TriangleMesh mesh;
  std::vector<std::vector<int>> polygons;
  bool sawVertices = false;
  for (const PlyElement& element : header.elements) {
    if (element.name == "vertex" && !sawVertices) {
      readVertices(reader, element, mesh);
      sawVertices = true;
    } else if (element.name == "face" && polygons.empty()) {
      readFaces(reader, element, polygons);
    } else {
      readElement(reader, element, [](std::int64_t, const Instance&) {});
    }
  }
  if (!sawVertices) throw IoError(name + ": PLY file has no vertex element");
  appendPolygons(polygons, mesh, name);
  return mesh;
}

std::string writePly(const ddf::TriangleMesh& mesh) {
  std::string out = "ply\nformat binary_little_endian 1.0\ncomment written by ddfcam\n";
  out += "element vertex " + std::to_string(mesh.vertices.size()) + "\n";
  out += "property double x\nproperty double y\nproperty double z\n";
  out += "element face " + std::to_string(mesh.triangles.size()) + "\n";
  out += "property list uchar int vertex_indices\nend_header\n";
  out.reserve(out.size() + 24 * mesh.vertices.size() + 13 * mesh.triangles.size());
  for (const auto& v : mesh.vertices)
    for (int i = 0; i < 3; ++i) putF64(out, v[i]);
  for (const auto& t : mesh.triangles) {
    out += static_cast<char>(3);
    for (const int v : t) putU32(out, static_cast<std::uint32_t>(v));
  }
  return out;
}

}  // namespace ddfcam::io::detail
