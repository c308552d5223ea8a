// SPDX-License-Identifier: MIT
// ddfcam: format dispatch for mesh files, vertex welding.
#include <ddfcam/io/mesh/mesh_io.h>

#include <ddfcam/error.h>

#include "../common/file_access.h"
#include "mesh_formats.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <unordered_map>

namespace ddfcam::io {
namespace {

MeshFormat requireFormat(const std::filesystem::path& path) {
  const auto format = meshFormatOf(path);
  if (!format) {
    throw IoError(path.string() + ": unknown mesh file extension '" + path.extension().string() +
                  "' (expected .stl, .obj, .ply or .off)");
  }
  return *format;
}

struct PositionKey {
  std::uint64_t bits[3];
  bool operator==(const PositionKey& o) const {
    return bits[0] == o.bits[0] && bits[1] == o.bits[1] && bits[2] == o.bits[2];
  }
};

struct PositionHash {
  std::size_t operator()(const PositionKey& k) const {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the three words
    for (const std::uint64_t w : k.bits) h = (h ^ w) * 1099511628211ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

PositionKey keyOf(const Eigen::Vector3d& p) {
  // Adding +0.0 turns -0.0 into +0.0, so both signs of zero weld.
  return {{std::bit_cast<std::uint64_t>(p.x() + 0.0), std::bit_cast<std::uint64_t>(p.y() + 0.0),
           std::bit_cast<std::uint64_t>(p.z() + 0.0)}};
}

void validateIndices(const ddf::TriangleMesh& mesh) {
  const auto vertexCount = static_cast<int>(mesh.vertices.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const int v : mesh.triangles[t])
      if (v < 0 || v >= vertexCount)
        throw InvalidInput("triangle " + std::to_string(t) + " refers to vertex " +
                           std::to_string(v) + " of " + std::to_string(vertexCount));
}

}  // namespace

std::optional<MeshFormat> meshFormatOf(const std::filesystem::path& path) {
  const std::string ext = detail::lowerExtension(path);
  if (ext == ".stl") return MeshFormat::Stl;
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".ply") return MeshFormat::Ply;
  if (ext == ".off") return MeshFormat::Off;
  return std::nullopt;
}

ddf::TriangleMesh readMesh(const std::filesystem::path& path) {
  const MeshFormat format = requireFormat(path);
  const std::string bytes = detail::readFileBytes(path);
  const std::string name = path.string();
  if (bytes.empty()) throw IoError(name + ": file is empty");
  ddf::TriangleMesh mesh;
  switch (format) {
    case MeshFormat::Stl:
      mesh = detail::readStl(bytes, name);
      break;
    case MeshFormat::Obj:
      mesh = detail::readObj(bytes, name);
      break;
    case MeshFormat::Ply:
      mesh = detail::readPly(bytes, name);
      break;
    case MeshFormat::Off:
      mesh = detail::readOff(bytes, name);
      break;
  }
  if (mesh.triangles.empty()) throw IoError(name + ": file contains no triangles");
  return mesh;
}

void writeMesh(const ddf::TriangleMesh& mesh, const std::filesystem::path& path) {
  const MeshFormat format = requireFormat(path);
  validateIndices(mesh);
  std::string bytes;
  switch (format) {
    case MeshFormat::Stl:
      bytes = detail::writeStl(mesh);
      break;
    case MeshFormat::Obj:
      bytes = detail::writeObj(mesh);
      break;
    case MeshFormat::Ply:
      bytes = detail::writePly(mesh);
      break;
    case MeshFormat::Off:
      bytes = detail::writeOff(mesh);
      break;
  }
  detail::writeFileAtomically(path, bytes);
}

ddf::TriangleMesh weldVertices(const ddf::TriangleMesh& mesh) {
  validateIndices(mesh);
  ddf::TriangleMesh out;
  out.triangles.reserve(mesh.triangles.size());
  std::unordered_map<PositionKey, int, PositionHash> ids;
  ids.reserve(mesh.vertices.size());
  for (const auto& t : mesh.triangles) {
    std::array<int, 3> welded{};
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector3d& p = mesh.vertices[t[c]];
      const auto [it, inserted] = ids.try_emplace(keyOf(p), static_cast<int>(out.vertices.size()));
      if (inserted) out.vertices.push_back(p);
      welded[c] = it->second;
    }
    out.triangles.push_back(welded);
  }
  return out;
}

namespace detail {

void appendFan(ddf::TriangleMesh& mesh, const int* corners, int count) {
  for (int i = 1; i + 1 < count; ++i)
    mesh.triangles.push_back({corners[0], corners[i], corners[i + 1]});
}

}  // namespace detail
}  // namespace ddfcam::io
