// SPDX-License-Identifier: MIT
// ddfcam: Wavefront OBJ reader (v and f statements) and writer.
#include <ddfcam/error.h>

#include "../common/text_parsing.h"
#include "mesh_formats.h"

#include <cctype>

namespace ddfcam::io::detail {
namespace {

bool isStatementName(std::string_view key) {
  for (const char c : key)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

/// Statements of the OBJ format that carry nothing a triangle soup needs.
bool isKnownStatement(std::string_view key) {
  static constexpr std::string_view kKnown[] = {
      "vt",       "vn",       "vp",     "l",          "p",         "g",      "o",
      "s",        "mg",       "usemtl", "mtllib",     "usemap",    "maplib", "cstype",
      "deg",      "bmat",     "step",   "curv",       "curv2",     "surf",   "parm",
      "trim",     "hole",     "scrv",   "sp",         "end",       "con",    "bevel",
      "c_interp", "d_interp", "lod",    "shadow_obj", "trace_obj", "ctech",  "stech"};
  for (const auto k : kKnown)
    if (key == k) return true;
  return false;
}

/// Vertex index of one face corner "v", "v/vt", "v//vn" or "v/vt/vn"; negative is relative.
int cornerIndex(const LineCursor& cursor, std::string_view token, int vertexCount) {
  const std::int64_t raw = cursor.toInt(token.substr(0, token.find('/')));
  const std::int64_t index = raw < 0 ? vertexCount + raw : raw - 1;
  if (raw == 0 || index < 0 || index >= vertexCount) {
    cursor.fail("face refers to vertex " + std::to_string(raw) + " but " +
                std::to_string(vertexCount) + " vertices are defined so far");
  }
  return static_cast<int>(index);
}

void readFace(const LineCursor& cursor, const std::vector<std::string_view>& tokens,
              ddf::TriangleMesh& mesh, std::vector<int>& corners) {
  if (tokens.size() < 4)
    cursor.fail("face with " + std::to_string(tokens.size() - 1) + " corners, need at least 3");
  corners.clear();
  const int vertexCount = static_cast<int>(mesh.vertices.size());
  for (std::size_t i = 1; i < tokens.size(); ++i)
    corners.push_back(cornerIndex(cursor, tokens[i], vertexCount));
  appendFan(mesh, corners.data(), static_cast<int>(corners.size()));
}

}  // namespace

ddf::TriangleMesh readObj(std::string_view bytes, const std::string& name) {
  LineCursor cursor(bytes, name);
  ddf::TriangleMesh mesh;
  std::vector<std::string_view> tokens;
  std::vector<int> corners;
  std::string_view line;
  std::string firstUnknown;  // a hint when a text file that is no OBJ yields nothing
  while (cursor.next(line)) {
    if (looksBinary(line)) cursor.fail("binary data in an OBJ (text) file");
    splitTokens(stripComment(line, '#'), tokens);
    if (tokens.empty()) continue;
    const std::string_view key = tokens.front();
    if (key == "v") {
      if (tokens.size() < 4) cursor.fail("vertex needs three coordinates");
      mesh.vertices.emplace_back(cursor.toDouble(tokens[1]), cursor.toDouble(tokens[2]),
                                 cursor.toDouble(tokens[3]));
    } else if (key == "f" || key == "fo") {
      readFace(cursor, tokens, mesh, corners);
    } else if (!isStatementName(key)) {
      cursor.fail("not an OBJ statement: '" + std::string(key.substr(0, 40)) + "'");
    } else if (firstUnknown.empty() && !isKnownStatement(key)) {
      firstUnknown.append("'").append(key.substr(0, 40)).append("' on line ");
      firstUnknown += std::to_string(cursor.lineNumber());
    }
  }
  if (mesh.triangles.empty() && !firstUnknown.empty())
    cursor.failFile("no faces; unknown OBJ statement " + firstUnknown);
  return mesh;
}

std::string writeObj(const ddf::TriangleMesh& mesh) {
  std::string out = "# written by ddfcam\n";
  out.reserve(out.size() + 60 * mesh.vertices.size() + 30 * mesh.triangles.size());
  for (const auto& v : mesh.vertices) {
    out += 'v';
    for (int i = 0; i < 3; ++i) {
      out += ' ';
      appendNumber(out, v[i]);
    }
    out += '\n';
  }
  for (const auto& t : mesh.triangles) {
    out += 'f';
    for (const int v : t) out += ' ' + std::to_string(v + 1);
    out += '\n';
  }
  return out;
}

}  // namespace ddfcam::io::detail
