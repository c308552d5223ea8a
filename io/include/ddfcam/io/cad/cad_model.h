// SPDX-License-Identifier: MIT
// ddfcam: CAD models (STEP, IGES) read through OpenCASCADE, their tessellation and exact surfaces.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/length_unit.h>
#include <ddfcam/progress.h>

#include <Eigen/Core>

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ddfcam::io {

/// @brief True if @p path has a CAD suffix readCadModel() accepts: .step, .stp, .iges, .igs
/// (any case).
bool isCadFile(const std::filesystem::path& path);

/// @brief Parameters of readCadModel().
struct CadReadParams {
  /// Unit of the file's coordinates. std::nullopt: the unit the file states (STEP units,
  /// IGES global section). A given unit overrides the file's. Default std::nullopt.
  std::optional<ddfcam::LengthUnit> unit;
  /// Heal the shape with ShapeFix_Shape and sew loose faces and open shells. Default true.
  bool heal = true;
  /// Progress in [0, 1] and cancellation, called between reading, transfer, healing and the
  /// face survey. Default none.
  ProgressCallback progress;
  /// Sewing tolerance, mm; 0 = 1e-4 x the bounding-box diagonal (gaps of CAD exports in the
  /// file's own uncertainty close, distinct features stay apart). Default 0.
  double sewingToleranceMm = 0.0;
};

/// @brief One face of a CAD model.
struct CadFace {
  std::string surfaceType;  ///< "plane", "cylinder", "cone", "sphere", "torus", "B-spline", ...
  std::string name;         ///< display name: "face 12 (B-spline)" (1-based number)
  double areaMm2 = 0.0;     ///< exact area of the trimmed face, mm^2
};

/// @brief A CAD model read from a STEP or IGES file, in millimetres. Holds the OpenCASCADE
/// shape behind a pointer; copies share it (the model is immutable).
class CadModel {
 public:
  CadModel();
  ~CadModel();
  CadModel(const CadModel&);
  CadModel& operator=(const CadModel&);
  CadModel(CadModel&&) noexcept;
  CadModel& operator=(CadModel&&) noexcept;

  /// @brief The faces, indexed as everywhere in this header (0-based).
  const std::vector<CadFace>& faces() const;
  int faceCount() const { return static_cast<int>(faces().size()); }
  /// @brief The display names of faces(), in order.
  std::vector<std::string> faceNames() const;
  int solidCount() const;      ///< solids in the model
  int shellCount() const;      ///< shells (closed or open), those inside solids included
  int looseFaceCount() const;  ///< faces in no shell, as read (before sewing)
  /// @brief The unit the file states, if it is mm, cm, m or in; std::nullopt otherwise (none,
  /// or another unit such as feet, which OpenCASCADE still converts to mm).
  std::optional<ddfcam::LengthUnit> fileUnit() const;
  /// @brief The file's own name of its unit ("millimetre", "INCH", ...); empty if none.
  const std::string& fileUnitName() const;
  /// @brief The unit the coordinates were read in: the override of CadReadParams::unit, else
  /// fileUnit(), else mm.
  ddfcam::LengthUnit unit() const;
  /// @brief True if unit() is the unit the file states (no override).
  bool unitFromFile() const;
  /// @brief Axis-aligned bounds of the exact geometry (min, max), mm, part frame.
  std::array<Eigen::Vector3d, 2> boundsMm() const;
  /// @brief What healing and sewing changed, one fact per line (empty if nothing).
  const std::vector<std::string>& healing() const;
  /// @brief Total exact area of the faces, mm^2.
  double areaMm2() const;
  /// @brief The model's own geometric uncertainty, mm: the largest tolerance of its edges and
  /// vertices after healing (how far an edge's 3D curve may lie from its faces; 1e-7 for an
  /// exact model, 0.06 mm for boxed_sphere.step). A distance to the exact surface means
  /// nothing below it near face borders.
  double toleranceMm() const;

  struct Impl;  ///< the OpenCASCADE side (io/src/cad only)
  /// @brief Wraps a filled implementation (io/src/cad only).
  explicit CadModel(std::shared_ptr<const Impl> impl);
  const Impl& impl() const { return *impl_; }

 private:
  std::shared_ptr<const Impl> impl_;
};

/// @brief Reads a STEP (.step, .stp; AP203, AP214, AP242) or IGES (.iges, .igs) file: its
/// solids, shells and loose faces, converted to mm from the unit the file states (or the
/// override in @p params), healed and sewn (see CadReadParams).
/// @throws Cancelled through params.progress;
/// IoError naming the file when it is missing, empty, not a STEP/IGES file ("... is not
/// a STEP file"), damaged (the reader fails or transfers nothing), "... has no faces", or has an
/// unsupported suffix.
CadModel readCadModel(const std::filesystem::path& path, const CadReadParams& params = {});

/// @brief Parameters of tessellateCadModel().
struct CadTessellationParams {
  /// Largest distance of a triangle from its face's exact surface (chord deflection), mm,
  /// > 0. Default 0.01.
  double chordDeflectionMm = 0.01;
  /// Largest angle between the normals of neighbouring triangle corners, rad, > 0. Default 0.5.
  double angularDeflectionRad = 0.5;
  /// Nodes closer than this are merged into one vertex, mm; 0 = 1e-7 x the bounding-box
  /// diagonal (the nodes BRepMesh puts on a shared edge coincide to rounding). Default 0.
  double weldToleranceMm = 0.0;
  /// Progress in [0, 1] and cancellation, called between the stages and per face while the
  /// chord error is measured. Default none.
  ProgressCallback progress;
};

/// @brief A CAD model as triangles.
struct CadTessellation {
  /// Welded triangles in mm, counter-clockwise seen from outside (the faces' orientation).
  ddf::TriangleMesh mesh;
  std::vector<int> faceOfTriangle;  ///< per triangle, the index of its CAD face
  /// Largest measured chord error (distance of a triangle's centroid or edge midpoint from its
  /// face's exact surface), mm: as BRepMesh first made the triangles, and after the faces over
  /// the requested deflection were re-meshed finer (then <= chordDeflectionMm unless a face
  /// resisted every round).
  double initialChordErrorMm = 0.0;
  double chordErrorMm = 0.0;
  std::vector<int> refinedFaces;  ///< the faces re-meshed finer, ascending
};

/// @brief Triangulates every face of @p model with BRepMesh_IncrementalMesh, measures each
/// face's chord error against its exact surface (BRepMesh overshoots on some B-spline faces) and
/// re-meshes the faces over the requested deflection with a finer interior deflection (the
/// boundary nodes stay, so the faces still meet), a few rounds at most; orients the
/// triangles outwards (a reversed face's triangles are flipped), merges coincident nodes (shared
/// edges, seams, poles) and drops triangles that collapse in the merge.
/// @throws InvalidInput for a non-positive deflection; IoError if no face yields a triangle;
/// Cancelled through params.progress.
CadTessellation tessellateCadModel(const CadModel& model, const CadTessellationParams& params = {});

/// @brief The closest point of a CAD model to a query point.
struct CadProjection {
  Eigen::Vector3d pointMm = Eigen::Vector3d::Zero();  ///< closest point on the faces, mm
  double distanceMm = 0.0;                            ///< its distance from the query, mm
  int face = -1;                                      ///< index of the face it lies on
};

/// @brief Curvature of a CAD face at a point. Signs as planning::CurvatureField: a normal
/// curvature is positive where the surface bends away from the outward normal (convex; a
/// sphere of radius r seen from outside has k1 = k2 = 1/r).
struct CadCurvature {
  double k1 = 0.0;                                    ///< larger principal curvature, 1/mm
  double k2 = 0.0;                                    ///< smaller principal curvature, 1/mm
  Eigen::Vector3d dir1 = Eigen::Vector3d::Zero();     ///< unit direction of k1 (zero if umbilic)
  Eigen::Vector3d dir2 = Eigen::Vector3d::Zero();     ///< unit direction of k2 (zero if umbilic)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit outward normal
  Eigen::Vector3d pointMm = Eigen::Vector3d::Zero();  ///< the point on the surface used, mm
  bool umbilic = false;                               ///< directions undefined (k1 == k2)
};

/// @brief Exact-surface queries on a CAD model, for oracles and reports. Each face keeps its
/// surface and exact bounding box; a projection visits the faces nearest first by box distance
/// and stops when no box can hold a closer point, so thousands of queries stay fast. Not
/// thread-safe for concurrent calls (use one query object per thread).
class CadSurfaceQuery {
 public:
  explicit CadSurfaceQuery(const CadModel& model);
  ~CadSurfaceQuery();
  CadSurfaceQuery(CadSurfaceQuery&&) noexcept;
  CadSurfaceQuery& operator=(CadSurfaceQuery&&) noexcept;

  /// @brief The closest point of the trimmed faces to @p pointMm (mm, part frame), or
  /// std::nullopt if none lies within @p maxDistanceMm.
  std::optional<CadProjection> project(const Eigen::Vector3d& pointMm,
                                       double maxDistanceMm = 1e300) const;

  /// @brief Principal curvatures and directions of face @p face at the foot of @p pointMm on its
  /// surface (GeomLProp_SLProps at the projected (u, v)); std::nullopt if the projection or the
  /// curvature is undefined there (e.g. a pole).
  /// @throws InvalidInput if @p face is out of range.
  std::optional<CadCurvature> curvature(int face, const Eigen::Vector3d& pointMm) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ddfcam::io
