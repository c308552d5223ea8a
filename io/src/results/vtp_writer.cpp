// SPDX-License-Identifier: MIT
// ddfcam: VTK XML PolyData (.vtp) writer, ASCII, without the VTK library.
#include <ddfcam/error.h>
#include <ddfcam/io/results/vtp_writer.h>

#include "../common/file_access.h"

#include <charconv>
#include <cmath>
#include <set>

namespace ddfcam::io {
namespace {

/// Appends the shortest text that reads back to exactly @p value (float or double).
template <class T>
void appendNumber(std::string& out, T value) {
  if (std::isnan(value)) {
    out += "nan";
    return;
  }
  if (std::isinf(value)) {
    out += value > 0 ? "inf" : "-inf";
    return;
  }
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void checkName(const std::string& name, std::set<std::string>& seen) {
  if (name.empty()) throw InvalidInput("a .vtp point data array has an empty name");
  if (name.find_first_of("<>&\"") != std::string::npos)
    throw InvalidInput("the .vtp array name '" + name + "' contains one of < > & \"");
  if (!seen.insert(name).second)
    throw InvalidInput("the .vtp array name '" + name + "' is used twice");
}

void checkInput(const ddf::TriangleMesh& mesh, const VtpPointData& data) {
  const std::size_t n = mesh.vertices.size();
  std::set<std::string> seen;
  const auto checkSize = [n](const std::string& name, std::size_t size) {
    if (size != n)
      throw InvalidInput("the .vtp array '" + name + "' has " + std::to_string(size) +
                         " values for " + std::to_string(n) + " vertices");
  };
  for (const VtpScalarArray& a : data.scalars) {
    checkName(a.name, seen);
    checkSize(a.name, a.values.size());
  }
  for (const VtpVectorArray& a : data.vectors) {
    checkName(a.name, seen);
    checkSize(a.name, a.values.size());
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const int v : mesh.triangles[t])
      if (v < 0 || static_cast<std::size_t>(v) >= n)
        throw InvalidInput("triangle " + std::to_string(t) + " of the .vtp mesh names vertex " +
                           std::to_string(v) + " of " + std::to_string(n));
}

void openArray(std::string& out, const char* type, const std::string& name, int components) {
  out += "        <DataArray type=\"";
  out += type;
  out += '"';
  if (!name.empty()) out += " Name=\"" + name + '"';
  if (components > 1) out += " NumberOfComponents=\"" + std::to_string(components) + '"';
  out += " format=\"ascii\">\n";
}

constexpr const char* kCloseArray = "        </DataArray>\n";

/// Writes @p count items, @p perLine to a line, each through @p item.
template <class Fn>
void appendLines(std::string& out, std::size_t count, std::size_t perLine, Fn&& item) {
  for (std::size_t begin = 0; begin < count; begin += perLine) {
    out += "         ";
    for (std::size_t at = begin; at < std::min(count, begin + perLine); ++at) {
      out += ' ';
      item(at);
    }
    out += '\n';
  }
}

void appendTriple(std::string& out, const Eigen::Vector3d& v, bool asFloat) {
  for (int c = 0; c < 3; ++c) {
    if (c > 0) out += ' ';
    if (asFloat)
      appendNumber(out, static_cast<float>(v[c]));
    else
      appendNumber(out, v[c]);
  }
}

void appendPointData(std::string& out, const VtpPointData& data, std::size_t n) {
  out += "      <PointData";
  if (!data.scalars.empty()) out += " Scalars=\"" + data.scalars.front().name + '"';
  if (!data.vectors.empty()) out += " Vectors=\"" + data.vectors.front().name + '"';
  out += ">\n";
  for (const VtpScalarArray& a : data.scalars) {
    openArray(out, "Float32", a.name, 1);
    appendLines(out, n, 9, [&](std::size_t i) { appendNumber(out, a.values[i]); });
    out += kCloseArray;
  }
  for (const VtpVectorArray& a : data.vectors) {
    openArray(out, "Float32", a.name, 3);
    appendLines(out, n, 2, [&](std::size_t i) { appendTriple(out, a.values[i], true); });
    out += kCloseArray;
  }
  out += "      </PointData>\n";
}

void appendGeometry(std::string& out, const ddf::TriangleMesh& mesh) {
  out += "      <Points>\n";
  openArray(out, "Float64", "Points", 3);
  appendLines(out, mesh.vertices.size(), 2,
              [&](std::size_t i) { appendTriple(out, mesh.vertices[i], false); });
  out += kCloseArray;
  out += "      </Points>\n      <Polys>\n";
  const std::size_t t = mesh.triangles.size();
  openArray(out, "Int64", "connectivity", 1);
  appendLines(out, 3 * t, 12,
              [&](std::size_t i) { out += std::to_string(mesh.triangles[i / 3][i % 3]); });
  out += kCloseArray;
  openArray(out, "Int64", "offsets", 1);
  appendLines(out, t, 12, [&](std::size_t i) { out += std::to_string(3 * (i + 1)); });
  out += kCloseArray;
  out += "      </Polys>\n";
}

}  // namespace

std::string formatVtp(const ddf::TriangleMesh& mesh, const VtpPointData& data) {
  checkInput(mesh, data);
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <PolyData>\n";
  out += "    <Piece NumberOfPoints=\"" + std::to_string(mesh.vertices.size()) +
         "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"" +
         std::to_string(mesh.triangles.size()) + "\">\n";
  appendPointData(out, data, mesh.vertices.size());
  appendGeometry(out, mesh);
  out += "    </Piece>\n  </PolyData>\n</VTKFile>\n";
  return out;
}

void writeVtp(const ddf::TriangleMesh& mesh, const VtpPointData& data,
              const std::filesystem::path& path) {
  const std::string text = formatVtp(mesh, data);
  detail::writeFileAtomically(path, text);
}

}  // namespace ddfcam::io
