// SPDX-License-Identifier: MIT
// ddfcam: cutter-location programs from planned tool paths (poses, linked moves, a project).
#pragma once

#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/planning/model/project.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/planning/placement/cl_program.h>
#include <ddfcam/planning/placement/path_linking.h>
#include <ddfcam/planning/tools/tool.h>

#include <optional>
#include <string>
#include <vector>

namespace ddfcam::planning {

/// @brief The spindle (rotation) axis of a tool of kind @p kind in its own frame
/// (planning/tool.h): +x for wheels (CylinderRoll, BeltContactWheel) and Sphere, +z (tip to
/// holder) for cutters (BallEnd, FlatEnd, TorusCutter). A program's ClPoint::axis is
/// pose.linear() times this.
/// @throws InvalidInput for a value outside the enum.
ddf::Vec3 spindleAxisInToolFrame(ToolKind kind);

/// @brief APT's CUTTER record of a cutter: BallEnd (d = 2R, r = R, e = 0, f = R), FlatEnd
/// (d = 2R, r = 0, e = R, f = 0), TorusCutter (d = 2R, r = edge, e = R - edge, f = edge); alpha
/// = beta = 0, h = the cutting length (Tool::widthMm). std::nullopt for wheels and Sphere, which
/// APT's cutter model does not describe.
std::optional<ClCutter> clCutterOf(const Tool& tool);

/// @brief How the passes of a path are joined in a program.
struct ClLinkParams {
  /// Lift between passes along the surface normal, mm, >= 0 and finite (default 5).
  double clearanceMm = 5.0;
  /// Insert the lift (retract, rapid, approach) between passes; false: the passes follow each
  /// other directly, the first point of a pass being the end of a Cut move (default true).
  bool linkPasses = true;
};

/// @brief The unit surface normal (material -> tool side) at the contact of @p pose, derived
/// from the tool's geometry when no normals are known: for wheels and Sphere the direction
/// from the contact to the tool reference point (exact for poses made by placeTool() with tilt
/// 0: the wheel's centre lies on the normal); for BallEnd from the contact to the ball centre
/// (reference + radius along the axis); for TorusCutter from the contact to the nearest point
/// of the circle of corner centres, or the axis when the contact is under the flat bottom; for
/// FlatEnd the axis when the contact lies at the bottom (tip plane), else the direction from
/// the contact to the axis.
/// @throws InvalidInput if the direction is undefined (e.g. reference point on the contact of a
/// wheel), naming @p index.
ddf::Vec3 derivedContactNormal(const PathPose& pose, const Tool& tool, int index);

/// @brief The program of one tool path: one Cut point per pose at the path's feed, pass by
/// pass (ToolPath::passStarts; none: one pass), ClPoint::path = pass index, ClPoint::point
/// counting from 0 within that path. Positions: the contacts (Contact) or the pose
/// translations (ToolReference); axis = pose.linear() * spindleAxisInToolFrame(tool.kind);
/// normal = @p normals[i] or derivedContactNormal().
/// With link.linkPasses, before every pass but the first three points are inserted, all
/// belonging to the FOLLOWING pass (path index of that pass, numbered before its cut points):
/// Link (the retract: previous pass's last position + clearance x its normal, its axis and
/// normal, path feed), Rapid (the point clearance above the next pass's first position along
/// its normal, with that pose's axis and normal, feed 0) and Link (the approach, ending on the
/// next pass's first position, path feed). The first Cut point of the pass then repeats the
/// approach's end point (a zero-length move), so every pose gives exactly one Cut point.
/// toolNumber 1 (a project index is not known here), toolName = tool.name, cutter =
/// clCutterOf(tool), partName = path.name, pointKind = @p kind, sourceUnit mm.
/// @param normals #poses unit normals (tool side) or empty (derived).
/// @throws InvalidInput if @p normals has another size, a derived normal is undefined, or the
/// clearance is negative or not finite.
ClProgram clProgramFromPath(const ToolPath& path, const Tool& tool, ClPointKind kind,
                            const std::vector<ddf::Vec3>& normals = {},
                            const ClLinkParams& link = {});

/// @brief Appends the points of @p more to @p program: path indices shifted by
/// program.pathCount(), point indices renumbered within each path; with link.linkPasses and
/// both programs non-empty, a lift as in clProgramFromPath() (along the point's normal, else
/// its axis, else +z) joins @p program's last point to @p more's first, its three points
/// belonging to @p more's first path. Header data of @p more is ignored.
/// @throws InvalidInput if the clearance is negative or not finite.
void appendClProgram(ClProgram& program, const ClProgram& more, const ClLinkParams& link = {});

/// @brief The program of a linked path (linkPaths() of the passes of @p path): one
/// block per move of @p linked, in order, ClPoint::path = move index, ClPoint::point counting
/// within the move. A Cut move takes the poses of pass move.path of @p path (reversed if
/// move.reversed); its points must be that pass's contacts. Link and Rapid moves give their
/// points (the start point included, as the move's polyline) as contact-level points carrying
/// the axis, normal and contact -> reference offset of the last pose of the preceding Cut (the
/// tool keeps that orientation while it travels); feed: the path's for Cut and Link, 0 for
/// Rapid. Axis as clProgramFromPath() (the spindle axis of @p tool's kind).
/// @param normals #poses unit normals (tool side) of @p path, or empty (derived as in
/// clProgramFromPath()).
/// @throws InvalidInput if a Cut refers to a missing pass, its points do not match the pass's
/// contacts (count or value, 1e-9 mm), the first move is not a Cut, or @p normals has another
/// size.
ClProgram clProgramFromLinked(const LinkedPaths& linked, const ToolPath& path, const Tool& tool,
                              ClPointKind kind, const std::vector<ddf::Vec3>& normals = {});

/// @brief What programsForExport() takes from a project and how it groups it.
struct ExportSelection {
  ClPointKind pointKind = ClPointKind::ToolReference;  ///< positions given (default tool ref.)
  /// One program per region (true) or all selected paths in one program (default false).
  bool perRegion = false;
  /// Indices into Project::regions whose paths are exported; empty = all regions and the paths
  /// in no region (default empty).
  std::vector<int> regions{};
  /// Indices into Project::paths to export; empty = all (default empty).
  std::vector<int> paths{};
  ClLinkParams link{};  ///< lifts between passes and between paths (default ClLinkParams{})
};

/// @brief A program with the name it is exported under (a file suffix, a PARTNO).
struct NamedProgram {
  std::string name;   ///< project part name, region name, "unassigned"; may carry " T<n>"
  ClProgram program;  ///< the program
};

/// @brief The programs of a project's selected paths. A path is selected when it is listed in
/// selection.paths (or that is empty) and its region (pathRegions() on the part; -1
/// when the project has no part) is listed in selection.regions (or that is empty: then paths
/// in no region are selected too). Grouping: one group of all selected paths named after the
/// project's part name ("paths" if empty), or with perRegion one group per region holding a
/// selected path (named after the region, in region order) and one named "unassigned" for the
/// selected paths in no region. A group whose paths use several tools is split per tool (in
/// order of first use), each named "<group> T<tool index + 1>". Each program: the paths of the
/// group in project order, each as clProgramFromPath() with its own tool
/// (Project::tools[path.tool]), its feed and selection.link, appended with consecutive path
/// indices (a lift as between passes joins consecutive paths too); toolNumber = tool index +
/// 1, toolName = the tool's name, cutter = clCutterOf(tool), partName = the group name. Normals:
/// the part's smooth surface normal (smoothSurfaceNormal()) where the contact is found on
/// the part (ddf::SurfaceLocator), else derivedContactNormal(). Paths without poses are left out;
/// groups without points give no program.
/// @throws InvalidInput for an index out of range (naming it), a path whose tool index is
/// invalid, or as clProgramFromPath().
std::vector<NamedProgram> programsForExport(const Project& project,
                                            const ExportSelection& selection);

}  // namespace ddfcam::planning
