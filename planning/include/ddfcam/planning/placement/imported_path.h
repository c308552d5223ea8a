// SPDX-License-Identifier: MIT
// ddfcam: placing a cutter-location program read from a file on a part as a ToolPath.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/planning/placement/cl_program.h>
#include <ddfcam/planning/placement/tool_orientation.h>
#include <ddfcam/planning/tools/tool.h>
#include <ddfcam/progress.h>

#include <Eigen/Geometry>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::planning {

/// @brief What the vectors of a program (ClPoint::axis: APT's GOTO i,j,k, a CSV's i,j,k or
/// axis columns, a robot pose's z axis) stand for. Robot programs often give the approach
/// direction, CAM programs the tool axis; read the wrong way, the tool stands inside the part.
enum class PathVectorMeaning {
  Auto,               ///< decided from the part: pointing into it, approach; else tool axis
  ToolAxis,           ///< spindle axis, cutters from the tip to the holder (APT); wheels' axis
  ApproachDirection,  ///< the way the tool moves onto the part, from the holder through the
                      ///< tip into it: cutters take the reversed vector as their axis, wheels
                      ///< and balls the reversed vector as the surface normal
  SurfaceNormal       ///< surface normal at the contact, part to tool: the tool stands along it
};

/// @brief What the positions of a program stand for, overriding ClProgram::pointKind.
enum class PathPointMeaning {
  Declared,       ///< ClProgram::pointKind as the reader found or assumed it
  Auto,           ///< decided from the part: on its surface, contacts; a tool reference
                  ///< height off it (wheel or ball centres), tool reference points
  Contact,        ///< ClPointKind::Contact: points on the surface the tool touches
  ToolReference,  ///< ClPointKind::ToolReference: cutter tips, wheel and ball centres
};

/// @brief Short name of @p meaning as options and reports write it: "auto", "axis",
/// "approach" or "normal".
std::string_view pathVectorMeaningName(PathVectorMeaning meaning);
/// @brief Short name of @p meaning: "file", "auto", "contact" or "tip".
std::string_view pathPointMeaningName(PathPointMeaning meaning);
/// @brief The meaning named @p name by pathVectorMeaningName(); empty for another name.
std::optional<PathVectorMeaning> pathVectorMeaningFromName(std::string_view name);
/// @brief The meaning named @p name by pathPointMeaningName(); empty for another name.
std::optional<PathPointMeaning> pathPointMeaningFromName(std::string_view name);

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
  /// Index of the tool in the project (ToolPath::tool) (default 0).
  int toolIndex = 0;
  /// A pose whose tool lies farther than this from the part surface (gap or penetration) is
  /// counted as off the part, mm, > 0 (default 2).
  double contactSearchMm = 2.0;
  /// Contact programs: lead and tilt angles derived from a point's axis and normal that are
  /// smaller than this are taken as 0, deg, >= 0 (default 0.1). A flat bottom or a straight
  /// wheel mantle touches with its rim at any non-zero angle, so rounding noise in the file's
  /// axes and normals would otherwise move the tool by a radius or half its width.
  double angleSnapDeg = 0.1;
  /// Contact programs: place the tool at every point with these lead and tilt angles instead
  /// of the angles its axis gives (wheels still feed across their axis; cutters stand along
  /// the normal, leaned by these). Empty: the file's axes decide (default empty).
  std::optional<PlacementParams> contactAngles{};
  /// What the program's vectors stand for (default ToolAxis, as APT defines its i,j,k).
  PathVectorMeaning vectorMeaning = PathVectorMeaning::ToolAxis;
  /// What the program's positions stand for (default Declared: ClProgram::pointKind).
  PathPointMeaning pointMeaning = PathPointMeaning::Declared;
  /// A pose whose tool reaches deeper than this into the part, or a cutter whose axis points
  /// into it, is counted as gouging and warned about, mm, > 0 (default 0.2: above a grinding
  /// infeed, below the millimetres a reversed vector costs).
  double gougeWarnMm = 0.2;
  /// Progress in [0, 1] over the points and cancellation (default none).
  ProgressCallback progress{};
};

/// @brief The meanings placeProgram() used, and what the part said about them. Evidence comes
/// from up to 512 cut points spread over the program, each with its nearest point on the part
/// (smooth normal n there, signed distance s of the point, + on the tool side).
struct PathConvention {
  PathVectorMeaning vectors = PathVectorMeaning::ToolAxis;  ///< meaning used (never Auto)
  ClPointKind points = ClPointKind::ToolReference;          ///< kind used
  bool vectorsDetected = false;  ///< vectors decided by Auto (else given or nothing to decide)
  bool pointsDetected = false;   ///< points decided by Auto
  /// Cut points examined over the part. Those beside its border, whose nearest normal tells
  /// nothing about their side, or farther from it than h + contactSearchMm + the tool's radius
  /// and width are left out; with fewer than one in four over the part nothing is decided (a
  /// path in another frame or unit).
  int sampled = 0;
  int leftOut = 0;     ///< cut points examined and left out: beside the part's border or far off
  int vectorsOut = 0;  ///< of them, vectors pointing out of the part (v.n > 0.5)
  int vectorsIn = 0;   ///< vectors pointing into it (v.n < -0.5)
  int pointsOnSurface = 0;    ///< points nearer to the surface than to the reference height
  int pointsAtReference = 0;  ///< points nearer to the reference height h (see below)
  /// Height of the tool reference point above the contact for a tool standing along the
  /// normal, mm: wheels' and balls' radius, 0 for cutters (their tip touches: contact and tip
  /// cannot be told apart, and the declared kind is kept).
  double referenceHeightMm = 0.0;
  double medianPointDistanceMm = 0.0;  ///< median s of the sampled points, mm
  /// One line on what was used and why, e.g. "vectors: approach directions (detected: they
  /// point into the part at 98 of 98 sampled points)".
  std::string reason;
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
  ToolPath path;
  /// #P unit surface normals at the contacts, part frame, towards the tool.
  std::vector<ddf::Vec3> normals;
  /// #P distance from the tool to the part surface, mm: > 0 a gap, < 0 the depth the tool
  /// reaches into the surface (see placeProgram()).
  std::vector<double> contactDistancesMm;
  /// #P index into ClProgram::points of the point each pose was made from.
  std::vector<int> sourcePoints;
  /// Poses with |contact distance| > contactSearchMm (off the part, or far from it).
  int pointsOffPart = 0;
  /// Largest |contact distance| over all poses, mm (those off the part included).
  double maxAbsContactDistanceMm = 0.0;
  /// Largest |contact distance| over the poses on the part, mm; empty if none is on it.
  std::optional<double> maxOnPartContactDistanceMm;
  /// Poses over the part (not beside its border) reaching deeper than gougeWarnMm into it, or
  /// (cutters) whose spindle axis points into it (axis . normal < 0 at the contact).
  int gougingPoses = 0;
  /// Deepest reach into the part over the poses over it, mm, >= 0 (0: none penetrates).
  double maxGougeDepthMm = 0.0;
  /// The vector and point meanings used, detected or given, and the evidence.
  PathConvention convention;
  /// What placing noticed (off-part points, gouges, vectors or points that look different from
  /// what they were taken for, missing feed, dropped moves), with source lines.
  std::vector<ClMessage> warnings;
};

/// @brief Places @p program on @p part for @p tool.
///
/// Positions are rescaled (params.actualUnit) and transformed (params.transform) into the part
/// frame. Vectors and positions are then read as params.vectorMeaning and params.pointMeaning
/// say (Auto: decided from the part, see PathConvention; ties keep ToolAxis and the declared
/// kind): ToolAxis keeps ClPoint::axis; ApproachDirection reverses it (cutters) or makes
/// its reverse the point's normal, without axis (wheels, Sphere); SurfaceNormal makes it the
/// normal, without axis. A ToolReference program left with normals and no axes becomes a
/// Contact one: contact = point - the reference offset of placeToolDetailed() at
/// the normal (lead and tilt 0), feeding as below. Every kept point gives a tool reference point r
/// and a unit spindle axis a, both in the part frame:
/// - ToolReference programs: r = the point, a = its axis, else params.defaultAxis.
/// - Contact programs: r = the point + the offset of placeToolDetailed() at the
///   point's normal n (the file's, or the part's with normalsFromPart) feeding towards the next
///   point of the pass (the previous one at its end). With an axis a in the file, cutters take
///   lead = asin(a.t) and tilt = atan2(-a.b, a.n) (t the unit tangential feed, b = n x t), so
///   their axis is a (angles below angleSnapDeg taken as 0); wheels feed across the axis's
///   tangential part with tilt = asin(a.n); Sphere ignores it. Without one, cutters stand along n
///   and wheels lie across the feed in the tangent plane (lead and tilt 0); params.defaultAxis is
///   not used. params.contactAngles, if given, replace the lead and tilt (not a wheel's feed).
/// The pose maps the tool's spindle axis (tool +x for wheels and Sphere, +z for cutters) onto
/// a and its origin onto r; the turn about the axis is carried from point to point by the
/// smallest rotation (continuous and deterministic; revolved tools do not depend on it).
///
/// Contact of a pose: of the tool's core samples (Sphere and wheels: their centre, reach =
/// radius; BallEnd: its ball centre, reach = radius; FlatEnd: its tip and 16 points of its
/// bottom rim, reach 0; TorusCutter: its tip, reach 0, and 16 points of the circle of corner
/// centres, reach = corner radius) the one whose distance to the part's raster mesh
/// (ddf::extractRasterMesh, MeshDistance) minus its reach is smallest (earlier
/// samples win ties); its foot is then moved onto the point of the smooth surface where the
/// sample lies along smoothSurfaceNormal() (a few fixed-point steps), which removes
/// the sideways shift the facets' normal jumps would cause. Contact = that foot, normal = the
/// smooth normal there (towards the side the DDF vectors point to, the tool side), distance =
/// +-|sample - foot| (- when the sample lies behind the surface) - reach. Wheels are
/// probed at their centre only: exact for an untilted wheel (centre on the contact normal).
/// Warnings: gouging poses (count and deepest), vectors or points the part shows to be
/// something else than what they were taken for (a clear 2:1 majority of the sampled points),
/// poses off the part.
/// Cost: the raster mesh of the whole part (F (m-1)^2 triangles) is built once per call.
///
/// @param part the part whose surface the contacts lie on (design or workpiece DDF), mm.
/// @throws InvalidInput for an empty program (or no point left after dropping moves), a point
/// with a non-finite position or a zero, non-finite axis or normal, a non-finite or non-rigid
/// transform, a zero default axis, contactSearchMm or gougeWarnMm <= 0, a negative toolIndex, an
/// invalid tool (validateTool), a placement placeToolDetailed() refuses, or a Contact program point
/// without a normal when normalsFromPart is false ("needs normals"); the message names the point
/// and its source line. Cancelled through params.progress.
ImportedPath placeProgram(const ClProgram& program, const Tool& tool,
                          const ddf::DisplacementField& part,
                          const PlaceProgramParams& params = {});

}  // namespace ddfcam::planning
