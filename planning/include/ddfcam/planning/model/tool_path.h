// SPDX-License-Identifier: MIT
// ddfcam: a tool path as a sequence of tool poses with the contact points they were made for.
#pragma once

#include <ddfcam/ddf/support_mesh.h>

#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace ddfcam::planning {

/// @brief One tool placement along a path.
struct PathPose {
  /// Tool frame -> part frame (mm); the tool mesh of Tool is given in the tool frame.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  /// Point where the tool is meant to touch the design surface, mm, part frame.
  ddf::Vec3 contact = ddf::Vec3::Zero();

  bool operator==(const PathPose& o) const {
    return pose.matrix() == o.pose.matrix() && contact == o.contact;
  }
};

/// @brief A named tool path: poses in machining order, grouped into passes.
struct ToolPath {
  std::string name;               ///< shown in lists and files
  int tool = 0;                   ///< index into Project::tools (default 0)
  double feedMmPerMin = 1000.0;   ///< feed rate, mm/min (default 1000)
  std::vector<PathPose> poses{};  ///< #P poses in machining order
  /// Index of the first pose of every pass, ascending, first entry 0 when poses exist; the
  /// tool is lifted between passes, so overlays draw each pass as its own polyline.
  std::vector<int> passStarts{};

  bool operator==(const ToolPath&) const = default;
};

}  // namespace ddfcam::planning
