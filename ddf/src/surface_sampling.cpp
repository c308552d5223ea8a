// SPDX-License-Identifier: MIT
// ddfcam: locating points on the represented surface and sampling per-raster-point values there.
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/ddf/v_projection.h>
#include <ddfcam/error.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace ddfcam::ddf {
namespace {

constexpr float kNoValue = std::numeric_limits<float>::quiet_NaN();

void checkValues(const DisplacementField& ddf, std::span<const float> values, const char* what) {
  if (values.size() != ddf.allHeights().size()) {
    throw InvalidInput(std::string(what) + ": " + std::to_string(values.size()) +
                       " values, expected " + std::to_string(ddf.allHeights().size()) +
                       " (faces x points per face)");
  }
}

// Negative coordinates set to 0, the rest rescaled to sum 1: the nearest point of the face in
// barycentric terms, which is all a "slightly outside" coordinate needs.
Vec3 clampBary(const Vec3& bary) {
  const Vec3 c = bary.cwiseMax(0.0);
  const double sum = c.sum();
  if (!(sum > 0.0)) return Vec3::Constant(1.0 / 3.0);
  return c / sum;
}

// Lattice coordinate snapped to an integer when it is one up to rounding, so that raster points
// land on a cell corner with weight exactly 1.
double snap(double x) {
  const double r = std::round(x);
  return std::abs(x - r) < 1e-9 ? r : x;
}

}  // namespace

double interpolateOnFace(const DisplacementField& ddf, std::span<const float> values, int face,
                         const Vec3& bary) {
  checkValues(ddf, values, "interpolateOnFace");
  if (face < 0 || face >= ddf.faceCount()) {
    throw InvalidInput("interpolateOnFace: face " + std::to_string(face) + " out of range [0, " +
                       std::to_string(ddf.faceCount()) + ")");
  }
  if (!bary.allFinite())
    throw InvalidInput("interpolateOnFace: non-finite barycentric coordinates");
  const Raster& raster = ddf.raster();
  const int n = raster.steps();
  const float* v = values.data() + static_cast<std::size_t>(face) * ddf.pointsPerFace();
  auto at = [&](int i, int k) { return static_cast<double>(v[raster.index(i, k)]); };

  const Vec3 mu = clampBary(bary);
  const double a = snap(mu[0] * n), c = snap(mu[2] * n);  // lattice i and k
  int a0 = std::min(static_cast<int>(std::floor(a)), n - 1);
  int c0 = std::min(static_cast<int>(std::floor(c)), n - 1);
  if (a0 + c0 > n - 1) --c0;  // on the edge j = 0 at a lattice corner: the cell below holds it
  a0 = std::max(a0, 0), c0 = std::max(c0, 0);
  const double fa = a - a0, fc = c - c0;

  // Terms with weight 0 are skipped so that a NaN ("no value") at a neighbour does not leak
  // into a point that lies exactly on other raster points.
  double sum = 0.0;
  auto add = [&](double w, int i, int k) {
    if (w != 0.0) sum += w * at(i, k);
  };
  if (fa + fc <= 1.0 || a0 + c0 == n - 1) {  // "up" cell (a0, c0), (a0 + 1, c0), (a0, c0 + 1)
    add(1.0 - fa - fc, a0, c0);
    add(fa, a0 + 1, c0);
    add(fc, a0, c0 + 1);
  } else {  // "down" cell (a0 + 1, c0 + 1), (a0, c0 + 1), (a0 + 1, c0)
    const double ga = 1.0 - fa, gc = 1.0 - fc;
    add(1.0 - ga - gc, a0 + 1, c0 + 1);
    add(ga, a0, c0 + 1);
    add(gc, a0 + 1, c0);
  }
  return sum;
}

std::optional<SurfaceLocation> locateOnFace(const DisplacementField& ddf, int face, const Vec3& p) {
  if (face < 0 || face >= ddf.faceCount()) {
    throw InvalidInput("locateOnFace: face " + std::to_string(face) + " out of range [0, " +
                       std::to_string(ddf.faceCount()) + ")");
  }
  const std::span<const float> heights = ddf.allHeights();
  std::optional<SurfaceLocation> best;
  double bestGap = std::numeric_limits<double>::infinity();
  for (const VProjection& root : vProject(ddf, face, p)) {
    if (!root.mu.allFinite() || !std::isfinite(root.h)) continue;
    const Vec3 bary = clampBary(root.mu);
    const double h = interpolateOnFace(ddf, heights, face, bary);
    // A NaN height ("no value") loses against any finite one but still locates the foot.
    const double gap = std::isnan(h) ? std::numeric_limits<double>::max() : std::abs(root.h - h);
    if (best && !(gap < bestGap)) continue;
    bestGap = gap;
    best = SurfaceLocation{face, bary, h, ddf.pointAt(face, bary, h)};
  }
  return best;
}

SurfaceSamples sampleRasterMesh(const DisplacementField& ddf, const RasterMesh& raster) {
  const RasterTopology& topo = ddf.topology();
  for (std::size_t v = 0; v < raster.vertexPoint.size(); ++v) {
    if (raster.vertexPoint[v] >= topo.pointCount()) {
      throw InvalidInput("sampleRasterMesh: vertex " + std::to_string(v) + " is raster point " +
                         std::to_string(raster.vertexPoint[v]) + " of " +
                         std::to_string(topo.pointCount()) + " (a raster mesh of another DDF?)");
    }
  }
  SurfaceSamples out;
  const std::size_t count = raster.vertexPoint.size();
  out.face.assign(count, -1);
  out.bary.assign(count, Vec3::Constant(1.0 / 3.0));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count), [&](const auto& range) {
    for (std::size_t v = range.begin(); v != range.end(); ++v) {
      PointCopy lowest{std::numeric_limits<int>::max(), 0};
      topo.forEachCopy(raster.vertexPoint[v], [&](PointCopy c) {
        if (c.face < lowest.face) lowest = c;
      });
      if (lowest.face == std::numeric_limits<int>::max()) continue;  // point without a face
      const RasterCoord rc = topo.coord(lowest);
      out.face[v] = lowest.face;
      out.bary[v] = ddf.rasterBary(rc.i, rc.k);
    }
  });
  return out;
}

SurfaceSamples sampleMeshVertices(const DisplacementField& ddf, const TriangleMesh& mesh,
                                  std::span<const int> triangleFace) {
  if (triangleFace.size() != mesh.triangles.size()) {
    throw InvalidInput("sampleMeshVertices: " + std::to_string(triangleFace.size()) +
                       " triangle faces for " + std::to_string(mesh.triangles.size()) +
                       " triangles");
  }
  SurfaceSamples out;
  const std::size_t count = mesh.vertices.size();
  out.face.assign(count, -1);
  out.bary.assign(count, Vec3::Constant(1.0 / 3.0));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int f = triangleFace[t];
    if (f < 0 || f >= ddf.faceCount()) {
      throw InvalidInput("sampleMeshVertices: triangle " + std::to_string(t) + " has face " +
                         std::to_string(f) + ", out of range [0, " +
                         std::to_string(ddf.faceCount()) + ")");
    }
    for (int v : mesh.triangles[t]) {
      if (v < 0 || static_cast<std::size_t>(v) >= count) {
        throw InvalidInput("sampleMeshVertices: triangle " + std::to_string(t) + " uses vertex " +
                           std::to_string(v) + " of " + std::to_string(count));
      }
      if (out.face[v] < 0) out.face[v] = f;
    }
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count), [&](const auto& range) {
    for (std::size_t v = range.begin(); v != range.end(); ++v) {
      if (out.face[v] < 0) continue;  // vertex used by no triangle
      if (const auto loc = locateOnFace(ddf, out.face[v], mesh.vertices[v]))
        out.bary[v] = loc->bary;
    }
  });
  return out;
}

std::vector<float> valuesAtSamples(const DisplacementField& ddf, std::span<const float> values,
                                   const SurfaceSamples& samples) {
  checkValues(ddf, values, "valuesAtSamples");
  if (samples.bary.size() != samples.face.size())
    throw InvalidInput("valuesAtSamples: samples have " + std::to_string(samples.face.size()) +
                       " faces but " + std::to_string(samples.bary.size()) + " coordinates");
  std::vector<float> out(samples.face.size(), kNoValue);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out.size()), [&](const auto& range) {
    for (std::size_t v = range.begin(); v != range.end(); ++v) {
      if (samples.face[v] < 0) continue;
      out[v] = static_cast<float>(interpolateOnFace(ddf, values, samples.face[v], samples.bary[v]));
    }
  });
  return out;
}

std::vector<float> valuesPerPoint(const DisplacementField& ddf, std::span<const float> values) {
  checkValues(ddf, values, "valuesPerPoint");
  const RasterTopology& topo = ddf.topology();
  const Raster& raster = ddf.raster();
  const int n = raster.steps();
  std::vector<float> out(topo.pointCount(), kNoValue);
  std::vector<std::uint8_t> taken(topo.pointCount(), 0);
  // Faces in ascending order: the first copy seen of a point is the lowest-index face's.
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const float* v = values.data() + static_cast<std::size_t>(f) * ddf.pointsPerFace();
    for (int k = 0; k <= n; ++k) {
      for (int i = 0; i + k <= n; ++i) {
        const PointId id = topo.id(f, i, k);
        if (taken[id]) continue;
        taken[id] = 1;
        out[id] = v[raster.index(i, k)];
      }
    }
  }
  return out;
}

}  // namespace ddfcam::ddf
