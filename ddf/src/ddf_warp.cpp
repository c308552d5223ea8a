// SPDX-License-Identifier: MIT
// ddfcam: warps of a DDF by its vectors and its support, and meshes of morph positions (ch. 9).
#include <ddfcam/ddf/ddf_warp.h>
#include <ddfcam/error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include "canonical_points.h"

namespace ddfcam::ddf {
namespace {

constexpr int kNoVertex = -1;

// Orthonormal bend frame (x, y, z = x cross y) from the user's directions.
std::array<Vec3, 3> bendFrame(const CylinderWarpParams& params) {
  const double xn = params.bendDirection.norm();
  if (!(xn > 0.0) || !std::isfinite(xn))
    throw InvalidInput("mapSupportOntoCylinder: the bend direction is zero or not finite");
  const Vec3 x = params.bendDirection / xn;
  const Vec3 yRaw = params.axisDirection - params.axisDirection.dot(x) * x;
  const double yn = yRaw.norm();
  if (!(yn > 1e-9 * std::max(1.0, params.axisDirection.norm())) || !std::isfinite(yn))
    throw InvalidInput(
        "mapSupportOntoCylinder: the axis direction is zero or parallel to the bend direction");
  const Vec3 y = yRaw / yn;
  return {x, y, x.cross(y)};
}

void checkCylinderFit(const DisplacementField& ddf, const std::array<Vec3, 3>& frame,
                      const CylinderWarpParams& params) {
  const double r = params.radiusMm;
  double xMin = std::numeric_limits<double>::infinity();
  double xMax = -xMin;
  for (int v = 0; v < ddf.vertexCount(); ++v) {
    const Vec3 d = ddf.position(v) - params.originMm;
    const double x = d.dot(frame[0]);
    xMin = std::min(xMin, x);
    xMax = std::max(xMax, x);
    if (!((r + d.dot(frame[2])) / r > 0.0)) {
      throw InvalidInput("mapSupportOntoCylinder: support vertex " + std::to_string(v) +
                         " lies beyond the cylinder axis (R + z <= 0)");
    }
  }
  if (xMax - xMin > 2.0 * std::numbers::pi * std::abs(r)) {
    throw InvalidInput("mapSupportOntoCylinder: the support spans " + std::to_string(xMax - xMin) +
                       " mm along the bend, more than the cylinder's circumference");
  }
}

// Index (allHeights() layout) of the copy in the lowest-index face of every raster point, as
// extractRasterMesh positions shared points; kNoCopy for points without a face.
constexpr std::size_t kNoCopy = std::numeric_limits<std::size_t>::max();
std::vector<std::size_t> ownerCopies(const DisplacementField& layout) {
  const RasterTopology& topo = layout.topology();
  const Raster& raster = layout.raster();
  const int n = raster.steps();
  const detail::PointOwners owners(layout);
  std::vector<std::size_t> ownerCopy(topo.pointCount(), kNoCopy);
  for (int f = 0; f < layout.faceCount(); ++f) {
    for (int k = 0; k <= n; ++k) {
      for (int i = 0; i + k <= n; ++i) {
        const PointId id = topo.id(f, i, k);
        if (owners.owner(id, f) == f)
          ownerCopy[id] = f * layout.pointsPerFace() + raster.index(i, k);
      }
    }
  }
  return ownerCopy;
}

}  // namespace

void scaleVectors(DisplacementField& ddf, double factor) {
  if (factor == 0.0 || !std::isfinite(factor))
    throw InvalidInput("scaleVectors: factor " + std::to_string(factor) +
                       " (must be finite and nonzero)");
  std::vector<Vec3> vectors = ddf.vectors();
  for (Vec3& v : vectors) v *= factor;
  ddf.setVectors(std::move(vectors));
}

void mapSupportOntoCylinder(DisplacementField& ddf, const CylinderWarpParams& params) {
  const double r = params.radiusMm;
  if (r == 0.0 || !std::isfinite(r))
    throw InvalidInput("mapSupportOntoCylinder: radius " + std::to_string(r) +
                       " mm (must be finite and nonzero)");
  if (!params.originMm.allFinite())
    throw InvalidInput("mapSupportOntoCylinder: the origin is not finite");
  const auto frame = bendFrame(params);
  checkCylinderFit(ddf, frame, params);

  SupportMesh support = ddf.support();
  std::vector<Vec3> vectors(ddf.vertexCount());
  for (int v = 0; v < ddf.vertexCount(); ++v) {
    const Vec3 d = ddf.position(v) - params.originMm;
    const double x = d.dot(frame[0]), y = d.dot(frame[1]), z = d.dot(frame[2]);
    const double theta = x / r, c = std::cos(theta), s = std::sin(theta);
    const Vec3 p =
        params.originMm + (r + z) * s * frame[0] + y * frame[1] + ((r + z) * c - r) * frame[2];
    support.set_point(SupportMesh::VertexHandle(v), toOpenMesh(p));
    // The local frame turns by theta about the axis: x -> (c, -s), z -> (s, c) in (x, z).
    const Vec3& w = ddf.vector(v);
    const double wx = w.dot(frame[0]), wy = w.dot(frame[1]), wz = w.dot(frame[2]);
    vectors[v] = (wx * c + wz * s) * frame[0] + wy * frame[1] + (-wx * s + wz * c) * frame[2];
  }
  std::vector<float> heights = std::move(ddf.allHeights());
  DisplacementField warped(std::move(support), std::move(vectors), ddf.resolution());
  warped.allHeights() = std::move(heights);
  ddf = std::move(warped);
}

RasterMesh morphRasterMesh(const DisplacementField& layout, std::span<const Vec3> positions) {
  if (positions.size() != layout.allHeights().size()) {
    throw InvalidInput("morphMesh: " + std::to_string(positions.size()) + " positions for " +
                       std::to_string(layout.allHeights().size()) + " raster point copies");
  }
  const RasterTopology& topo = layout.topology();
  const Raster& raster = layout.raster();
  const int n = raster.steps();
  const std::vector<std::size_t> ownerCopy = ownerCopies(layout);
  RasterMesh out;
  std::vector<int> vertexOf(topo.pointCount(), kNoVertex);
  for (std::size_t id = 0; id < ownerCopy.size(); ++id) {
    if (ownerCopy[id] == kNoCopy) continue;
    const Vec3& p = positions[ownerCopy[id]];
    if (!p.allFinite()) continue;
    vertexOf[id] = static_cast<int>(out.mesh.vertices.size());
    out.mesh.vertices.push_back(p);
    out.vertexPoint.push_back(static_cast<PointId>(id));
  }

  std::vector<int> local(raster.pointCount());
  auto emit = [&](int a, int b, int c) {
    if (a != kNoVertex && b != kNoVertex && c != kNoVertex) out.mesh.triangles.push_back({a, b, c});
  };
  out.mesh.triangles.reserve(static_cast<std::size_t>(n) * n * layout.faceCount());
  for (int f = 0; f < layout.faceCount(); ++f) {
    std::size_t l = 0;
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) local[l++] = vertexOf[topo.id(f, i, k)];
    auto at = [&](int i, int k) { return local[raster.index(i, k)]; };
    // Same cells and corner order as extractRasterMesh: upward cells, then downward cells.
    for (int c = 0; c < n; ++c)
      for (int a = 0; a + c < n; ++a) emit(at(a + 1, c), at(a, c), at(a, c + 1));
    for (int c = 0; c + 1 < n; ++c)
      for (int a = 0; a + c + 1 < n; ++a) emit(at(a, c + 1), at(a + 1, c + 1), at(a + 1, c));
  }
  return out;
}

TriangleMesh morphMesh(const DisplacementField& layout, std::span<const Vec3> positions) {
  return morphRasterMesh(layout, positions).mesh;
}

std::vector<Vec3> heightPositions(const DisplacementField& layout, std::span<const float> heights) {
  if (heights.size() != layout.allHeights().size()) {
    throw InvalidInput("heightPositions: " + std::to_string(heights.size()) + " heights for " +
                       std::to_string(layout.allHeights().size()) + " raster point copies");
  }
  const Raster& raster = layout.raster();
  const int n = raster.steps();
  std::vector<Vec3> out(heights.size());
  for (int f = 0; f < layout.faceCount(); ++f) {
    const std::size_t base = static_cast<std::size_t>(f) * layout.pointsPerFace();
    for (int k = 0; k <= n; ++k) {
      for (int i = 0; i + k <= n; ++i) {
        const std::size_t c = base + raster.index(i, k);
        out[c] = layout.pointAt(f, layout.rasterBary(i, k), heights[c]);
      }
    }
  }
  return out;
}

}  // namespace ddfcam::ddf
