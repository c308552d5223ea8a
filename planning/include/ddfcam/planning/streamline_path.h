// SPDX-License-Identifier: MIT
// ddfcam: turning streamlines on a DDF into tool paths (contacts and tool poses).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/planning/streamline.h>
#include <ddfcam/planning/tool.h>
#include <ddfcam/planning/tool_path.h>

#include <string>
#include <vector>

namespace ddfcam::planning {

/// @brief Unit normal of the represented surface at @p location, pointing to the tool side (the
/// side the displacement vectors point to): the normal of the raster triangle (fig. 7.1a) that
/// contains the location, the surface ddf::interpolateOnFace interpolates over.
/// @throws InvalidInput if the location's face is out of range.
ddf::Vec3 surfaceNormal(const ddf::DisplacementField& ddf, const ddf::SurfaceLocation& location);

/// @brief Parameters of toolPathFromStreamlines().
struct StreamlinePathParams {
  std::string name = "streamlines";  ///< name of the path (default "streamlines")
  double depthMm = 0.0;              ///< infeed below the contact along the normal, mm (default 0)
  double feedMmPerMin = 1000.0;      ///< feed rate, mm/min (default 1000)
};

/// @brief A tool path with one pass per streamline (in the given order, each traced from its
/// first point): contacts are the streamline points; the tool touches the surface there with
/// the feed along the streamline (a roll by rollPoseAtContact, a ball centred R - depth above
/// the contact along the normal, tool frame not rotated). Streamlines with fewer than two
/// points are left out.
/// @param toolIndex index of @p tool in the project's tool list (ToolPath::tool).
/// @throws InvalidInput for an invalid tool, or if no streamline has two points.
ToolPath toolPathFromStreamlines(const ddf::DisplacementField& ddf,
                                 const std::vector<Streamline>& streamlines, const Tool& tool,
                                 int toolIndex, const StreamlinePathParams& params = {});

}  // namespace ddfcam::planning
