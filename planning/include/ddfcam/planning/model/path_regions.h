// SPDX-License-Identifier: MIT
// ddfcam: which region of the part each tool path machines (for per-region exports).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/model/project.h>
#include <ddfcam/planning/model/tool_path.h>

#include <vector>

namespace ddfcam::planning {

/// @brief The region of each path: the region whose faces hold the most of the path's contacts
/// (PathPose::contact located on @p part by ddf::SurfaceLocator: the support face whose
/// V-projection of the contact lies nearest to it). Ties go to the lower region index; a
/// contact that cannot be located or lies on a face of no region counts for no region.
/// @param regions regions of @p part (faces in range); a face listed by several regions counts
/// for the first.
/// @return #paths region indices, -1 for a path with no contact in any region (or no poses).
/// @throws InvalidInput if a region lists a face outside the part (naming the region).
std::vector<int> pathRegions(const ddf::DisplacementField& part, const std::vector<Region>& regions,
                             const std::vector<ToolPath>& paths);

}  // namespace ddfcam::planning
