// SPDX-License-Identifier: MIT
// ddfcam tests: loading the shared turbine blade and bunny once, and brute-force distances.
#pragma once

#include "../support/brute_force_distance.h"

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/mesh/part_loader.h>
#include <ddfcam/planning/analysis/curvature.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ddfcam::io::test {

using ddf::Vec3;
using ddfcam::test::meshDistance;
using ddfcam::test::triangleDistance;

/// Raster resolution of the converted parts: enough raster points per face for the blended
/// vertex curvature, few enough for every stage to stay well below a second.
constexpr int kResolution = 5;

inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

inline double segmentDistance(const Vec3& q, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp((q - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  return (a + t * ab - q).norm();
}

/// One shared part through the pipeline, computed once per test program.
struct Part {
  ddf::TriangleMesh mesh;
  ddf::DisplacementField ddf;
  double diagonal = 0.0;
  planning::CurvatureField curvature;
};

inline std::filesystem::path meshPath(const std::string& file) {
  return std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "meshes" / file;
}

/// Loads @p file through io::loadPart and computes its curvature (cached); null if absent.
inline const Part* sharedPart(const std::string& file) {
  static std::map<std::string, std::unique_ptr<Part>> cache;
  auto& slot = cache[file];
  if (slot) return slot.get();
  const auto path = meshPath(file);
  if (!std::filesystem::exists(path)) return nullptr;
  auto part = std::make_unique<Part>();
  part->mesh = readMesh(path);
  const auto [lo, hi] = part->mesh.bounds();
  part->diagonal = (hi - lo).norm();
  auto start = std::chrono::steady_clock::now();
  LoadPartParams load;
  load.conversion.resolution = kResolution;
  part->ddf = loadPart(path, load);
  std::printf("[%s] load + convert (m = %d, %d faces): %.3f s\n", file.c_str(), kResolution,
              part->ddf.faceCount(), secondsSince(start));
  start = std::chrono::steady_clock::now();
  part->curvature = planning::computeCurvature(part->ddf);
  std::printf("[%s] curvature: %.3f s\n", file.c_str(), secondsSince(start));
  slot = std::move(part);
  return slot.get();
}

/// Calls @p fn(face, a, b, c) for every raster triangle, with a, b, c flat indices into the
/// face's raster (up triangles, then down triangles, row by row).
template <typename Fn>
inline void forEachRasterTriangle(const ddf::DisplacementField& ddf, Fn&& fn) {
  const auto& raster = ddf.raster();
  const int n = raster.steps();
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k < n; ++k)
      for (int i = 0; i + k < n; ++i) {
        fn(f, raster.index(i, k), raster.index(i + 1, k), raster.index(i, k + 1));
        if (i + k + 2 <= n)
          fn(f, raster.index(i + 1, k), raster.index(i + 1, k + 1), raster.index(i, k + 1));
      }
}

/// Raster points of every face, flat index -> represented point (Raster order).
inline std::vector<Vec3> rasterPoints(const ddf::DisplacementField& ddf) {
  std::vector<Vec3> out;
  out.reserve(ddf.allHeights().size());
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) out.push_back(ddf.surfacePoint(f, i, k));
  return out;
}

}  // namespace ddfcam::io::test
