// SPDX-License-Identifier: MIT
// ddfcam: automatic segmentation of a part by curvature type and tool-size class (sec. 8.1).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/model/project.h>
#include <ddfcam/progress.h>

#include <cstdint>
#include <string>
#include <vector>

namespace ddfcam::planning {

/// @brief Curvature type of a surface point as seen from the tool (tool-side signs of
/// CurvatureField). The values are stable: they are stored as bytes and shown in colour maps.
enum class CurvatureType : std::uint8_t {
  Flat = 0,     ///< both principal curvatures count as zero
  Convex = 1,   ///< k_max > 0, k_min >= 0: bends away from the tool (also a convex cylinder)
  Concave = 2,  ///< k_min < 0, k_max <= 0: bends towards the tool (also a concave cylinder)
  Saddle = 3    ///< k_max > 0 > k_min
};

/// @brief Lower-case name of @p type: "flat", "convex", "concave" or "saddle".
const char* curvatureTypeName(CurvatureType type);

/// @brief Thresholds of classifyCurvature().
struct CurvatureTypeParams {
  /// A principal curvature with |k| at most this counts as zero, 1/mm (default 1e-3: radii
  /// above 1 m are flat; well above the curvature error of a DDF at m >= 9).
  double flatCurvaturePerMm = 1e-3;
};

/// @brief Curvature type of every raster point of @p curvature (layout of allHeights()).
/// @returns curvature.size() bytes, each a CurvatureType value; NaN curvature gives Flat.
/// @throws InvalidInput if flatCurvaturePerMm is negative or not finite.
std::vector<std::uint8_t> classifyCurvature(const CurvatureField& curvature,
                                            const CurvatureTypeParams& params = {});

/// @brief classifyCurvature() as a ScalarField "curvature type" (values 0..3 = CurvatureType,
/// unsigned, no unit) for colour maps.
/// @throws InvalidInput as classifyCurvature().
ScalarField curvatureTypeField(const CurvatureField& curvature,
                               const CurvatureTypeParams& params = {});

/// @brief Radius reported where no radius bound exists (convex or flat points), mm. Kept
/// finite so that colour maps and histograms stay meaningful.
inline constexpr double kUnlimitedToolRadiusMm = 1e6;

/// @brief The largest ball or wheel-crown radius that does not gouge at every raster point:
/// 1/|k_min| where k_min < 0 (the tool side bends towards the tool, sec. 8.1), capped at
/// @p capMm, and @p capMm where k_min >= 0. NaN curvature gives NaN.
/// @returns ScalarField "max tool radius", unit "mm", unsigned, curvature.size() values.
/// @throws InvalidInput if capMm is not positive and finite.
ScalarField maxToolRadiusField(const CurvatureField& curvature,
                               double capMm = kUnlimitedToolRadiusMm);

/// @brief Label of a raster point or face whose curvature admits none of the tool radii.
inline constexpr int kNoToolFits = -1;

/// @brief Tool-size class of every raster point: the index into @p toolRadiiMm of the largest
/// radius that does not gouge there (radius <= maxToolRadius * (1 + relativeTolerance)), or
/// kNoToolFits when even the smallest one gouges. NaN curvature gives kNoToolFits.
/// @param toolRadiiMm available ball or wheel-crown radii, mm, strictly ascending, positive.
/// @param relativeTolerance accepted relative excess of a tool radius over the bound (>= 0).
/// @returns curvature.size() class indices.
/// @throws InvalidInput if @p toolRadiiMm is empty, not strictly ascending or not positive,
/// or relativeTolerance is negative.
std::vector<int> classifyToolRadius(const CurvatureField& curvature,
                                    const std::vector<double>& toolRadiiMm,
                                    double relativeTolerance = 0.0);

/// @brief Options of the segmentation functions.
struct SegmentationParams {
  CurvatureTypeParams type;  ///< thresholds of the curvature type (default: see there)
  /// Accepted relative excess of a tool radius over 1/|k_min| in segmentByToolRadius()
  /// (default 0: never accept a radius the estimated curvature forbids).
  double relativeRadiusTolerance = 0.0;
  /// Regions with fewer faces are merged into a neighbour (default 4; 1 keeps all regions).
  int minFaces = 4;
  /// Regions whose support area is below this are merged into a neighbour, mm^2 (default 0).
  double minAreaMm2 = 0.0;
  /// Progress in [0, 1]; returning false cancels (default: none).
  ProgressCallback progress;
};

/// @brief Regions from one label per support face: connected components of equally labelled
/// faces (faces are adjacent when they share a support edge); then, smallest first (face
/// count, area, lowest face), every small region (fewer than minFaces faces or support area
/// below minAreaMm2) is merged into the adjacent region it shares the longest boundary with
/// (ties: the larger, then the one with the lower first face) and takes its label, until no
/// small region has a neighbour (an isolated small component stays). Regions are ordered by
/// their lowest face and named "<labelNames[label]> <1-based position>"; colours are
/// pairwise distinct. Every face lies in exactly one region.
/// @param faceLabels one label in [0, labelNames.size()) per support face.
/// @throws InvalidInput on a size mismatch, a label out of range, minFaces < 1 or a
/// negative minAreaMm2. @throws Cancelled if params.progress asks to stop.
std::vector<Region> segmentFaces(const ddf::DisplacementField& ddf,
                                 const std::vector<int>& faceLabels,
                                 const std::vector<std::string>& labelNames,
                                 const SegmentationParams& params = {});

/// @brief Segmentation by curvature type (fig. 8.4b): each support face takes the majority
/// CurvatureType of its raster points (ties: lower CurvatureType value), then segmentFaces()
/// with the names "flat", "convex", "concave", "saddle" (e.g. "convex 1", "concave 2").
/// @param curvature computeCurvature(ddf), F * pointsPerFace entries.
/// @throws InvalidInput if the curvature does not match the DDF's layout, or as
/// segmentFaces(). @throws Cancelled if params.progress asks to stop.
std::vector<Region> segmentByCurvatureType(const ddf::DisplacementField& ddf,
                                           const CurvatureField& curvature,
                                           const SegmentationParams& params = {});

/// @brief Segmentation into tool-size classes: each support face takes the majority
/// classifyToolRadius() class of its raster points (ties: the smaller radius), then
/// segmentFaces() with the names "radius <r> mm" (r the largest fitting radius of the
/// class, e.g. "radius 5 mm 3") and "no tool".
/// @param toolRadiiMm available radii, mm, strictly ascending, positive.
/// @throws InvalidInput as classifyToolRadius(), on a layout mismatch, or as segmentFaces().
/// @throws Cancelled if params.progress asks to stop.
std::vector<Region> segmentByToolRadius(const ddf::DisplacementField& ddf,
                                        const CurvatureField& curvature,
                                        const std::vector<double>& toolRadiiMm,
                                        const SegmentationParams& params = {});

}  // namespace ddfcam::planning
