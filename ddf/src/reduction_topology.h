// SPDX-License-Identifier: MIT
// ddfcam (private): the topology of one edge contraction of the support reduction (sec. 6.1):
// kept vertices, critical edges, and the faces a contraction modifies.
#pragma once

#include <ddfcam/ddf/support_mesh.h>

#include <array>
#include <span>
#include <vector>

namespace ddfcam::ddf::detail {

/// @brief Vertices no contraction may move: mesh boundary vertices, vertices whose faces
/// carry different labels (@p faceLabels empty or one per face) and vertices on a feature edge
/// (the normals of its two faces differ by more than @p featureAngleDeg; 180 = none). #V flags.
std::vector<char> keptVertices(const SupportMesh& mesh, std::span<const int> faceLabels,
                               double featureAngleDeg = 180.0);

/// @brief Whether contracting the edge of @p heh is pathological (fig. 6.5, 6.6): the edge
/// lies on a closed path of length 3 that is not a face, or OpenMesh's link test refuses it
/// (which needs the status attributes of @p mesh, hence non-const).
bool isCriticalEdge(SupportMesh& mesh, SupportMesh::HalfedgeHandle heh);

/// @brief What the contraction of one interior edge touches (fig. 6.7).
struct ContractionRegion {
  SupportMesh::HalfedgeHandle heh;  ///< from a to b; collapse keeps b
  int a = -1;                       ///< vertex removed by the collapse
  int b = -1;                       ///< vertex that becomes the new vertex
  std::array<int, 2> removed{};     ///< the two faces of the edge
  std::vector<int> modified;        ///< the other faces around a or b
  std::vector<int> ring;            ///< vertices adjacent to a or b, except a and b
  std::vector<int> neighbours;      ///< faces at a ring vertex outside the region
};

/// @brief The region of the contraction of the interior edge of @p heh, which removes its
/// from-vertex and keeps its to-vertex.
ContractionRegion contractionRegion(const SupportMesh& mesh, SupportMesh::HalfedgeHandle heh);

/// @brief The vertex indices of face @p face in the order of its halfedges.
std::array<int, 3> faceVertexIds(const SupportMesh& mesh, int face);

}  // namespace ddfcam::ddf::detail
