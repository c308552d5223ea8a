// SPDX-License-Identifier: MIT
// ddfcam: the curvature of a converted part from vertex fits on the mesh it came from.
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/ddf/raster_normal.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/design_curvature.h>
#include <ddfcam/planning/analysis/vertex_curvature.h>
#include <ddfcam/planning/surface/mesh_distance.h>

#include "curvature_tensor.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;
using Mat3 = Eigen::Matrix3d;

/// The design triangle nearest to a raster point and the barycentric coordinates of the foot
/// point in it (corner order of the triangle's face vertices); triangle -1 when none is near.
struct Foot {
  int triangle = -1;
  Vec3 bary = Vec3::Zero();
};

// The design mesh welded as a support of its own, heights 0, unit pseudo-normals: the shape
// computeVertexCurvature() fits. The fits live at the corners, but a strip of long triangles
// needs the fits' face samples (up to 4 steps per edge), so m = 5.
ddf::DisplacementField designField(const ddf::TriangleMesh& design) {
  ddf::ConversionParams c;
  c.resolution = 5;
  c.chooseLengths = false;
  return ddf::convertMeshToDdf(design, c).ddf;
}

double meanRasterSpacing(const ddf::DisplacementField& part) {
  double sum = 0.0;
  for (int f = 0; f < part.faceCount(); ++f) {
    const auto& v = part.faceVertices(f);
    for (int c = 0; c < 3; ++c) sum += (part.position(v[c]) - part.position(v[(c + 1) % 3])).norm();
  }
  return sum / (3.0 * part.faceCount() * (part.resolution() - 1));
}

Vec3 barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e0 = b - a, e1 = c - a, d = p - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1);
  const double d20 = d.dot(e0), d21 = d.dot(e1), det = d00 * d11 - d01 * d01;
  if (!(std::abs(det) > 0.0)) return Vec3(1.0, 0.0, 0.0);
  const double v = (d11 * d20 - d01 * d21) / det, w = (d00 * d21 - d01 * d20) / det;
  // The foot lies in the triangle; clamping only removes rounding below 0.
  const Vec3 clamped = Vec3(1.0 - v - w, v, w).cwiseMax(0.0);
  return clamped / clamped.sum();
}

// Feet of all raster points of @p part (allHeights layout), in blocks of faces so that
// progress and cancellation are polled between them.
std::vector<Foot> rasterFeet(const ddf::DisplacementField& part, const ddf::TriangleMesh& design,
                             double maxDistanceMm, const CurvatureParams& params) {
  const MeshDistance distance(design);
  std::vector<Foot> feet(part.allHeights().size());
  const ddf::Raster& raster = part.raster();
  auto body = [&](const tbb::blocked_range<int>& r) {
    for (int f = r.begin(); f < r.end(); ++f)
      for (int k = 0; k <= raster.steps(); ++k)
        for (int i = 0; i < raster.rowLength(k); ++i) {
          const auto hit = distance.closestPoint(part.surfacePoint(f, i, k), maxDistanceMm);
          if (!hit) continue;
          const auto& t = design.triangles[static_cast<std::size_t>(hit->triangle)];
          Foot& foot = feet[f * part.pointsPerFace() + raster.index(i, k)];
          foot.triangle = hit->triangle;
          foot.bary = barycentric(hit->point, design.vertices[t[0]], design.vertices[t[1]],
                                  design.vertices[t[2]]);
        }
  };
  const int block = 512;
  for (int first = 0; first < part.faceCount(); first += block) {
    reportProgress(params.progress, 0.5 * first / part.faceCount());
    const tbb::blocked_range<int> range(first, std::min(part.faceCount(), first + block), 16);
    params.parallel ? tbb::parallel_for(range, body) : body(range);
  }
  return feet;
}

// Per design face the label most raster points whose foot lies on it carry; faces without a
// foot take the label of the nearest labelled face across edges (breadth first).
std::vector<int> designLabels(const ddf::DisplacementField& part, const std::vector<Foot>& feet,
                              const ddf::DisplacementField& design,
                              const std::vector<int>& partLabels) {
  std::vector<std::pair<int, int>> votes;  // (design face, label)
  for (std::size_t at = 0; at < feet.size(); ++at)
    if (feet[at].triangle >= 0)
      votes.emplace_back(feet[at].triangle,
                         partLabels[at / static_cast<std::size_t>(part.pointsPerFace())]);
  std::sort(votes.begin(), votes.end());
  std::vector<int> label(static_cast<std::size_t>(design.faceCount()), -1);
  std::vector<bool> known(label.size(), false);
  std::deque<int> queue;
  for (std::size_t a = 0; a < votes.size();) {
    std::size_t b = a, best = a, bestCount = 0;
    while (b < votes.size() && votes[b].first == votes[a].first) {
      std::size_t e = b;
      while (e < votes.size() && votes[e] == votes[b]) ++e;
      if (e - b > bestCount) best = b, bestCount = e - b;
      b = e;
    }
    label[votes[a].first] = votes[best].second, known[votes[a].first] = true;
    queue.push_back(votes[a].first);
    a = b;
  }
  for (; !queue.empty(); queue.pop_front())
    for (const auto g : design.support().ff_range(design.support().face_handle(queue.front())))
      if (!known[g.idx()]) {
        label[g.idx()] = label[queue.front()], known[g.idx()] = true;
        queue.push_back(g.idx());
      }
  return label;
}

}  // namespace

namespace {

/// The fitted design surface: its field, and per face the allHeights index of each corner.
struct DesignFit {
  ddf::DisplacementField field;
  ddf::TriangleMesh triangles;  // its support, face order kept
  CurvatureField curvature;
  std::array<int, 3> cornerIndex{};  // raster index of corner c
};

DesignFit fitDesign(const ddf::TriangleMesh& design) {
  DesignFit fit;
  fit.field = designField(design);
  fit.triangles = ddf::extractSupportMesh(fit.field);
  const ddf::Raster& raster = fit.field.raster();
  for (int k = 0; k <= raster.steps(); ++k)
    for (int i = 0; i < raster.rowLength(k); ++i) {
      const Vec3 b = fit.field.rasterBary(i, k);
      int c = 0;
      if (b.maxCoeff(&c) == 1.0) fit.cornerIndex[static_cast<std::size_t>(c)] = raster.index(i, k);
    }
  return fit;
}

// Blended design tensors at the raster points of part face @p f; false if a point has no foot.
bool transferFace(const ddf::DisplacementField& part, int f, const DesignFit& fit,
                  const std::vector<Foot>& feet, const CurvatureParams& params,
                  CurvatureField& out) {
  const ddf::Raster& raster = part.raster();
  const std::size_t base = static_cast<std::size_t>(f) * part.pointsPerFace();
  for (int k = 0; k <= raster.steps(); ++k)
    for (int i = 0; i < raster.rowLength(k); ++i) {
      const std::size_t at = base + raster.index(i, k);
      const Foot& foot = feet[at];
      if (foot.triangle < 0) return false;
      const std::size_t corners =
          static_cast<std::size_t>(foot.triangle) * fit.field.pointsPerFace();
      Mat3 s = Mat3::Zero();
      for (int c = 0; c < 3; ++c)
        s += foot.bary[c] * detail::curvatureTensor(fit.curvature, corners + fit.cornerIndex[c]);
      const Vec3 n = ddf::rasterNormal(part, f, i, k);
      const auto& t = fit.triangles.triangles[static_cast<std::size_t>(foot.triangle)];
      const auto& v = fit.triangles.vertices;
      // The fits' sign follows the design's orientation; the part's follows its vectors.
      if ((v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).dot(n) < 0.0) s = -s;
      detail::storeCurvatureTensor(s, n, params.umbilicTolerance, params.flatCurvaturePerMm, out,
                                   at);
    }
  return true;
}

// Faces @p off (not on the design) from the part's own raster differences, when it has them.
void fillOffDesignFaces(const ddf::DisplacementField& part, const std::vector<int>& off,
                        const CurvatureParams& params, CurvatureField& out) {
  if (off.empty()) return;
  const std::size_t per = part.pointsPerFace();
  if (part.resolution() < 4) {
    for (const int f : off) std::fill_n(out.umbilic.begin() + f * per, per, std::uint8_t{1});
    return;
  }
  CurvatureParams own = params;
  own.method = CurvatureMethod::RasterDifferences;
  own.progress = nullptr;
  const CurvatureField differences = computeCurvature(part, own);
  for (const int f : off)
    for (std::size_t at = f * per; at < (f + 1) * per; ++at) {
      out.kMax[at] = differences.kMax[at], out.kMin[at] = differences.kMin[at];
      out.mean[at] = differences.mean[at], out.gaussian[at] = differences.gaussian[at];
      out.dirMax[at] = differences.dirMax[at], out.dirMin[at] = differences.dirMin[at];
      out.umbilic[at] = differences.umbilic[at];
    }
}

}  // namespace

CurvatureField computeDesignCurvature(const ddf::DisplacementField& part,
                                      const ddf::TriangleMesh& design,
                                      const CurvatureParams& params) {
  if (part.faceCount() == 0) throw InvalidInput("computeDesignCurvature: the part has no faces");
  if (design.triangles.empty())
    throw InvalidInput("computeDesignCurvature: the design mesh has no triangles");
  if (!params.faceLabels.empty() &&
      params.faceLabels.size() != static_cast<std::size_t>(part.faceCount()))
    throw InvalidInput("computeDesignCurvature: " + std::to_string(params.faceLabels.size()) +
                       " face labels for " + std::to_string(part.faceCount()) + " faces");
  DesignFit fit = fitDesign(design);
  const double reach =
      params.designDistanceMm > 0.0 ? params.designDistanceMm : 0.25 * meanRasterSpacing(part);
  const std::vector<Foot> feet = rasterFeet(part, fit.triangles, reach, params);
  VertexCurvatureParams vertex;
  vertex.umbilicTolerance = params.umbilicTolerance;
  vertex.flatCurvaturePerMm = params.flatCurvaturePerMm;
  vertex.parallel = params.parallel;
  if (!params.faceLabels.empty())
    vertex.faceLabels = designLabels(part, feet, fit.field, params.faceLabels);
  fit.curvature = computeVertexCurvature(fit.field, vertex);
  reportProgress(params.progress, 0.8);
  CurvatureField out;
  detail::resizeCurvatureField(out, part.allHeights().size());
  out.step = 1;
  out.method = CurvatureMethod::DesignMeshFit;
  std::vector<char> onDesign(static_cast<std::size_t>(part.faceCount()), 0);
  auto body = [&](const tbb::blocked_range<int>& r) {
    for (int f = r.begin(); f < r.end(); ++f)
      onDesign[f] = transferFace(part, f, fit, feet, params, out);
  };
  const tbb::blocked_range<int> all(0, part.faceCount(), 64);
  params.parallel ? tbb::parallel_for(all, body) : body(all);
  std::vector<int> off;
  for (int f = 0; f < part.faceCount(); ++f)
    if (!onDesign[f]) off.push_back(f);
  fillOffDesignFaces(part, off, params, out);
  reportProgress(params.progress, 1.0);
  return out;
}

}  // namespace ddfcam::planning
