// SPDX-License-Identifier: MIT
// ddfcam: the tolerance class of every raster point against the design, kept up to date face by
// face while a simulation cuts (the live tolerance band of paper 003, app. A).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/inspection/error_map.h>

#include <cstdint>
#include <span>
#include <vector>

namespace ddfcam::planning {

/// @brief Per raster point of a part (layout of DisplacementField::allHeights()), its
/// ToleranceClass against a design on the same support and vectors: the class of the
/// deviation deviationMap() gives there, (h - h_design) (v . n) with n the design surface's
/// oriented normal (rasterPointNormals of the design), mm, cast to float as deviationMap does.
/// The factors v . n are computed once; update() re-classifies only the faces a cut changed,
/// at about 2 ns per raster point.
class LiveToleranceMap {
 public:
  /// Class value of a raster point without a deviation (a NaN height).
  static constexpr std::uint8_t kNoValue = 255;

  /// @param design support, vectors and the design's heights.
  /// @param band the tolerance band, mm (validateToleranceBand).
  /// @throws InvalidInput for an invalid band.
  LiveToleranceMap(const ddf::DisplacementField& design, const ToleranceBand& band);

  /// @brief Classifies every raster point of @p part (same support as the design).
  /// @throws InvalidInput if @p part has another number of heights.
  void updateAll(const ddf::DisplacementField& part);
  /// @brief Re-classifies the raster points of @p faces (any order, duplicates allowed).
  /// @throws InvalidInput if @p part has another number of heights or a face is out of range.
  void update(const ddf::DisplacementField& part, std::span<const int> faces);

  /// @brief static_cast<std::uint8_t>(ToleranceClass) per raster point, or kNoValue.
  const std::vector<std::uint8_t>& classes() const { return classes_; }
  const ToleranceBand& band() const { return band_; }

 private:
  void classifyFace(const ddf::DisplacementField& part, int face);
  void checkPart(const ddf::DisplacementField& part) const;

  std::vector<float> designHeights_;
  std::vector<double> factors_;  // v . n per raster point
  std::vector<std::uint8_t> classes_;
  std::size_t pointsPerFace_ = 0;
  ToleranceBand band_;
};

}  // namespace ddfcam::planning
