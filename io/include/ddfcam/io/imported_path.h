// SPDX-License-Identifier: MIT
// ddfcam: placing a cutter-location program read from a file on a part as a planning::ToolPath.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/io/cl_program.h>
#include <ddfcam/planning/tool.h>
#include <ddfcam/planning/tool_path.h>
#include <ddfcam/progress.h>

#include <Eigen/Geometry>

#include <optional>
#include <string>
#include <vector>

namespace ddfcam::io {

/// @brief How placeProgram() maps a program onto a part.
struct PlaceProgramParams {
  /// The unit the file's numbers are really in, when the file (or the reader's default) got it
  /// wrong: positions are rescaled by millimetresPer(*actualUnit) /
  /// millimetresPer(program.sourceUnit), feeds likewise. Empty: trust program.sourceUnit
  /// (default empty).
  std::optional<LengthUnit> actualUnit{};
  /// Program frame -> part frame, applied after the unit rescaling (rotation to axes and
  /// normals, the whole map to positions), mm. Must be finite and rigid (default identity).
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  /// Spindle axis, program frame, for points without one (3-axis programs); any length > 0
  /// (default +z: a cutter pointing down onto the part from above).
  ddf::Vec3 defaultAxis = ddf::Vec3::UnitZ();
  /// Keep Link moves (retract, approach, direct links) as poses of the path (default true).
  bool includeLinks = true;
  /// Keep Rapid moves as poses of the path; they usually travel above the part and cut
  /// nothing (default false).
  bool includeRapids = false;
  /// Contact programs: points without a normal take the part's normal at the surface point
  /// nearest to them (default true); false: such a program is refused.
  bool normalsFromPart = true;
  /// Name of the path; empty takes program.partName, or "imported path" if that is empty too
  /// (default empty).
  std::string name{};
  /// Index of the tool in the project (planning::ToolPath::tool) (default 0).
  int toolIndex = 0;
  /// A pose whose tool lies farther than this from the part surface (gap or penetration) is
  /// counted as off the part, mm, > 0 (default 2).
  double contactSearchMm = 2.0;
  /// Contact programs: lead and tilt angles derived from a point's axis and normal that are
  /// smaller than this are taken as 0, deg, >= 0 (default 0.1). A flat bottom or a straight
  /// wheel mantle touches with its rim at any non-zero angle, so rounding noise in the file's
  /// axes and normals would otherwise move the tool by a radius or half its width.
  double angleSnapDeg = 0.1;
  /// Progress in [0, 1] over the points and cancellation (default none).
  ProgressCallback progress{};
};

/// @brief A program placed on a part: a path that simulation (planning/grinding_simulation.h,
/// planning/path_simulation.h) and error maps (planning/error_map.h) take like a planned one.
struct ImportedPath {
  /// Poses (tool frame -> part frame, mm; see planning/tool.h for the tool frames) with
  /// contacts on the part surface, one pose per kept program point. A pass starts at the
  /// first point, after every dropped point (a rapid, or a link with includeLinks off: the
  /// tool left the surface there) and where a Cut follows a Cut of another program path
  /// (ClPoint::path); kept links and rapids belong to the pass they move in. Feed = the first
  /// cutting feed of the program times the unit factor (ToolPath's default, with a warning, if
  /// the program gives none); name and tool from the params.
  planning::ToolPath path;
  /// #P unit surface normals at the contacts, part frame, towards the tool.
  std::vector<ddf::Vec3> normals;
  /// #P distance from the tool to the part surface, mm: > 0 a gap, < 0 the depth the tool
  /// reaches into the surface (see placeProgram()).
  std::vector<double> contactDistancesMm;
  /// #P index into ClProgram::points of the point each pose was made from.
  std::vector<int> sourcePoints;
  /// Poses with |contact distance| > contactSearchMm (off the part, or far from it).
  int pointsOffPart = 0;
  /// Largest |contact distance| over the poses on the part, mm (0 if none is on it).
  double maxContactDistanceMm = 0.0;
  /// What placing noticed (off-part points, missing feed, dropped moves), with source lines.
  std::vector<ClMessage> warnings;
};

/// @brief Places @p program on @p part for @p tool.
///
/// Positions are rescaled (params.actualUnit) and transformed (params.transform) into the part
/// frame. Every kept point gives a tool reference point r and a unit spindle axis a, both in
/// the part frame:
/// - ToolReference programs: r = the point, a = its axis, else params.defaultAxis.
/// - Contact programs: r = the point + the offset of planning::placeToolDetailed() at the
///   point's normal n (the file's, or the part's with normalsFromPart) feeding towards the next
///   point of the pass (the previous one at its end). With an axis a in the file, cutters take
///   lead = asin(a.t) and tilt = atan2(-a.b, a.n) (t the unit tangential feed, b = n x t), so
///   their axis is a (angles below angleSnapDeg taken as 0); wheels feed across the axis's
///   tangential part with tilt = asin(a.n); Sphere ignores it. Without one, cutters stand along n
///   and wheels lie across the feed in the tangent plane (lead and tilt 0); params.defaultAxis is
///   not used.
/// The pose maps the tool's spindle axis (tool +x for wheels and Sphere, +z for cutters) onto
/// a and its origin onto r; the turn about the axis is carried from point to point by the
/// smallest rotation (continuous and deterministic; revolved tools do not depend on it).
///
/// Contact of a pose: of the tool's core samples (Sphere and wheels: their centre, reach =
/// radius; BallEnd: its ball centre, reach = radius; FlatEnd: its tip and 16 points of its
/// bottom rim, reach 0; TorusCutter: its tip, reach 0, and 16 points of the circle of corner
/// centres, reach = corner radius) the one whose distance to the part's raster mesh
/// (ddf::extractRasterMesh, planning::MeshDistance) minus its reach is smallest (earlier
/// samples win ties); its foot is then moved onto the point of the smooth surface where the
/// sample lies along planning::smoothSurfaceNormal() (a few fixed-point steps), which removes
/// the sideways shift the facets' normal jumps would cause. Contact = that foot, normal = the
/// smooth normal there (towards the side the DDF vectors point to, the tool side), distance =
/// +-|sample - foot| (- when the sample lies behind the surface) - reach. Wheels are
/// probed at their centre only: exact for an untilted wheel (centre on the contact normal).
/// Cost: the raster mesh of the whole part (F (m-1)^2 triangles) is built once per call.
///
/// @param part the part whose surface the contacts lie on (design or workpiece DDF), mm.
/// @throws InvalidInput for an empty program (or no point left after dropping moves), a point
/// with a non-finite position or a zero, non-finite axis or normal, a non-finite or non-rigid
/// transform, a zero default axis, contactSearchMm <= 0, a negative toolIndex, an invalid tool
/// (validateTool), a placement placeToolDetailed() refuses, or a Contact program point without
/// a normal when normalsFromPart is false ("needs normals"); the message names the point and
/// its source line. Cancelled through params.progress.
ImportedPath placeProgram(const ClProgram& program, const planning::Tool& tool,
                          const ddf::DisplacementField& part,
                          const PlaceProgramParams& params = {});

}  // namespace ddfcam::io
