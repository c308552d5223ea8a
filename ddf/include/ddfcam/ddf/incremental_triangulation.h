// SPDX-License-Identifier: MIT
// ddfcam: an adaptive triangulation of a DDF surface kept up to date while its heights change.
#pragma once

#include <ddfcam/ddf/adaptive_triangulation.h>
#include <ddfcam/ddf/displacement_field.h>

#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace ddfcam::ddf {

/// @brief Parameter positions (i, k) of a triangle's three corners on its support face, in
/// raster steps (raster point (i, k) of Raster at integers; fractions between them), float.
using TriangleParams = std::array<std::array<float, 2>, 3>;

/// @brief What one IncrementalTriangulation::update() did.
struct TriangulationUpdate {
  /// Faces subdivided again: the changed ones and every face sharing a support vertex with one
  /// (a cut's shared points reach those), sorted.
  std::vector<int> subdividedFaces;
  /// Faces whose triangles were rebuilt: the subdivided ones and the faces sharing a support
  /// edge with them (whose T-vertex removal uses the points the neighbour put on the edge),
  /// sorted.
  std::vector<int> reassembledFaces;
  /// Vertex slots whose position, normal or use may have changed, sorted: a display updates
  /// these points and the triangles of reassembledFaces.
  std::vector<int> touchedSlots;
  double seconds = 0.0;  ///< wall time of the update, s
};

/// @brief The adaptive triangulation of ch. 7 (triangulateAdaptive() with T-vertex removal)
/// kept per support face, so that after a cut only the faces it reached are subdivided again
/// (the incremental display of a live simulation).
///
/// The result after any sequence of update() and setFaceEps() calls equals a fresh
/// triangulateAdaptive() of the current heights with the current bounds: per face the same
/// triangles with bitwise the same corner positions, in the same order (the subdivision of a face depends only on its own raster and its canonical
/// border points, and the points on a support edge only on that edge), hence crack-free and
/// without T-vertices. Vertices live in slots: a border vertex has one slot for all faces that
/// share it, freed slots are reused, so slot numbers differ from the fresh build's indices.
/// Normals are area-weighted vertex normals summed in face order, so they too equal those of
/// a fresh build of the same heights.
class IncrementalTriangulation {
 public:
  /// @brief Triangulates @p ddf within @p epsMm (mm, > 0). @p ddf must outlive this object,
  /// and afterwards only its heights may change (support, vectors and m stay).
  /// @throws InvalidInput if epsMm is not positive.
  explicit IncrementalTriangulation(const DisplacementField& ddf, double epsMm = 0.01);
  ~IncrementalTriangulation();
  IncrementalTriangulation(IncrementalTriangulation&&) noexcept;
  IncrementalTriangulation& operator=(IncrementalTriangulation&&) noexcept;

  /// @brief Brings the triangulation up to date after the heights of @p changedFaces changed
  /// (any order, duplicates allowed; e.g. ddf::CutStats::touchedFaces). Faces outside the set
  /// and its neighbours must not have changed.
  TriangulationUpdate update(std::span<const int> changedFaces);

  /// @brief Sets an error bound per support face (mm, each > 0; see
  /// AdaptiveTriangulationParams::faceEpsMm), e.g. from the view (a level of detail that
  /// follows the camera). Faces whose bound changed and their edge neighbours (whose shared
  /// edges may now be held to another bound) are subdivided again; afterwards the result
  /// equals a fresh build with these bounds. The heights must not have changed since the last
  /// update(). @throws InvalidInput as checkFaceEps.
  TriangulationUpdate setFaceEps(std::span<const float> epsMm);

  /// @brief The error bound given at construction, mm.
  double epsMm() const;
  /// @brief The error bound of every face, mm (all epsMm() until setFaceEps()).
  const std::vector<float>& faceEps() const;
  /// @brief Vertex slots, mm, part frame; a slot no triangle refers to is free (stale).
  const std::vector<Vec3>& vertices() const;
  /// @brief Unit area-weighted vertex normal per slot (oriented like the support faces; zero
  /// for a free slot).
  const std::vector<Vec3>& normals() const;
  /// @brief Triangles of support face @p face as slot triples, oriented like the face.
  const std::vector<std::array<int, 3>>& faceTriangles(int face) const;
  /// @brief Per triangle of faceTriangles(@p face), where its corners lie on the face's raster:
  /// the lattice position of a subdivision vertex, the mean of its leaf's corners for a centroid
  /// (where the centroid's position is the mean of theirs). A display maps raster-resolution
  /// values (one per raster point of the face, e.g. a texture) through these. Computed on first
  /// request after the face was rebuilt (so displays without raster colours pay nothing); not
  /// to be called concurrently with itself or an update.
  const std::vector<TriangleParams>& faceTriangleParams(int face) const;
  /// @brief Number of triangles over all faces.
  std::size_t triangleCount() const;
  /// @brief The mesh with its slots compacted (first use in face order), the face of every
  /// triangle and the statistics of triangulateAdaptiveWithStats().
  AdaptiveTriangulation snapshot() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace ddfcam::ddf
