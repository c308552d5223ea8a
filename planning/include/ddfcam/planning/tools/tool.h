// SPDX-License-Identifier: MIT
// ddfcam: a grinding or milling tool as the workbench stores it (shape parameters) and the
// closed meshes of its cutting and non-cutting parts.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>

#include <optional>
#include <string>
#include <string_view>

namespace ddfcam::planning {

/// @brief Shapes of tools the workbench knows. Tool frames (the pose of a ToolPath maps the
/// tool frame to the part frame; its origin is the tool reference point):
/// - wheels (CylinderRoll, BeltContactWheel): rotation axis along tool +x, centred at the
///   origin (the centre of the wheel's mid plane);
/// - Sphere: a bare ball centred at the origin (kept for projects of format 2);
/// - cutters (BallEnd, FlatEnd, TorusCutter): axis along tool +z pointing from the tip to the
///   holder, the tip (lowest point on the axis) at the origin, as APT's CL point.
enum class ToolKind {
  CylinderRoll = 0,      ///< grinding roll or disc: radius, width, edge radius, crown radius
  Sphere = 1,            ///< bare ball (ball head without shank), centred at the origin
  BeltContactWheel = 2,  ///< belt grinder's contact wheel; radius includes the belt
  BallEnd = 3,           ///< ball-end cutter: radius = ball radius
  FlatEnd = 4,           ///< flat-end cutter: radius = cutter radius
  TorusCutter = 5,       ///< bull-nose cutter: radius = cutter radius, edgeRadiusMm = corner
};

/// @brief A named tool: its shape and size, all lengths in mm. Meshes are derived
/// (toolMesh(), toolMeshes()). Initialise it with designated initialisers: the positional
/// form of format 2 ({name, kind, radius, width, segments}) now puts the count into
/// edgeRadiusMm.
struct Tool {
  std::string name = "roll R5 W10";        ///< shown in lists and files (default "roll R5 W10")
  ToolKind kind = ToolKind::CylinderRoll;  ///< shape (default cylindrical roll)
  double radiusMm = 5.0;  ///< wheel radius, ball radius or cutter radius, mm (default 5)
  /// Wheels: width along the axis. Cutters: length of the cutting part (flutes) from the tip
  /// along +z. Unused for Sphere. Default 10.
  double widthMm = 10.0;
  /// Wheels: radius rounding the two rims (0 = sharp). TorusCutter: corner radius
  /// (0 < edge < radius). Default 0.
  double edgeRadiusMm = 0.0;
  /// Wheels: radius of the convex crown of the mantle across the width (0 = straight
  /// cylinder; must be >= width / 2). Default 0.
  double crownRadiusMm = 0.0;
  /// Non-cutting part. Wheels: arbor radius (shaft along the axis on both sides). Cutters:
  /// shank radius. 0 = no shaft or shank. Default 0.
  double shankRadiusMm = 0.0;
  /// Wheels: arbor length beyond each side face. Cutters: shank length above the cutting
  /// part. Default 0.
  double shankLengthMm = 0.0;
  /// Non-cutting part. Wheels: flange radius (a disc against each side face; < radius).
  /// Cutters: holder radius (a cylinder above the shank). 0 = none. Default 0.
  double holderRadiusMm = 0.0;
  /// Wheels: flange thickness. Cutters: holder length. Default 0.
  double holderLengthMm = 0.0;
  /// Largest distance between the mesh and the true tool surface, mm (default 0.005). Sets
  /// the facet count when segments is 0.
  double chordToleranceMm = 0.005;
  /// Facets around the circumference; 0 = chosen from chordToleranceMm (see toolMesh(); a
  /// multiple of 4, so mesh vertices lie on the lowest line of a wheel, as with any explicit
  /// multiple of 4). Default 48 (format-2 projects stored a count).
  int segments = 48;

  bool operator==(const Tool&) const = default;
};

/// @brief The cutting and non-cutting parts of a tool, each closed and outward oriented, in
/// the tool frame (see ToolKind).
struct ToolMeshes {
  ddf::TriangleMesh cutting;     ///< the part that removes material
  ddf::TriangleMesh nonCutting;  ///< shank, holder, arbor, flanges; empty if none
};

/// @brief The snake_case key of @p kind used in files and on the command line:
/// "cylinder_roll", "sphere", "belt_contact_wheel", "ball_end", "flat_end", "torus_cutter";
/// "unknown" for a value outside the enum.
std::string_view toolKindName(ToolKind kind);

/// @brief The kind whose toolKindName() is @p name; std::nullopt for any other text.
std::optional<ToolKind> toolKindFromName(std::string_view name);

/// @brief Checks that @p tool describes a buildable shape: a known kind; finite sizes;
/// radius > 0; width > 0 (not for Sphere); wheels: 0 <= edge <= width / 2, crown 0 or
/// >= width / 2 and > edge, both rims' side faces still reach the axis region (the fillet
/// starts above the axis), flange radius < radius; BallEnd: width >= radius; TorusCutter:
/// 0 < edge < radius, width >= edge; non-cutting sizes >= 0; chord tolerance > 0 (and, with
/// segments 0, reachable with at most 4096 segments); segments 0 or 3..4096 (Sphere: 0 or
/// 4..4096). Fields a kind does not use are not checked beyond being finite.
/// @throws InvalidInput naming the tool and the offending field.
void validateTool(const Tool& tool);

/// @brief The closed cutting mesh of @p tool in its own frame, for the depth buffer and for
/// display: toolProfile() (tool_profiles.h) revolved by revolveProfile(). Every vertex lies on
/// the true surface (the mesh is inscribed); with segments 0 every facet lies within
/// chordToleranceMm of it. Facets around: segments, or with segments 0
/// segmentsForChordTolerance(largest radius, tolerance / 2); profile arcs: pieces of at most 2 pi /
/// segments of turn with segments > 0, else of sagitta <= tolerance / 2. A plain roll (edge 0,
/// crown 0) has 4 segments triangles. Sphere with segments > 0 is makeSphereTool(radius, segments /
/// 2, segments) (2 segments (segments / 2 - 1) triangles), as format-2 projects expect.
/// @throws InvalidInput as validateTool().
ddf::TriangleMesh toolMesh(const Tool& tool);

/// @brief Both parts of @p tool (cutting as toolMesh(); non-cutting from the shank, holder,
/// arbor and flange fields: nonCuttingProfiles() revolved, each connected solid a closed
/// component of the one mesh, at the same facet rules, facets around capped at 4096). The two
/// parts touch but do not overlap: wheels' non-cutting parts lie at |x| >= width / 2,
/// cutters' at z >= width.
/// @throws InvalidInput as validateTool().
ToolMeshes toolMeshes(const Tool& tool);

}  // namespace ddfcam::planning
