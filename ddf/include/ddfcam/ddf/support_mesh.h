// SPDX-License-Identifier: MIT
// ddfcam: the support triangle mesh of a DDF (OpenMesh, double precision).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <array>
#include <vector>

namespace ddfcam::ddf {

/// @brief 3D point or vector in the part frame, mm.
using Vec3 = Eigen::Vector3d;

/// @brief OpenMesh traits: double-precision points, no per-element normals stored.
struct SupportTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};

/// @brief Support mesh S of a DDF: an oriented triangle mesh; the front side of a face is the
/// side its counter-clockwise normal points to.
using SupportMesh = OpenMesh::TriMesh_ArrayKernelT<SupportTraits>;

/// @brief Converts an OpenMesh point to Eigen.
inline Vec3 toEigen(const OpenMesh::Vec3d& p) {
  return {p[0], p[1], p[2]};
}

/// @brief Converts an Eigen point to OpenMesh.
inline OpenMesh::Vec3d toOpenMesh(const Vec3& p) {
  return {p.x(), p.y(), p.z()};
}

/// @brief Builds a support mesh from indexed triangles.
/// @param points #V points, mm.
/// @param triangles #F vertex index triples, counter-clockwise seen from the front side.
/// @throws InvalidInput if an index is out of range or OpenMesh rejects a face (non-manifold
/// configuration); the message names the face.
SupportMesh makeSupportMesh(const std::vector<Vec3>& points,
                            const std::vector<std::array<int, 3>>& triangles);

}  // namespace ddfcam::ddf
