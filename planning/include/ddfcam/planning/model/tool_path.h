// SPDX-License-Identifier: MIT
// ddfcam: a tool path as a sequence of tool poses with the contact points they were made for.
#pragma once

#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/planning/lines/streamline.h>

#include <Eigen/Geometry>

#include <cstddef>
#include <optional>
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
  /// The lines as traced on the part (unsmoothed), one per pass in cutting order, when the
  /// streamline planner made the path; empty otherwise (e.g. imported paths). They travel with
  /// the path (saved, undone, kept on renaming), so smoothing and fairing start from them and
  /// not from the placed contacts.
  std::vector<Streamline> rawLines{};
  /// Idle length of the linking the planner made (LinkedPaths::idleLengthMm, lifted links
  /// included), mm; empty when the path was not linked.
  std::optional<double> linkedIdleMm{};

  bool operator==(const ToolPath&) const = default;
};

/// @brief Heap bytes held by the raw lines of @p path, for memory accounting (undo limits).
inline std::size_t rawLinesBytes(const ToolPath& path) {
  std::size_t bytes = path.rawLines.capacity() * sizeof(Streamline);
  for (const Streamline& line : path.rawLines)
    bytes += line.points.capacity() * sizeof(ddf::SurfaceLocation);
  return bytes;
}

}  // namespace ddfcam::planning
