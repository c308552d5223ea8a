// SPDX-License-Identifier: MIT
// ddfcam: APT cutter records of planning tools, and the planning tool a cutter record describes.
#pragma once

#include <ddfcam/planning/placement/cl_program.h>
#include <ddfcam/planning/tools/tool.h>

#include <string>

namespace ddfcam::planning {

/// @brief The 7-parameter APT cutter CUTTER/d,r,e,f,alpha,beta,h of @p tool (mm, degrees),
/// with d = 2 R, r the corner radius, e = R - r, f = r, alpha = beta = 0:
/// - BallEnd: r = R (e = 0, f = R), h = flute length (width);
/// - FlatEnd: r = 0 (e = R, f = 0), h = width;
/// - TorusCutter: r = corner (edgeRadiusMm), e = R - r, f = r, h = width;
/// - Sphere: a ball, r = R, e = 0, f = R, h = 2 R (note: its reference point is the centre);
/// - CylinderRoll, BeltContactWheel: the wheel as a disc cutter, r = rim radius
///   (edgeRadiusMm), e = R - r, f = r, h = width (its axis is tool +x, not the APT +z).
/// @throws InvalidInput if the tool fails validateTool().
ClCutter aptCutter(const Tool& tool);

/// @brief The planning tool for an APT @p cutter (the inverse of aptCutter()) (mm): a ball-end when
/// the corner radius is the radius (within 1e-6 of it), a flat-end when it is 0, else a torus
/// cutter with that corner radius; flute length h (2 d if h is 0). Frames as planning/tool.h (tip
/// at the origin, axis +z), so APT's CL point is the tool reference point.
/// @param name tool name; empty gives "imported cutter".
/// @throws InvalidInput if the cutter gives no usable tool (diameter <= 0, a negative corner
/// radius or one larger than the radius, or a tool validateTool() refuses).
Tool toolFromCutter(const ClCutter& cutter, const std::string& name);

}  // namespace ddfcam::planning
