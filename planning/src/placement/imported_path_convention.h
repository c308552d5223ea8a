// SPDX-License-Identifier: MIT
// ddfcam: what an imported program's vectors and points stand for (tool axis, approach
// direction or surface normal; contact or tool reference point), detected from the part.
#pragma once

#include <ddfcam/planning/placement/imported_path.h>

#include "imported_path_contacts.h"

#include <optional>
#include <string>
#include <vector>

namespace ddfcam::planning::detail {

/// @brief A kept program point in the part frame.
struct PlacedPoint {
  int source = 0;                          ///< index into ClProgram::points
  bool passStart = false;                  ///< a pass starts here
  bool cut = true;                         ///< a Cut move (links and rapids give no evidence)
  ddf::Vec3 position = ddf::Vec3::Zero();  ///< mm
  std::optional<ddf::Vec3> axis;           ///< unit
  std::optional<ddf::Vec3> normal;         ///< unit
};

/// @brief The world axis least aligned with unit @p a made perpendicular to it (ties prefer
/// z, then x).
ddf::Vec3 perpendicularTo(const ddf::Vec3& a);

/// @brief Unit tangential part of @p feed at unit normal @p n, else of @p hint, else
/// perpendicularTo(n).
ddf::Vec3 tangentialFeed(const ddf::Vec3& feed, const ddf::Vec3& n, const ddf::Vec3& hint);

/// @brief Feed direction at kept point @p k: towards the next point of its pass, else from the
/// previous one; zero for a pass of one point.
ddf::Vec3 feedAt(const std::vector<PlacedPoint>& pts, std::size_t k);

/// @brief True for the wheel kinds (CylinderRoll, BeltContactWheel).
bool isWheel(ToolKind kind);
/// @brief True for the cutter kinds (BallEnd, FlatEnd, TorusCutter).
bool isCutter(ToolKind kind);

/// @brief The meanings of params.vectorMeaning and params.pointMeaning (Auto and Declared
/// resolved from the part and @p declared), with the evidence and a reason. Appends a warning
/// to @p warnings for every given meaning the evidence contradicts.
PathConvention resolveConvention(const PartSurface& surface, const std::vector<PlacedPoint>& pts,
                                 const Tool& tool, ClPointKind declared,
                                 const PlaceProgramParams& params,
                                 std::vector<ClMessage>& warnings);

/// @brief Rewrites @p pts as @p convention says (see placeProgram()).
/// @return the kind the points are to be placed as.
/// @throws InvalidInput (nested: placeToolDetailed()'s) naming the program point if
/// a reference point cannot be turned into a contact.
ClPointKind applyConvention(const PathConvention& convention, const Tool& tool,
                            const PartSurface& surface, std::vector<PlacedPoint>& pts);

/// @brief Text for @p convention's meanings, e.g. "vectors read as approach directions, points
/// as contacts".
std::string conventionSummary(const PathConvention& convention);

}  // namespace ddfcam::planning::detail
