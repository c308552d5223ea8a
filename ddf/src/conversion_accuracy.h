// SPDX-License-Identifier: MIT
// ddfcam: how far a converted DDF lies from its input mesh, measured both ways on sample
// points, and the raster resolution a spacing or a point budget allows.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/progress.h>

#include <cstddef>
#include <span>
#include <vector>

#include "deformation_stage.h"

namespace ddfcam::ddf::detail {

/// @brief Largest of the two distances of measureDistances() and where they occur.
struct MeasuredDistances {
  double inputToDdfMm = 0.0;             ///< largest input sample to raster surface distance
  double ddfToInputMm = 0.0;             ///< largest stored raster point to input distance
  Vec3 worstInputPoint = Vec3::Zero();   ///< input sample of inputToDdfMm, mm
  Vec3 worstRasterPoint = Vec3::Zero();  ///< raster surface point of ddfToInputMm, mm
  double worstMm() const { return inputToDdfMm > ddfToInputMm ? inputToDdfMm : ddfToInputMm; }
};

/// @brief Longest edge of @p support, mm (0 without edges).
double longestSupportEdgeMm(const SupportMesh& support);

/// @brief Heights stored by @p faces faces at resolution @p m: faces x m (m + 1) / 2.
std::size_t storedRasterPoints(int faces, int m);

/// @brief Smallest m in [2, 256] with longestEdgeMm / (m - 1) <= spacingMm.
/// @throws InvalidInput when that m exceeds 256 or the raster would store more than
/// @p maxRasterPoints heights (the message names the point count and the memory it needs).
int resolutionForSpacing(double longestEdgeMm, int faces, double spacingMm,
                         std::size_t maxRasterPoints);

/// @brief Sample points of the listed triangles of @p input: their vertices (once each), edge
/// midpoints and centroids, mm.
std::vector<Vec3> inputSamples(const TriangleMesh& input, std::span<const int> triangles);

/// @brief Both-way distances between @p ddf and the input: every sample of @p samples to the
/// represented surface triangulated along the raster (extractRasterMesh), and the surface
/// point of every stored raster point to the input mesh of @p inputBvh. Parallel (TBB); calls
/// @p progress between blocks. @throws Cancelled through @p progress.
MeasuredDistances measureDistances(const DisplacementField& ddf, std::span<const Vec3> samples,
                                   const TriangleBvh& inputBvh, const ProgressCallback& progress);

}  // namespace ddfcam::ddf::detail
