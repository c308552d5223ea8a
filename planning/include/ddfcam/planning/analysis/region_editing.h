// SPDX-License-Identifier: MIT
// ddfcam: manual region editing (sec. 8.1): assign, brush, merge, split, rename, remove.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/model/project.h>
#include <ddfcam/planning/surface/uniform_grid.h>

#include <Eigen/Core>

#include <array>
#include <span>
#include <string>
#include <vector>

namespace ddfcam::planning {

/// @brief Region index of every support face: faceCount entries, -1 where no region holds
/// the face.
/// @throws InvalidInput if a region lists a face outside [0, faceCount) or a face lies in two
/// regions (naming both).
std::vector<int> faceRegionIndex(const std::vector<Region>& regions, int faceCount);

/// @brief Region index per raster point as ScalarField "region" (unsigned, no unit; layout of
/// allHeights(): every raster point of a face carries its face's region index, NaN where the
/// face lies in no region), for colour maps.
/// @throws InvalidInput as faceRegionIndex().
ScalarField regionIndexField(const ddf::DisplacementField& ddf, const std::vector<Region>& regions);

/// @brief A display colour (RGB in [0, 1]) that differs clearly from every colour of
/// @p regions: of 96 candidates (a golden-ratio hue walk in vivid, pale and dark variants),
/// the one farthest (RGB distance) from all of them; the first candidate if there are none.
std::array<float, 3> distinctRegionColor(const std::vector<Region>& regions);

/// @brief Moves @p faces into region @p target, taking them out of every other region (other
/// regions keep their place even if they become empty). @p target == regions.size() appends
/// a new region named @p newRegionName with distinctRegionColor() and a default plan;
/// @p target == -1 only takes the faces out of all regions (an eraser).
/// @param faces support face indices in any order, duplicates allowed.
/// @param faceCount the part's support face count.
/// @returns the edited copy; faces stay ascending and unique.
/// @throws InvalidInput if @p target is out of [-1, regions.size()], a face is out of range,
/// the regions are inconsistent (see faceRegionIndex()) or a new region's name is empty.
std::vector<Region> assignFaces(const std::vector<Region>& regions, int target,
                                std::span<const int> faces, int faceCount,
                                const std::string& newRegionName = {});

/// @brief Merges the regions at @p indices (at least two, distinct) into the one with the
/// lowest index: it keeps its place, name, colour and plan and receives the union of all their
/// faces; the others are removed.
/// @throws InvalidInput if fewer than two distinct indices are given or one is out of range.
std::vector<Region> mergeRegions(const std::vector<Region>& regions, std::vector<int> indices);

/// @brief Splits region @p index into its connected parts (faces are connected when they share
/// a support edge). The part holding the region's lowest face keeps the place, name, colour and
/// plan; the others, ordered by their lowest face, follow it as "<name> (2)", "<name> (3)", ...
/// with the same plan and new distinct colours. A connected region is returned unchanged.
/// @throws InvalidInput if @p index is out of range or a face is not a face of @p ddf.
std::vector<Region> splitConnectedParts(const ddf::DisplacementField& ddf,
                                        const std::vector<Region>& regions, int index);

/// @brief Moves @p faces (all of region @p index, not all of its faces) into a new region
/// "<name> (split)" with the same plan and a distinct colour, inserted right after it.
/// @throws InvalidInput if @p index is out of range, @p faces is empty, holds a face that is
/// not in the region, or holds all of its faces.
std::vector<Region> splitRegionFaces(const std::vector<Region>& regions, int index,
                                     std::span<const int> faces);

/// @brief Renames region @p index.
/// @throws InvalidInput if @p index is out of range or @p name is empty.
std::vector<Region> renameRegion(const std::vector<Region>& regions, int index,
                                 const std::string& name);

/// @brief Removes region @p index (its faces become unassigned).
/// @throws InvalidInput if @p index is out of range.
std::vector<Region> removeRegion(const std::vector<Region>& regions, int index);

/// @brief Replaces the plan of region @p index.
/// @throws InvalidInput if @p index is out of range.
std::vector<Region> setRegionPlan(const std::vector<Region>& regions, int index,
                                  const RegionPlan& plan);

/// @brief Where a support face lies on the represented surface, for lasso selection.
struct FaceFrame {
  ddf::Vec3 centroid;  ///< mean of the face's raster surface points, mm, part frame
  /// Unit normal of the triangle through the surface points of the face's three corners,
  /// oriented along the face's mean displacement vector (towards the tool side); zero if
  /// that triangle is degenerate.
  ddf::Vec3 normal;
};

/// @brief FaceFrame of every support face of @p ddf (faceCount entries).
std::vector<FaceFrame> faceFrames(const ddf::DisplacementField& ddf);

/// @brief True if @p point lies inside the closed polygon @p polygon (even-odd rule; any
/// 2D frame, e.g. widget pixels). Fewer than three vertices contain nothing.
bool pointInPolygon(const Eigen::Vector2d& point, std::span<const Eigen::Vector2d> polygon);

/// @brief A UniformGrid over the raster surface points of a DDF, for brush queries: each
/// query visits only the grid cells that the ball touches. Build once per part state (heights
/// included); O(points) to build.
class SurfacePointGrid {
 public:
  /// @param cellSizeMm grid cell edge, mm; <= 0 picks the mean support edge length.
  /// @throws InvalidInput if the DDF has no faces.
  explicit SurfacePointGrid(const ddf::DisplacementField& ddf, double cellSizeMm = 0.0);

  /// @brief Support faces with at least one raster surface point within @p radiusMm of
  /// @p point (mm, part frame), ascending.
  /// @throws InvalidInput if @p radiusMm is negative or not finite.
  std::vector<int> facesWithinDistance(const ddf::Vec3& point, double radiusMm) const;

  /// @brief Grid cell edge in use, mm.
  double cellSizeMm() const { return grid_.cellMm(); }

 private:
  int faceCount_ = 0;
  std::vector<ddf::Vec3> points_;  ///< raster surface points, face by face
  std::vector<int> pointFace_;     ///< face of points_[i]
  UniformGrid grid_{1.0};          ///< indices into points_
};

/// @brief One-off brush query: SurfacePointGrid(ddf).facesWithinDistance(point, radiusMm).
/// Builds the grid (O(points)); keep a SurfacePointGrid for repeated queries.
/// @throws InvalidInput as SurfacePointGrid.
std::vector<int> facesWithinDistance(const ddf::DisplacementField& ddf, const ddf::Vec3& point,
                                     double radiusMm);

}  // namespace ddfcam::planning
