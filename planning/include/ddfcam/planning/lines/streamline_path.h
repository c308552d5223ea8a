// SPDX-License-Identifier: MIT
// ddfcam: turning streamlines on a DDF into tool paths (contacts and tool poses).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/planning/placement/path_sampling.h>
#include <ddfcam/planning/placement/tool_orientation.h>
#include <ddfcam/planning/tools/tool.h>

#include <optional>
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
  /// Infeed below the contact along the normal, mm, added to placement.depthMm (kept for the
  /// callers that predate placement) (default 0).
  double depthMm = 0.0;
  double feedMmPerMin = 1000.0;  ///< feed rate, mm/min (default 1000)
  /// Lead, tilt and infeed of the tool at every contact (placeTool()) (default: lead 0, tilt 0,
  /// depth 0: the tool touches with its axis on the normal, wheels across the feed).
  PlacementParams placement{};
  /// Set: every streamline is resampled along the feed at the step derived from the tolerance
  /// (or the override) by placeAlongPath() (path_sampling.h; uniform step per pass plus the
  /// eq. 5.8 poses, normals from smoothSurfaceNormal(); its name and feed fields are replaced
  /// by name and feedMmPerMin above). Not set: one pose at every streamline point, normal from
  /// surfaceNormal() (default not set).
  std::optional<PathSamplingParams> sampling{};
};

/// @brief A tool path with one pass per streamline (in the given order, each traced from its
/// first point). Without params.sampling the contacts are the streamline points; with it the
/// contacts are resampled along each streamline (see StreamlinePathParams::sampling). At each
/// contact placeTool() puts @p tool (any ToolKind) on the tangent plane with the feed along the
/// streamline and params.placement (depth: placement.depthMm + params.depthMm), e.g. a roll
/// centred R - depth above the contact with its axis across the feed, a Sphere centred R - depth
/// above it. Streamlines with fewer than two points (or zero length when sampled) are left out.
/// @param toolIndex index of @p tool in the project's tool list (ToolPath::tool).
/// @throws InvalidInput for an invalid tool, bad placement or sampling parameters (as
/// placeTool() / placeAlongPath()), or if no streamline has two points.
ToolPath toolPathFromStreamlines(const ddf::DisplacementField& ddf,
                                 const std::vector<Streamline>& streamlines, const Tool& tool,
                                 int toolIndex, const StreamlinePathParams& params = {});

/// @brief As toolPathFromStreamlines(), with how each pass was sampled (PlacedPath::passes is
/// empty when params.sampling is not set).
/// @throws InvalidInput as toolPathFromStreamlines().
PlacedPath toolPathFromStreamlinesDetailed(const ddf::DisplacementField& ddf,
                                           const std::vector<Streamline>& streamlines,
                                           const Tool& tool, int toolIndex,
                                           const StreamlinePathParams& params = {});

/// @brief The unit surface normal (material -> tool) that placeTool() used for @p pose, made
/// for @p tool with @p placement (only its angles matter), recovered from the pose's rotation:
/// the contact frame (t, b, n) is the pose rotation with lead and tilt undone.
/// @throws InvalidInput for |lead| or |tilt| >= 90 deg or non-finite angles.
ddf::Vec3 placedNormal(const Tool& tool, const Eigen::Isometry3d& pose,
                       const PlacementParams& placement);

}  // namespace ddfcam::planning
