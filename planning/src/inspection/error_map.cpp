// SPDX-License-Identifier: MIT
// ddfcam: error maps: signed normal deviation per raster point, raster point areas, path samples.
#include "error_region.h"

#include <ddfcam/ddf/surface_locator.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/inspection/error_map.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

// Surface points g + h v of every raster point, laid out like the heights; NaN for a
// non-finite height.
std::vector<Vec3> surfacePoints(const ddf::DisplacementField& ddf, std::span<const float> heights) {
  std::vector<Vec3> points(heights.size());
  const int n = ddf.raster().steps();
  tbb::parallel_for(tbb::blocked_range<int>(0, ddf.faceCount()), [&](const auto& range) {
    for (int f = range.begin(); f != range.end(); ++f) {
      const std::size_t base = static_cast<std::size_t>(f) * ddf.pointsPerFace();
      std::size_t l = base;
      for (int k = 0; k <= n; ++k)
        for (int i = 0; i + k <= n; ++i, ++l) {
          const double h = heights[l];
          points[l] = std::isfinite(h) ? ddf.pointAt(f, ddf.rasterBary(i, k), h)
                                       : Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
        }
    }
  });
  return points;
}

// Calls fn(a, b, c) with the flat indices of every raster triangle of face f, ordered so that
// (b - a) x (c - a) has the orientation of the support face (fig. 7.1a: "up" and "down"
// triangles of the lattice).
template <class Fn>
void forRasterTriangles(const ddf::DisplacementField& ddf, int f, Fn&& fn) {
  const ddf::Raster& raster = ddf.raster();
  const int n = raster.steps();
  const std::size_t base = static_cast<std::size_t>(f) * ddf.pointsPerFace();
  for (int k = 0; k < n; ++k)
    for (int i = 0; i + k < n; ++i) {
      const std::size_t a = base + raster.index(i, k);
      const std::size_t b = base + raster.index(i + 1, k);
      const std::size_t c = base + raster.index(i, k + 1);
      fn(a, c, b);
      if (i + k + 1 < n) fn(b, c, base + raster.index(i + 1, k + 1));
    }
}

// Twice the area-weighted normal of the raster triangles around every distinct raster point
// (PointId order), summed over the copies in all faces.
std::vector<Vec3> pointNormals(const ddf::DisplacementField& ddf, const std::vector<Vec3>& points) {
  std::vector<Vec3> perCopy(points.size(), Vec3::Zero());
  tbb::parallel_for(tbb::blocked_range<int>(0, ddf.faceCount()), [&](const auto& range) {
    for (int f = range.begin(); f != range.end(); ++f)
      forRasterTriangles(ddf, f, [&](std::size_t a, std::size_t b, std::size_t c) {
        const Vec3 cross = (points[b] - points[a]).cross(points[c] - points[a]);
        if (!cross.allFinite()) return;
        perCopy[a] += cross;
        perCopy[b] += cross;
        perCopy[c] += cross;
      });
  });
  std::vector<Vec3> perPoint(ddf.topology().pointCount(), Vec3::Zero());
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f) {
    std::size_t l = static_cast<std::size_t>(f) * ddf.pointsPerFace();
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i, ++l) perPoint[ddf.topology().id(f, i, k)] += perCopy[l];
  }
  return perPoint;
}

void checkSameSupport(const ddf::DisplacementField& a, const ddf::DisplacementField& b) {
  if (a.faceCount() != b.faceCount() || a.vertexCount() != b.vertexCount() ||
      a.resolution() != b.resolution()) {
    throw InvalidInput(
        "deviationMap: the produced DDF (" + std::to_string(a.faceCount()) + " faces, " +
        std::to_string(a.vertexCount()) + " vertices, m = " + std::to_string(a.resolution()) +
        ") and the desired DDF (" + std::to_string(b.faceCount()) + " faces, " +
        std::to_string(b.vertexCount()) + " vertices, m = " + std::to_string(b.resolution()) +
        ") do not share a support");
  }
}

// Unit normals per copy of the surface through @p points (laid out like the heights), oriented
// like the copy's vector v; v's direction where no valid raster triangle surrounds the point.
std::vector<Vec3> orientedUnitNormals(const ddf::DisplacementField& ddf,
                                      const std::vector<Vec3>& points) {
  const std::vector<Vec3> sums = pointNormals(ddf, points);
  std::vector<Vec3> out(points.size());
  const int n = ddf.raster().steps();
  tbb::parallel_for(tbb::blocked_range<int>(0, ddf.faceCount()), [&](const auto& range) {
    for (int f = range.begin(); f != range.end(); ++f) {
      std::size_t l = static_cast<std::size_t>(f) * ddf.pointsPerFace();
      for (int k = 0; k <= n; ++k)
        for (int i = 0; i + k <= n; ++i, ++l) {
          const Vec3 v = ddf.vectorAt(f, ddf.rasterBary(i, k));
          const Vec3& sum = sums[ddf.topology().id(f, i, k)];
          if (!(sum.norm() > 0.0)) {
            out[l] = v.normalized();
            continue;
          }
          const Vec3 unit = sum.normalized();
          out[l] = v.dot(unit) < 0.0 ? Vec3(-unit) : unit;
        }
    }
  });
  return out;
}

}  // namespace

std::vector<Vec3> rasterPointNormals(const ddf::DisplacementField& ddf) {
  return orientedUnitNormals(ddf, surfacePoints(ddf, ddf.allHeights()));
}

ScalarField deviationMap(const ddf::DisplacementField& produced,
                         std::span<const float> desiredHeights) {
  detail::checkFieldSize(produced, desiredHeights.size(), "deviationMap: desired heights");
  const std::vector<Vec3> normals =
      orientedUnitNormals(produced, surfacePoints(produced, desiredHeights));
  ScalarField field{"deviation", "mm", true, std::vector<float>(desiredHeights.size()), {}};
  const std::vector<float>& heights = produced.allHeights();
  const int n = produced.raster().steps();
  tbb::parallel_for(tbb::blocked_range<int>(0, produced.faceCount()), [&](const auto& range) {
    for (int f = range.begin(); f != range.end(); ++f) {
      std::size_t l = static_cast<std::size_t>(f) * produced.pointsPerFace();
      for (int k = 0; k <= n; ++k)
        for (int i = 0; i + k <= n; ++i, ++l) {
          const Vec3 v = produced.vectorAt(f, produced.rasterBary(i, k));
          // v . n >= 0 by the orientation; n = v / |v| where no raster triangle is valid.
          field.values[l] = static_cast<float>(
              (static_cast<double>(heights[l]) - static_cast<double>(desiredHeights[l])) *
              v.dot(normals[l]));
        }
    }
  });
  return field;
}

ScalarField deviationMap(const ddf::DisplacementField& produced,
                         const ddf::DisplacementField& desired) {
  checkSameSupport(produced, desired);
  return deviationMap(produced, std::span<const float>(desired.allHeights()));
}

std::vector<double> rasterPointAreas(const ddf::DisplacementField& ddf) {
  const std::vector<Vec3> points = surfacePoints(ddf, ddf.allHeights());
  std::vector<double> areas(points.size(), 0.0);
  tbb::parallel_for(tbb::blocked_range<int>(0, ddf.faceCount()), [&](const auto& range) {
    for (int f = range.begin(); f != range.end(); ++f)
      forRasterTriangles(ddf, f, [&](std::size_t a, std::size_t b, std::size_t c) {
        const double third = (points[b] - points[a]).cross(points[c] - points[a]).norm() / 6.0;
        if (!std::isfinite(third)) return;
        areas[a] += third;
        areas[b] += third;
        areas[c] += third;
      });
  });
  return areas;
}

std::vector<PathDeviationSample> deviationAlongLocations(
    const ScalarField& deviation, const ddf::DisplacementField& ddf,
    std::span<const ddf::SurfaceLocation> locations) {
  detail::checkFieldSize(ddf, deviation.values.size(), "deviationAlongLocations: deviation");
  std::vector<PathDeviationSample> out;
  out.reserve(locations.size());
  double arc = 0.0;
  for (std::size_t s = 0; s < locations.size(); ++s) {
    const ddf::SurfaceLocation& location = locations[s];
    if (s > 0) arc += (location.point - locations[s - 1].point).norm();
    out.push_back({0, arc, location.point,
                   ddf::interpolateOnFace(ddf, deviation.values, location.face, location.bary)});
  }
  return out;
}

std::vector<PathDeviationSample> deviationAlongPath(const ScalarField& deviation,
                                                    const ddf::DisplacementField& ddf,
                                                    const ToolPath& path) {
  detail::checkFieldSize(ddf, deviation.values.size(), "deviationAlongPath: deviation");
  std::vector<PathDeviationSample> out;
  out.reserve(path.poses.size());
  const ddf::SurfaceLocator locator(ddf);
  double arc = 0.0;
  int pass = 0;
  for (std::size_t p = 0; p < path.poses.size(); ++p) {
    const Vec3& contact = path.poses[p].contact;
    const bool newPass =
        std::binary_search(path.passStarts.begin(), path.passStarts.end(), static_cast<int>(p));
    if (newPass && p > 0) ++pass;
    if (p > 0 && !newPass) arc += (contact - path.poses[p - 1].contact).norm();
    PathDeviationSample sample{pass, arc, contact, std::numeric_limits<double>::quiet_NaN()};
    if (const auto location = locator.locate(contact)) {
      sample.deviationMm =
          ddf::interpolateOnFace(ddf, deviation.values, location->face, location->bary);
    }
    out.push_back(sample);
  }
  return out;
}

std::vector<PathDeviationSample> deviationAlongPath(const ddf::DisplacementField& produced,
                                                    const ddf::DisplacementField& desired,
                                                    const ToolPath& path) {
  return deviationAlongPath(deviationMap(produced, desired), desired, path);
}

}  // namespace ddfcam::planning
