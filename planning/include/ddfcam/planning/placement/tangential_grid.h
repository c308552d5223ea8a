// SPDX-License-Identifier: MIT
// ddfcam: tangential height grids at a contact point (dissertation sec. 8.4.2, fig. 8.18, 8.20).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>

#include <Eigen/Geometry>

#include <limits>
#include <vector>

namespace ddfcam::planning {

/// @brief An orthonormal frame at a contact point: @c normal points from the material to the
/// tool; (u, v) span the tangent plane. Coordinates (u, v, w) of a part-frame point p are
/// (axisU . (p - origin), axisV . (p - origin), normal . (p - origin)), mm.
struct TangentFrame {
  ddf::Vec3 origin = ddf::Vec3::Zero();   ///< contact point, mm, part frame
  ddf::Vec3 axisU = ddf::Vec3::UnitX();   ///< first tangent axis (unit)
  ddf::Vec3 axisV = ddf::Vec3::UnitY();   ///< second tangent axis, normal x axisU (unit)
  ddf::Vec3 normal = ddf::Vec3::UnitZ();  ///< unit normal, material -> tool

  /// @brief (u, v, w) of part-frame point @p p, mm.
  ddf::Vec3 toLocal(const ddf::Vec3& p) const {
    const ddf::Vec3 d = p - origin;
    return {axisU.dot(d), axisV.dot(d), normal.dot(d)};
  }
  /// @brief Part-frame point of local coordinates @p l, mm.
  ddf::Vec3 toPart(const ddf::Vec3& l) const {
    return origin + l.x() * axisU + l.y() * axisV + l.z() * normal;
  }
};

/// @brief The frame at @p contact with normal @p normal whose u axis is the tangential part of
/// @p hint (e.g. a roll's axis, so the grid box hugs the tool); if @p hint is (nearly) parallel
/// to the normal, any tangent direction is used.
/// @throws InvalidInput for a zero or non-finite normal.
TangentFrame tangentFrame(const ddf::Vec3& contact, const ddf::Vec3& normal,
                          const ddf::Vec3& hint = ddf::Vec3::UnitX());

/// @brief Spatial index of a DDF's raster surface (the raster triangles of fig. 7.1a) for
/// repeated local queries: a uniform grid over conservative per-face bounds (the hull of
/// p_a + h v_a for the face's smallest and largest height), built once in O(#heights).
/// It reads the field's heights at construction: rebuild (or refresh()) after changing them.
class SurfacePatchIndex {
 public:
  /// @brief Indexes @p goal (kept by reference; it must outlive the index).
  /// @throws InvalidInput for a field without faces.
  explicit SurfacePatchIndex(const ddf::DisplacementField& goal);

  /// @brief Recomputes the face bounds of @p faces after their heights changed (cell lists
  /// are kept, so a face may only shrink or move within its old cells' reach).
  void refresh(const std::vector<int>& faces);

  /// @brief Faces whose bounds overlap @p box (part frame, mm); sorted, unique, into @p out.
  void query(const Eigen::AlignedBox3d& box, std::vector<int>& out) const;

  /// @brief The six hull points of face @p f (3 corners at the smallest height, then 3 at the
  /// largest), mm: every raster point of the face lies in their convex hull.
  const std::array<ddf::Vec3, 6>& hull(int f) const { return hull_[f]; }

  /// @brief The indexed field.
  const ddf::DisplacementField& field() const { return *ddf_; }

  /// @brief Unit normal of the represented surface at the raster triangle nearest to
  /// @p contact (mm, part frame), oriented like the displacement vectors.
  /// @throws InvalidInput if no face lies near @p contact.
  ddf::Vec3 normalAt(const ddf::Vec3& contact) const;

 private:
  void computeHull(int f);
  const ddf::DisplacementField* ddf_ = nullptr;
  std::vector<std::array<ddf::Vec3, 6>> hull_;
  Eigen::AlignedBox3d bounds_;
  ddf::Vec3 cell_ = ddf::Vec3::Ones();
  Eigen::Vector3i dims_ = Eigen::Vector3i::Ones();
  std::vector<int> cellStart_;  // CSR: faces of cell c are cellFaces_[cellStart_[c] ..)
  std::vector<int> cellFaces_;
};

}  // namespace ddfcam::planning
