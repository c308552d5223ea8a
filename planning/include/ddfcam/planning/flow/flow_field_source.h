// SPDX-License-Identifier: MIT
// ddfcam: where the raw tool flow direction comes from (a plain choice regions store).
#pragma once

namespace ddfcam::planning {

/// @brief Where the raw tool flow direction comes from.
enum class FlowFieldSource {
  MaxCurvatureDirection,  ///< CurvatureField::dirMax
  MinCurvatureDirection,  ///< CurvatureField::dirMin
  FixedDirection,         ///< FlowFieldParams::fixedDirection projected onto the tangent plane
  UserStrokes             ///< tangents of the polylines FlowFieldParams::strokes drawn by the user
};

}  // namespace ddfcam::planning
