// SPDX-License-Identifier: MIT
// ddfcam: the heights of a converted DDF at a resolution that meets the accuracy asked for,
// and the crust fit to a stock allowance.
#pragma once

#include <ddfcam/ddf/mesh_conversion.h>

#include <span>
#include <string>

namespace ddfcam::ddf::detail {

/// @brief Sub-range [from, to] of @p progress (empty when @p progress is).
ProgressCallback progressShare(const ProgressCallback& progress, double from, double to);

/// @brief Fills the heights of result.ddf from @p mesh (its support and vectors are final),
/// raising the resolution for params.toleranceMm, fitting the crust for params.stockMm, and
/// measuring the distances to @p mesh where params ask for them (see ConversionParams); sets
/// result.accuracy (with a note on a tolerance not met), result.stock, the fill counts and
/// their copies in result.report.
/// @param keptTriangles the input triangles the support kept: the input samples are taken
/// from them. Progress runs over [0.6, 1] of params.progress.
/// @param warnOnMiss log the note on a tolerance not met as a warning; false leaves that to
/// the caller (the tolerance tries of a reduced support, which try other supports).
/// @throws Cancelled through params.progress.
void fillHeights(const TriangleMesh& mesh, const ConversionParams& params,
                 std::span<const int> keptTriangles, ConversionResult& result,
                 bool warnOnMiss = true);

/// @brief The note on a tolerance not met: m, spacing, both distances and where they are
/// largest, then @p why.
std::string toleranceNote(const ConversionAccuracy& accuracy, const std::string& why);

/// @brief @p x formatted as "%.4g mm".
std::string mm(double x);

/// @brief @p p formatted as "(x, y, z)" with 4 digits.
std::string at(const Vec3& p);

}  // namespace ddfcam::ddf::detail
