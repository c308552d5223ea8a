// SPDX-License-Identifier: MIT
// ddfcam: principal curvatures and directions at every raster point of a DDF (sec. 8.2).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/model/project.h>
#include <ddfcam/progress.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace ddfcam::planning {

/// @brief How computeCurvature() estimates the curvature.
enum class CurvatureMethod {
  /// VertexQuadricFit when every face of the DDF is flat (hasFlatFaces(): a converted triangle
  /// mesh before any cut); else DesignMeshFit when CurvatureParams::designMesh is set; else
  /// RasterDifferences.
  Automatic,
  /// Eq. 8.2 finite differences of the heights over the raster (smooth DDFs).
  RasterDifferences,
  /// Quadric fits at the support vertices, blended over the faces (computeVertexCurvature()).
  VertexQuadricFit,
  /// Quadric fits at the vertices of the mesh the part was converted from, at the nearest
  /// point of that mesh (computeDesignCurvature()): a reduced support's heights follow the
  /// mesh's flat triangles, whose second differences are zero inside and spikes at the edges.
  DesignMeshFit
};

/// @brief Options of computeCurvature().
struct CurvatureParams {
  /// Estimation method (default Automatic). A DDF converted from a mesh is flat inside every
  /// face: its raster differences see only the creases at the seams, so the automatic choice
  /// fits the vertices instead.
  CurvatureMethod method = CurvatureMethod::Automatic;
  /// Difference step d of eq. 8.2 in raster steps; 0 picks automaticCurvatureStep(m) (default 0).
  int step = 0;
  /// A point is flagged umbilic / near-isotropic when k_max - k_min <= umbilicTolerance *
  /// max(|k_max|, |k_min|) + flatCurvaturePerMm (default 0.05: 5 % anisotropy).
  double umbilicTolerance = 0.05;
  /// Curvature below which both directions count as meaningless (a plane is isotropic),
  /// 1/mm (default 1e-6).
  double flatCurvaturePerMm = 1e-6;
  /// VertexQuadricFit and DesignMeshFit: per support face a label such as its CAD face, or
  /// empty (VertexCurvatureParams::faceLabels; default empty).
  std::vector<int> faceLabels;
  /// The triangle mesh the DDF was converted from (mm, part frame), for DesignMeshFit, or null
  /// (default). partCurvatureParams() sets it for a part read from a mesh or CAD file.
  std::shared_ptr<const ddf::TriangleMesh> designMesh;
  /// DesignMeshFit: a face takes the design mesh's curvature when all its raster points lie
  /// within this distance of the mesh, mm; other faces (e.g. cut below the design) get
  /// RasterDifferences. 0 = a quarter of the mean raster spacing (default 0).
  double designDistanceMm = 0.0;
  /// Process faces in parallel with TBB (default true).
  bool parallel = true;
  /// Progress in [0, 1]; returning false cancels (default: none).
  ProgressCallback progress;
};

/// @brief Curvature of the represented surface at every stored raster point, laid out like
/// DisplacementField::allHeights() (face after face, Raster order; F * pointsPerFace entries).
/// Sign convention (tool side): the unit normal n points from the material to the tool, i.e.
/// to the +v side of the displacement vectors (cutting lowers h), and a normal curvature is
/// kappa = -II(t, t): positive where the surface bends away from the tool (convex, e.g. a
/// cylinder machined from outside), negative where it bends towards it (concave).
struct CurvatureField {
  std::vector<float> kMax;      ///< larger principal curvature, 1/mm
  std::vector<float> kMin;      ///< smaller principal curvature, 1/mm
  std::vector<float> mean;      ///< (kMax + kMin) / 2, 1/mm
  std::vector<float> gaussian;  ///< kMax * kMin, 1/mm^2
  /// Unit direction of kMax, part frame; a line field (the sign is arbitrary).
  std::vector<ddf::Vec3> dirMax;
  /// Unit direction of kMin, perpendicular to dirMax and to the normal; sign arbitrary.
  std::vector<ddf::Vec3> dirMin;
  /// 1 where the point is umbilic or near-isotropic (directions meaningless), else 0.
  std::vector<std::uint8_t> umbilic;
  int step = 1;  ///< the difference step d actually used, raster steps
  /// The method actually used (never Automatic).
  CurvatureMethod method = CurvatureMethod::RasterDifferences;

  /// @brief Number of entries (F * pointsPerFace).
  std::size_t size() const { return kMax.size(); }
};

/// @brief The automatic difference step d of eq. 8.2 for resolution @p m: d = max(1,
/// round((m - 1) * delta)) with delta = (48 * 2^-24)^(1/4) ~ 0.041 the parameter step that
/// balances the truncation error of the central second difference (~ h'''' delta^2 / 12) with
/// the float rounding of the heights (~ 4 * 2^-24 / delta^2) for h'''' ~ 1 over a face, so that
/// high m does not corrupt the directions (fig. 8.8). m = 17..37 -> 1, 50 -> 2, 100 -> 4. The
/// fourth-order stencils of computeCurvature() keep this rule: on z = sin x sin y their measured
/// error (truncation ~ delta^4, rounding ~ 1 / delta^2) is smallest near delta ~ 0.044, where
/// the rounding floor is ~7e-6 1/mm rms.
int automaticCurvatureStep(int m);

/// @brief Principal curvatures and directions of @p ddf at every raster point from its own
/// parametric form q(u, v) = g + h v (eq. 8.2): first and second fundamental forms from
/// fourth-order central differences of h (5 points with step d along the lattice directions u,
/// v and u - v, reaching 2 d steps), so k converges as O(spacing^4) until the float rounding of
/// the heights takes over. Near support edges the stencil continues into the neighbouring
/// faces: the missing heights are those of the face's own (affinely extended) stubble lines
/// where they meet the neighbouring face's surface, with that surface interpolated by
/// polynomials of degree min(6, m - 1) over its raster, so seams get the same symmetric stencil
/// and the same accuracy as the interior. On the outer boundary of an open support the heights
/// are extrapolated by the cubic of the nearest raster cells (lower accuracy there).
/// With params.method VertexQuadricFit, or Automatic on a DDF whose faces are all flat, the
/// result is computeVertexCurvature() instead (params.step is then not used); with
/// DesignMeshFit, or Automatic with params.designMesh set on a DDF with curved faces, it is
/// computeDesignCurvature().
/// @throws InvalidInput if params.step < 0 or the step is too large for the raster (3 d > m-1
/// needs m >= 4 and d <= (m - 1) / 3), the DDF has no faces, or params.faceLabels has a size
/// other than 0 or the face count (vertex fit).
/// @throws Cancelled if params.progress asks to stop.
CurvatureField computeCurvature(const ddf::DisplacementField& ddf,
                                const CurvatureParams& params = {});

/// @brief The curvature options for the part of @p project as a user sees it: its CAD faces
/// as labels (when there is one per support face) and, for a part read from a mesh or CAD file
/// (sourcePath set) with a design mesh, that mesh for DesignMeshFit. A generated part's design
/// mesh is a coarse triangulation of smooth heights, which its raster differences see better.
CurvatureParams partCurvatureParams(const Project& project);

/// @brief Scalar quantities of a CurvatureField.
enum class CurvatureQuantity {
  KMax,     ///< "k_max", 1/mm
  KMin,     ///< "k_min", 1/mm
  Mean,     ///< "mean curvature", 1/mm
  Gaussian  ///< "Gaussian curvature", 1/mm^2
};

/// @brief One quantity of @p field as a signed ScalarField ("k_max", "k_min", "mean curvature",
/// "Gaussian curvature"; units "1/mm" or "1/mm^2").
ScalarField curvatureScalarField(const CurvatureField& field, CurvatureQuantity quantity);

}  // namespace ddfcam::planning
