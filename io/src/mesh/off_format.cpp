// SPDX-License-Identifier: MIT
// ddfcam: Object File Format (ASCII OFF, with optional C/N/ST vertex extras) reader and writer.
#include <ddfcam/error.h>

#include "../common/text_parsing.h"
#include "mesh_formats.h"

namespace ddfcam::io::detail {
namespace {

/// Next line with content (comments and blank lines skipped); fails at the end of the file.
void nextTokens(LineCursor& cursor, std::vector<std::string_view>& tokens, const char* expected) {
  std::string_view line;
  while (cursor.next(line)) {
    splitTokens(stripComment(line, '#'), tokens);
    if (!tokens.empty()) return;
  }
  cursor.failFile(std::string("file ends before ") + expected);
}

/// Checks the keyword line ([ST][C][N]OFF) and returns the tokens that follow it on that line.
void readKeyword(LineCursor& cursor, std::vector<std::string_view>& tokens) {
  nextTokens(cursor, tokens, "the OFF keyword");
  const std::string_view key = tokens.front();
  if (key.size() < 3 || key.substr(key.size() - 3) != "OFF")
    cursor.fail("not an OFF file: expected the keyword OFF, found '" +
                std::string(key.substr(0, 40)) + "'");
  const std::string_view prefix = key.substr(0, key.size() - 3);
  if (prefix.find_first_not_of("STCN") != std::string_view::npos)
    cursor.fail("unsupported OFF variant '" + std::string(key) + "' (only 3D ASCII OFF)");
  if (tokens.size() > 1 && tokens[1] == "BINARY") cursor.fail("binary OFF is not supported");
  tokens.erase(tokens.begin());
}

void readFaces(LineCursor& cursor, std::int64_t faceCount, ddf::TriangleMesh& mesh) {
  std::vector<std::string_view> tokens;
  std::vector<int> corners;
  const auto vertexCount = static_cast<std::int64_t>(mesh.vertices.size());
  for (std::int64_t f = 0; f < faceCount; ++f) {
    nextTokens(cursor, tokens, ("face " + std::to_string(f)).c_str());
    const std::int64_t n = cursor.toInt(tokens[0]);
    if (n < 3) cursor.fail("face " + std::to_string(f) + " has " + std::to_string(n) + " corners");
    if (static_cast<std::int64_t>(tokens.size()) < n + 1)
      cursor.fail("face " + std::to_string(f) + " announces " + std::to_string(n) +
                  " corners but lists " + std::to_string(tokens.size() - 1));
    corners.clear();
    for (std::int64_t c = 1; c <= n; ++c) {
      const std::int64_t v = cursor.toInt(tokens[c]);
      if (v < 0 || v >= vertexCount)
        cursor.fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                    " of " + std::to_string(vertexCount));
      corners.push_back(static_cast<int>(v));
    }
    appendFan(mesh, corners.data(), static_cast<int>(corners.size()));
  }
}

}  // namespace

ddf::TriangleMesh readOff(std::string_view bytes, const std::string& name) {
  LineCursor cursor(bytes, name);
  if (looksBinary(bytes.substr(0, 4096))) cursor.failFile("not an OFF file (binary content)");
  std::vector<std::string_view> tokens;
  readKeyword(cursor, tokens);
  if (tokens.empty()) nextTokens(cursor, tokens, "the vertex and face counts");
  if (tokens.size() < 2) cursor.fail("expected vertex and face counts");
  const std::int64_t vertexCount = cursor.toInt(tokens[0]);
  const std::int64_t faceCount = cursor.toInt(tokens[1]);
  // Each vertex or face takes at least one line of two bytes, which bounds sane counts.
  const auto limit = static_cast<std::int64_t>(bytes.size());
  if (vertexCount < 0 || faceCount < 0 || vertexCount > limit || faceCount > limit)
    cursor.fail("implausible counts " + std::to_string(vertexCount) + " vertices, " +
                std::to_string(faceCount) + " faces");
  ddf::TriangleMesh mesh;
  mesh.vertices.reserve(static_cast<std::size_t>(vertexCount));
  for (std::int64_t v = 0; v < vertexCount; ++v) {
    nextTokens(cursor, tokens, ("vertex " + std::to_string(v)).c_str());
    if (tokens.size() < 3) cursor.fail("vertex " + std::to_string(v) + " needs 3 coordinates");
    mesh.vertices.emplace_back(cursor.toDouble(tokens[0]), cursor.toDouble(tokens[1]),
                               cursor.toDouble(tokens[2]));
  }
  readFaces(cursor, faceCount, mesh);
  return mesh;
}

std::string writeOff(const ddf::TriangleMesh& mesh) {
  std::string out = "OFF\n" + std::to_string(mesh.vertices.size()) + ' ' +
                    std::to_string(mesh.triangles.size()) + " 0\n";
  for (const auto& v : mesh.vertices) {
    for (int i = 0; i < 3; ++i) {
      if (i > 0) out += ' ';
      appendNumber(out, v[i]);
    }
    out += '\n';
  }
  for (const auto& t : mesh.triangles)
    out += "3 " + std::to_string(t[0]) + ' ' + std::to_string(t[1]) + ' ' + std::to_string(t[2]) +
           '\n';
  return out;
}

}  // namespace ddfcam::io::detail
