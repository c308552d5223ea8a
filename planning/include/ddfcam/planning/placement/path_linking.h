// SPDX-License-Identifier: MIT
// ddfcam: ordering the paths of a region and linking them (zig-zag or one direction).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/model/region_plan.h>

#include <vector>

namespace ddfcam::planning {

/// @brief Options of linkPaths().
struct LinkingParams {
  /// Order and direction of the paths (default ZigZag).
  LinkingOrder order = LinkingOrder::ZigZag;
  /// Feed direction along the paths, part frame, any length; zero picks the dominant direction
  /// of the paths' chords (end - start, sign-free principal axis, largest component made
  /// positive) (default zero).
  ddf::Vec3 feedDirection = ddf::Vec3::Zero();
  /// +1 or -1: cut along feedDirection or against it (RegionPlan::feedSign) (default +1). With
  /// ZigZag it orients the first path only.
  int feedSign = 1;
  /// Links whose gap (straight distance from a path's end to the next start) is at most this
  /// are one straight Link move on the surface; longer ones lift. A straight link dips below a
  /// convex surface by about kappa gap^2 / 8, so keep this small there. mm, >= 0 (default 0:
  /// every link lifts).
  double directLinkMaxMm = 0.0;
  /// Lift of a lifted link: retract by this along the normal at the end (Link), straight
  /// traverse to the point this far above the next start (Rapid), approach (Link); mm, >= 0
  /// (default 1).
  double clearanceMm = 1.0;
  /// Retract direction when no normals are given (tool side), part frame, non-zero (default +z).
  ddf::Vec3 retractDirection = ddf::Vec3::UnitZ();
};

/// @brief Kind of a move of a linked tool path, for labelling (e.g. a CSV column).
enum class MoveKind {
  Cut,   ///< along a path, in contact
  Link,  ///< a direct link, or the retract / approach of a lifted one (at feed)
  Rapid  ///< the traverse of a lifted link at clearance
};

/// @brief One move: a polyline of at least two points.
struct PathMove {
  MoveKind kind = MoveKind::Cut;  ///< what the move does
  std::vector<ddf::Vec3> points;  ///< #P >= 2 points, mm, part frame
  int path = -1;                  ///< index of the input path of a Cut, else -1
  bool reversed = false;          ///< a Cut runs against the input path's point order
};

/// @brief Paths in machining order with their links, and the report of sec. 8.3.
struct LinkedPaths {
  /// Moves in order: Cut, then per following path its link moves and its Cut.
  std::vector<PathMove> moves;
  std::vector<int> order;        ///< input path index of each Cut, in machining order
  double cuttingLengthMm = 0.0;  ///< total length of the Cut moves, mm
  double idleLengthMm = 0.0;     ///< total length of the Link and Rapid moves, mm
  int pathCount = 0;             ///< number of Cut moves
  int linkCount = 0;             ///< number of transitions between paths (pathCount - 1)
  int liftedLinkCount = 0;       ///< transitions that lifted (the rest are direct)
};

/// @brief Orders and links @p paths. Ordering is greedy nearest neighbour: the first path is
/// the one whose centroid lies lowest along the principal axis of the centroids (the direction
/// across the family; largest component made positive), oriented by the feed; then, from the
/// current end, ZigZag takes the path with the nearest end point (either end, the path then
/// starts there, so parallel paths alternate) and OneDirection the path with the nearest start
/// (every path oriented along feedSign x feedDirection; a closed path's orientation is that of
/// its first segment). Paths with fewer than two points are left out.
/// @param paths #paths polylines, mm, part frame.
/// @throws InvalidInput if feedSign is not +-1, a distance is negative or not finite, or the
/// retract direction is zero.
LinkedPaths linkPaths(const std::vector<std::vector<ddf::Vec3>>& paths,
                      const LinkingParams& params = {});

/// @brief As above, lifting along per-point surface normals (tool side) instead of
/// params.retractDirection.
/// @param normals same shape as @p paths, unit normals.
/// @throws InvalidInput also if the shapes differ.
LinkedPaths linkPaths(const std::vector<std::vector<ddf::Vec3>>& paths,
                      const std::vector<std::vector<ddf::Vec3>>& normals,
                      const LinkingParams& params = {});

/// @brief linkPaths() of the polylines of @p lines with normals from surfaceNormal(), for
/// evenlySpacedStreamlines() or seedAlongTransverse() output. PathMove::path and
/// LinkedPaths::order index @p lines (lines with fewer than two points are left out).
/// @throws InvalidInput as linkPaths().
LinkedPaths linkStreamlines(const ddf::DisplacementField& ddf, const std::vector<Streamline>& lines,
                            const LinkingParams& params = {});

}  // namespace ddfcam::planning
