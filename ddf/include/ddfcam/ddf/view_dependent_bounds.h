// SPDX-License-Identifier: MIT
// ddfcam: error bounds per support face from a view (a projected-pixel level of detail, as the
// adaptive display of paper 003): what the camera sees small is triangulated coarsely.
#pragma once

#include <ddfcam/ddf/displacement_field.h>

#include <vector>

namespace ddfcam::ddf {

/// @brief A camera and the display's tolerance, for viewDependentBounds().
struct ViewBoundsParams {
  Vec3 eyeMm = Vec3::Zero();           ///< camera position, mm, part frame (perspective)
  Vec3 direction = -Vec3::UnitZ();     ///< unit view direction, part frame
  double viewAngleDeg = 30.0;          ///< vertical view angle (perspective), degrees
  bool parallel = false;               ///< parallel projection instead of perspective
  double parallelScaleMm = 50.0;       ///< half the view's height, mm (parallel projection)
  int viewportHeightPx = 800;          ///< height of the view, pixels (> 0)
  double aspect = 1.0;                 ///< width / height of the view (> 0)
  /// Largest error a triangle may show on the screen, pixels (> 0). Default 0.5.
  double pixelError = 0.5;
  /// Bounds are minEpsMm * 2^j, j >= 0, at most maxEpsMm: powers of two keep most faces' bounds
  /// when the camera moves a little. Defaults 0.01 and 1.28 mm.
  double minEpsMm = 0.01;
  double maxEpsMm = 1.28;
};

/// @brief Checks @p view as viewDependentBounds() does. @throws InvalidInput as it.
void validateViewBounds(const ViewBoundsParams& view);

/// @brief Error bound per support face (mm, for AdaptiveTriangulationParams::faceEpsMm and
/// IncrementalTriangulation::setFaceEps): pixelError times the size of a pixel at the face's
/// nearest depth (the depth of its corners' surface points along the view direction, less
/// their spread), rounded down to minEpsMm * 2^j and clamped to [minEpsMm, maxEpsMm]. A face
/// behind the eye or outside the view's frustum gets maxEpsMm; one in view reaching the eye's
/// plane minEpsMm.
/// @throws InvalidInput for a non-positive viewport, aspect, pixel error or angle, a zero
/// direction, or minEpsMm <= 0 or maxEpsMm < minEpsMm.
std::vector<float> viewDependentBounds(const DisplacementField& ddf, const ViewBoundsParams& view);

}  // namespace ddfcam::ddf
