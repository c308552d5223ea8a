// SPDX-License-Identifier: MIT
// ddfcam: STL reader (ASCII and binary) and binary STL writer.
#include <ddfcam/error.h>
#include <ddfcam/io/mesh/mesh_io.h>

#include "../common/byte_codec.h"
#include "../common/text_parsing.h"
#include "mesh_formats.h"

#include <Eigen/Geometry>

namespace ddfcam::io::detail {
namespace {

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kFacetBytes = 50;

bool startsWithSolid(std::string_view bytes) {
  const std::size_t first = bytes.find_first_not_of(" \t\r\n");
  return first != std::string_view::npos && bytes.substr(first, 5) == "solid";
}

ddf::TriangleMesh readBinaryStl(std::string_view bytes, std::uint32_t count,
                                const std::string& name) {
  ddf::TriangleMesh soup;
  soup.vertices.reserve(3 * static_cast<std::size_t>(count));
  soup.triangles.reserve(count);
  const char* p = bytes.data() + kHeaderBytes + 4;
  for (std::uint32_t t = 0; t < count; ++t, p += kFacetBytes) {
    const int base = static_cast<int>(soup.vertices.size());
    for (int c = 0; c < 3; ++c) {
      const char* v = p + 12 + 12 * c;  // skip the stored normal
      soup.vertices.emplace_back(getF32(v), getF32(v + 4), getF32(v + 8));
      if (!soup.vertices.back().allFinite())
        throw IoError(name + ": binary STL triangle " + std::to_string(t) +
                      " has a non-finite coordinate");
    }
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  return soup;
}

void readAsciiFacetLine(LineCursor& cursor, const std::vector<std::string_view>& tokens,
                        ddf::TriangleMesh& soup, int& cornersInFacet, bool& inFacet) {
  const std::string_view key = tokens.front();
  if (key == "facet") {
    if (inFacet) cursor.fail("'facet' inside an unfinished facet");
    inFacet = true;
    cornersInFacet = 0;
  } else if (key == "vertex") {
    if (!inFacet) cursor.fail("'vertex' outside a facet");
    if (tokens.size() < 4) cursor.fail("'vertex' needs three coordinates");
    if (++cornersInFacet > 3) cursor.fail("facet with more than three vertices");
    soup.vertices.emplace_back(cursor.toDouble(tokens[1]), cursor.toDouble(tokens[2]),
                               cursor.toDouble(tokens[3]));
  } else if (key == "endfacet") {
    if (!inFacet || cornersInFacet != 3)
      cursor.fail("facet ends with " + std::to_string(cornersInFacet) + " vertices, expected 3");
    const int base = static_cast<int>(soup.vertices.size()) - 3;
    soup.triangles.push_back({base, base + 1, base + 2});
    inFacet = false;
  } else if (key != "outer" && key != "endloop" && key != "solid" && key != "endsolid") {
    cursor.fail("unexpected ASCII STL keyword '" + std::string(key.substr(0, 40)) + "'");
  }
}

ddf::TriangleMesh readAsciiStl(std::string_view bytes, const std::string& name) {
  LineCursor cursor(bytes, name);
  if (looksBinary(bytes))
    cursor.failFile(
        "starts like ASCII STL ('solid') but holds binary data and its size does "
        "not match a binary STL");
  ddf::TriangleMesh soup;
  std::vector<std::string_view> tokens;
  std::string_view line;
  int corners = 0;
  bool inFacet = false;
  while (cursor.next(line)) {
    splitTokens(line, tokens);
    if (!tokens.empty()) readAsciiFacetLine(cursor, tokens, soup, corners, inFacet);
  }
  if (inFacet) cursor.fail("file ends inside a facet");
  return soup;
}

}  // namespace

ddf::TriangleMesh readStl(std::string_view bytes, const std::string& name) {
  ddf::TriangleMesh soup;
  const bool sizeFitsBinary =
      bytes.size() >= kHeaderBytes + 4 &&
      bytes.size() == kHeaderBytes + 4 + kFacetBytes * getU32(bytes.data() + kHeaderBytes);
  if (sizeFitsBinary) {
    soup = readBinaryStl(bytes, getU32(bytes.data() + kHeaderBytes), name);
  } else if (startsWithSolid(bytes)) {
    soup = readAsciiStl(bytes, name);
  } else if (bytes.size() < kHeaderBytes + 4) {
    throw IoError(name + ": " + std::to_string(bytes.size()) +
                  " bytes is too short for a binary STL and it is not ASCII STL");
  } else {
    const std::uint32_t count = getU32(bytes.data() + kHeaderBytes);
    throw IoError(name + ": not a valid STL: binary header announces " + std::to_string(count) +
                  " triangles (" + std::to_string(kHeaderBytes + 4 + kFacetBytes * count) +
                  " bytes) but the file has " + std::to_string(bytes.size()) + " bytes");
  }
  return weldVertices(soup);
}

std::string writeStl(const ddf::TriangleMesh& mesh) {
  std::string out;
  out.reserve(kHeaderBytes + 4 + kFacetBytes * mesh.triangles.size());
  // A binary header must not start with "solid", or readers take the file for ASCII.
  std::string header = "binary STL written by ddfcam";
  header.resize(kHeaderBytes, ' ');
  out += header;
  putU32(out, static_cast<std::uint32_t>(mesh.triangles.size()));
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    const Eigen::Vector3d& b = mesh.vertices[t[1]];
    const Eigen::Vector3d& c = mesh.vertices[t[2]];
    Eigen::Vector3d normal = (b - a).cross(c - a);
    const double length = normal.norm();
    normal = length > 0.0 ? Eigen::Vector3d(normal / length) : Eigen::Vector3d::Zero();
    for (int i = 0; i < 3; ++i) putF32(out, static_cast<float>(normal[i]));
    for (const int v : t)
      for (int i = 0; i < 3; ++i) putF32(out, static_cast<float>(mesh.vertices[v][i]));
    putU16(out, 0);
  }
  return out;
}

}  // namespace ddfcam::io::detail
