// SPDX-License-Identifier: MIT
// ddfcam: the exact 2D profiles (lines and circular arcs) of the tools of tool.h, and their
// sampling at a chord tolerance.
#pragma once

#include <ddfcam/planning/tools/revolved_mesh.h>
#include <ddfcam/planning/tools/tool.h>

#include <utility>
#include <vector>

namespace ddfcam::planning {

/// @brief One piece of a profile in the (axial, radial) half plane, mm: a straight segment
/// from @p from to @p to, or (isArc) the circular arc of @p arcRadius about @p centre whose
/// points are centre + arcRadius (cos(startAngle + u sweepAngle), sin(startAngle + u
/// sweepAngle)) for u in [0, 1], the angle measured from +axial towards +radial (rad).
struct ProfileSegment {
  ProfilePoint from;        ///< start point, mm
  ProfilePoint to;          ///< end point, mm (the next segment's from)
  bool isArc = false;       ///< false: straight line (default)
  ProfilePoint centre;      ///< arc centre, mm (arcs only)
  double arcRadius = 0.0;   ///< arc radius, mm (arcs only)
  double startAngle = 0.0;  ///< angle of @p from about the centre, rad (arcs only)
  double sweepAngle = 0.0;  ///< signed angle from @p from to @p to, rad (arcs only)

  /// @brief The point at parameter @p u in [0, 1] (0 = from, 1 = to).
  ProfilePoint at(double u) const;
};

/// @brief The exact profile of a solid of revolution: connected segments from a pole (radial
/// 0) to a pole, revolved about @p axis in the tool frame (see RevolveAxis, ToolKind).
struct ToolProfile {
  RevolveAxis axis = RevolveAxis::X;     ///< rotation axis in the tool frame (default X)
  std::vector<ProfileSegment> segments;  ///< pole to pole, connected (default empty)

  /// @brief Largest radial coordinate of the profile at @p axial (the tool's radius at that
  /// station, mm); 0 outside the profile's axial range.
  double radiusAt(double axial) const;
  /// @brief Axial range (min, max) covered by the profile, mm.
  std::pair<double, double> axialRange() const;
  /// @brief Largest radial coordinate, mm.
  double maxRadius() const;
};

/// @brief The exact profile of the cutting part of @p tool:
/// - CylinderRoll, BeltContactWheel (axis X): side face at axial -width/2 from the axis up,
///   rim fillet of edgeRadiusMm, the mantle (straight at radius, or with crownRadiusMm > 0 the
///   arc of that radius whose highest point is (0, radiusMm)), fillet, side face down at
///   +width/2;
/// - Sphere (axis Z): the half circle of radiusMm about the origin from (-r, 0) to (r, 0);
/// - BallEnd (axis Z): quarter circle from the tip (0, 0) to (r, r), straight to (width, r),
///   flat top to (width, 0);
/// - FlatEnd (axis Z): (0, 0), (0, r), (width, r), (width, 0);
/// - TorusCutter (axis Z): (0, 0), (0, r - e), quarter circle of e about (e, r - e) to (e, r),
///   straight to (width, r), flat top to (width, 0).
/// @throws InvalidInput as validateTool().
ToolProfile toolProfile(const Tool& tool);

/// @brief Profiles of the non-cutting part of @p tool, one per connected solid (each pole to
/// pole, same axis as toolProfile()): wheels: on each side the union of the arbor (radius
/// shankRadiusMm, from the side face outwards shankLengthMm) and the flange (holderRadiusMm,
/// thickness holderLengthMm against the side face); cutters: the shank (shankRadiusMm, axial
/// width .. width + shankLengthMm) and the holder (holderRadiusMm, above the shank,
/// holderLengthMm long), as one stepped solid when both are present. Parts with a zero radius
/// or length are left out; Sphere has none. Empty if there is no non-cutting part.
/// @throws InvalidInput as validateTool().
std::vector<ToolProfile> nonCuttingProfiles(const Tool& tool);

/// @brief Polyline through @p profile: segment ends exactly, straight segments as they are,
/// each arc split into equal pieces of at most @p maxArcStepRad of turn and a chord sagitta of
/// at most @p chordToleranceMm (<= 0: no sagitta limit). Every returned point lies on the
/// profile; no two consecutive points are equal. The mantle arc of a crowned wheel is split
/// into an even number of pieces, so a point lies on its crest.
/// @throws InvalidInput if both limits are off (maxArcStepRad <= 0 and chordToleranceMm <= 0).
std::vector<ProfilePoint> sampleProfile(const ToolProfile& profile, double chordToleranceMm,
                                        double maxArcStepRad);

/// @brief Facets around the circumference that keep the chord sagitta of a circle of
/// @p radiusMm within @p chordToleranceMm: the smallest multiple of 4 (at least 8) with
/// radius (1 - cos(pi / s)) <= tolerance.
/// @throws InvalidInput if it exceeds @p maxSegments or the inputs are not positive.
int segmentsForChordTolerance(double radiusMm, double chordToleranceMm, int maxSegments = 4096);

}  // namespace ddfcam::planning
