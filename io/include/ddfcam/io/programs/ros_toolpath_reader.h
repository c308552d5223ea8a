// SPDX-License-Identifier: MIT
// ddfcam: reading ROS-Industrial tool paths saved as YAML (paths of geometry_msgs poses).
#pragma once

#include <ddfcam/planning/placement/cl_program.h>

#include <filesystem>
#include <string>
#include <string_view>

namespace ddfcam::io {

/// @brief Parses a ROS toolpath YAML document, as ROS-Industrial planners (noether, the
/// collaborative robotic sanding application) save them: one or more entries with `paths:`,
/// each path a mapping with an optional `header:` and a `poses:` list of geometry_msgs/Pose
/// (`position: {x, y, z}` in metres, `orientation: {x, y, z, w}` quaternion). The root may
/// also be a single mapping with `paths:`. Keys may come in any order; other keys (header,
/// process parameters) are ignored.
///
/// Every non-empty `poses` list becomes one path (ClPoint::path counts them from 0 in file
/// order); an empty list is skipped with a warning. Points: position * 1000 (mm), tool axis =
/// the normalised quaternion applied to +Z (the pose's z axis, as robot tool frames point it),
/// ClPointKind::ToolReference, MoveKind::Cut, feed 0 (the file gives none), sourceLine = line
/// of the pose. The program's sourceUnit is Metre; the first header's `frame_id` is kept as a
/// comment. A quaternion whose length differs from 1 by more than 1e-3 is normalised with a
/// warning.
///
/// Only the block-YAML subset such files use is accepted (see io/src/programs/yaml_subset.h): no
/// anchors, tags, block scalars or multi-line scalars; nesting up to 64 levels and up to 2 M
/// YAML nodes (about 200 k poses).
/// @param sourceName file name used in messages.
/// @throws IoError "<sourceName>: line N: <what>" for YAML outside the subset, a missing
/// `paths`/`poses`/`position`/`orientation` or coordinate, a non-number, a zero quaternion, a
/// coordinate beyond +-1e12 mm after the conversion from metres,
/// and "<sourceName>: ..." for a document without any pose.
planning::ClProgram decodeRosToolpathYaml(std::string_view text, const std::string& sourceName);

/// @brief Reads a ROS toolpath YAML file (see decodeRosToolpathYaml). The program's partName
/// is the file's stem.
/// @throws IoError if the file is missing, unreadable, larger than 1 GiB, or as
/// decodeRosToolpathYaml.
planning::ClProgram readRosToolpathYaml(const std::filesystem::path& file);

}  // namespace ddfcam::io
