// SPDX-License-Identifier: MIT
// ddfcam: the planning choices a region carries (sec. 8.1): tool, flow field, spacing, feed.
#pragma once

#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/planning/flow/flow_field_source.h>

#include <vector>

namespace ddfcam::planning {

/// @brief How the distance between neighbouring paths of a region is chosen.
enum class SpacingMode {
  FixedSpacing,      ///< RegionPlan::spacingMm between neighbouring paths
  ScallopTolerance,  ///< spacing from RegionPlan::scallopToleranceMm and the tool
};

/// @brief In which order and direction the paths of a region are cut.
enum class LinkingOrder {
  ZigZag,       ///< alternate directions, each path starts near the previous one's end
  OneDirection  ///< every path in the feed direction; a link returns to the next start
};

/// @brief Planning choices of one region. Defaults give a usable plan on a fresh region.
struct RegionPlan {
  /// Index into Project::tools; -1: no tool chosen yet (default -1).
  int tool = -1;
  /// Raw direction of the tool flow field (default: direction of maximum curvature).
  FlowFieldSource flowSource = FlowFieldSource::MaxCurvatureDirection;
  /// Direction for FlowFieldSource::FixedDirection, part frame, any length > 0 (default +x).
  ddf::Vec3 fixedDirection = ddf::Vec3::UnitX();
  /// Directions drawn by the user: polylines on the surface, mm, part frame; their tangents
  /// are the flow direction where they run (default none).
  std::vector<std::vector<ddf::Vec3>> strokes;
  /// Smooth the raw field (default true).
  bool smoothField = true;
  /// Smoothness weight lambda of the field, dimensionless (default 0.02, as FlowFieldParams).
  double smoothnessWeight = 0.02;
  /// How the path spacing is chosen (default FixedSpacing).
  SpacingMode spacingMode = SpacingMode::FixedSpacing;
  /// Distance between neighbouring paths for FixedSpacing, mm, > 0 (default 1).
  double spacingMm = 1.0;
  /// Largest scallop height for ScallopTolerance, mm, > 0 (default 0.01).
  double scallopToleranceMm = 0.01;
  /// Cutting direction along the field: +1 or -1 (default +1). Lines have no sign; this picks
  /// one of the two directions consistently along the region.
  int feedSign = 1;
  /// Order of the paths (default ZigZag).
  LinkingOrder linking = LinkingOrder::ZigZag;

  bool operator==(const RegionPlan&) const = default;
};

}  // namespace ddfcam::planning
