// SPDX-License-Identifier: MIT
// ddfcam: the arc of an APT CIRCLE record as chords within a tolerance.
#pragma once

#include <ddfcam/ddf/support_mesh.h>

#include <cstddef>
#include <string>
#include <vector>

namespace ddfcam::io::detail {

/// Most chords one CIRCLE arc may be cut into (a cap on top of the reader's cap on the radius
/// and on the points of all arcs of a program).
inline constexpr double kMaxAptArcChords = 1e6;

/// @brief A CIRCLE record converted to mm.
struct AptCircle {
  ddf::Vec3 centreMm = ddf::Vec3::Zero();  ///< a point on the circle's axis, mm
  ddf::Vec3 axis = ddf::Vec3::UnitZ();     ///< unit axis vector as written
  double radiusMm = 0.0;                   ///< radius, mm, > 0
  double radiusToleranceMm = 0.0;          ///< allowed mismatch of the end points' radii, mm
  int line = 0;                            ///< line of the CIRCLE record
};

/// @brief The points strictly between @p startMm and @p endMm of the arc of @p circle, in
/// order: the tool turns clockwise seen from the tip of the axis vector (a right-hand turn
/// about -axis; this is how the NX CLSFs write G02 with axis +z), from start to end;
/// coincident start and end make a full circle. Points lie at exactly radiusMm from the axis;
/// their height along the axis goes linearly from start to end (helix). Every chord (the
/// first from @p startMm, the last to @p endMm) is within @p chordToleranceMm of the arc.
/// @param maxPoints most points the caller accepts (its remaining budget); nothing is appended
/// to @p out when the arc needs more.
/// @return false with @p problem set if start or end is not at the radius (within
/// radiusToleranceMm), or the arc needs more than kMaxAptArcChords chords or more than
/// @p maxPoints points.
bool interpolateAptArc(const AptCircle& circle, const ddf::Vec3& startMm, const ddf::Vec3& endMm,
                       double chordToleranceMm, std::size_t maxPoints, std::vector<ddf::Vec3>& out,
                       std::string& problem);

}  // namespace ddfcam::io::detail
