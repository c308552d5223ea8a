// SPDX-License-Identifier: MIT
// ddfcam: where a placed tool of an imported program touches the part (nearest points, feet
// on the smooth surface, contact of a pose).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/planning/surface/mesh_distance.h>
#include <ddfcam/planning/tools/tool.h>

#include <Eigen/Geometry>

#include <utility>
#include <vector>

namespace ddfcam::planning::detail {

/// @brief The part's surface as its raster mesh, for nearest-point queries with the tool side
/// known (part frame, mm).
class PartSurface {
 public:
  /// @param part the part (not owned; must outlive this).
  explicit PartSurface(const ddf::DisplacementField& part);

  /// @brief A nearest point of the raster mesh.
  struct Hit {
    ddf::Vec3 point;        ///< nearest point, mm
    double signedDistance;  ///< mm; + on the side the part's vectors point to
    int face;               ///< face of the support mesh holding it
  };

  /// @brief The point of the raster mesh nearest to @p p.
  /// @throws InvalidInput if @p p is not finite.
  Hit nearest(const ddf::Vec3& p) const;

  /// @brief Unit normal at @p hit towards the tool side.
  ddf::Vec3 normal(const Hit& hit) const;

  /// @brief The foot of @p c on the smooth surface (c - foot along the smooth normal there),
  /// from @p hit, the nearest point of the faceted raster mesh, with the normal at the foot.
  std::pair<Hit, ddf::Vec3> smoothFoot(const ddf::Vec3& c, Hit hit) const;

 private:
  const ddf::DisplacementField& part_;
  ddf::RasterMesh raster_;
  MeshDistance distance_;
  int perFace_ = 1;
  std::vector<double> outward_;
};

/// @brief Core samples of @p tool in its own frame with their reach, mm: a ball end's centre
/// (reach r); a flat or torus cutter's tip centre (0) and 16 corner-circle centres (reach e);
/// any other tool's origin (reach r). A surface point touches the tool where its distance to
/// a sample equals the sample's reach.
std::vector<std::pair<ddf::Vec3, double>> coreSamples(const Tool& tool);

/// @brief True when @p c lies beside the part's border rather than above or below its surface:
/// the offset from @p foot (its nearest surface point, unit normal @p n there) leaves the normal
/// line by more than about 25 deg. Offsets below 1 um count as on the normal.
bool besideBorder(const ddf::Vec3& c, const ddf::Vec3& foot, const ddf::Vec3& n);

/// @brief Where a placed tool touches the part.
struct PoseContact {
  ddf::Vec3 point;      ///< contact point on the smooth surface, mm
  ddf::Vec3 normal;     ///< unit surface normal there, tool side
  double distanceMm;    ///< gap between tool and surface, mm (< 0: penetration)
  bool beside = false;  ///< the tool lies beside the part's border (besideBorder()), not over it
};

/// @brief The contact of the tool at @p pose: the core sample of @p samples nearest to the
/// raster mesh (minus its reach), its foot refined on the smooth surface.
PoseContact contactOf(const PartSurface& surface, const Eigen::Isometry3d& pose,
                      const std::vector<std::pair<ddf::Vec3, double>>& samples);

}  // namespace ddfcam::planning::detail
