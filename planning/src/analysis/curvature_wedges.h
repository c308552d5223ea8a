// SPDX-License-Identifier: MIT
// ddfcam: internal: the fans of the support vertices split at crease edges into smooth wedges.
#pragma once

#include <ddfcam/ddf/displacement_field.h>

#include <vector>

namespace ddfcam::planning::detail {

/// @brief Every support vertex's fan of faces split into wedges: maximal groups of faces
/// around the vertex joined across the edges through it whose represented triangles meet at
/// less than the crease angle. A vertex inside a smooth region has one wedge; one on a sharp
/// CAD edge (a cylinder meeting its end cap) has one per side, so that a fit at the vertex can
/// stay on one smooth sheet.
struct CurvatureWedges {
  /// Per vertex v, per entry of topology().vertexFaces(v): the wedge of that face at v.
  std::vector<std::vector<int>> ofFan;
  std::vector<int> vertex;              ///< per wedge: its support vertex
  std::vector<std::vector<int>> faces;  ///< per wedge: its faces

  /// @brief The wedge of face @p f at its corner vertex @p v (f must contain v).
  int at(const ddf::DisplacementField& ddf, int v, int f) const;
  int count() const { return static_cast<int>(vertex.size()); }
};

/// @brief The wedges of every vertex of @p ddf from the represented triangles through the
/// corner points @p corners (per vertex, mm); faces with no area never split a fan.
/// @param faceLabels per face a label (e.g. its CAD face), or empty: faces with different labels
/// never share a wedge.
/// @param cosCrease cosine of the crease angle between two triangles' normals.
CurvatureWedges curvatureWedges(const ddf::DisplacementField& ddf,
                                const std::vector<ddf::Vec3>& corners,
                                const std::vector<int>& faceLabels, double cosCrease);

/// @brief The faces within @p rings rings of wedge @p w: the wedge's own faces (ring 1), then
/// repeatedly, for every face collected, the faces of the wedge it lies in at each of its corners
/// (so the neighbourhood never crosses a crease). Sorted face indices.
std::vector<int> wedgeNeighbourhood(const ddf::DisplacementField& ddf,
                                    const CurvatureWedges& wedges, int w, int rings);

}  // namespace ddfcam::planning::detail
