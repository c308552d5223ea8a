// SPDX-License-Identifier: MIT
// ddfcam: loading a part as a DDF from a .ddf file or from a mesh file (converted on the fly).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/progress.h>

#include <filesystem>

namespace ddfcam::io {

/// @brief Parameters of loadPart().
struct LoadPartParams {
  /// Conversion of mesh files (raster resolution, welding, vector directions and lengths);
  /// ignored for .ddf files. Its progress callback is replaced by @ref progress.
  /// Default: ddf::ConversionParams defaults (m = 10).
  ddf::ConversionParams conversion;
  /// Progress in [0, 1] and cancellation for the whole load. Default none.
  ProgressCallback progress;
};

/// @brief What loadPart() did besides returning the field.
struct LoadPartReport {
  bool converted = false;      ///< true if the file was a mesh converted to a DDF
  int meshVertices = 0;        ///< vertices read from the mesh file (0 for .ddf)
  int meshTriangles = 0;       ///< triangles read from the mesh file (0 for .ddf)
  int droppedFaces = 0;        ///< triangles the conversion dropped as non-manifold or flipped
  int degenerateFaces = 0;     ///< triangles dropped for a repeated vertex or zero area
  int weldedVertices = 0;      ///< mesh vertices merged into another one
  int repairedVertices = 0;    ///< vertices whose direction was repaired (constraint 1)
  int infeasibleVertices = 0;  ///< vertices with no front-facing direction
};

/// @brief Loads @p path as a DDF: a .ddf file through readDdf, a .stl/.obj/.ply/.off mesh
/// through readMesh and ddf::convertMeshToDdf (the mesh becomes the support, heights 0).
/// @param report if not null, receives what the conversion did.
/// @throws IoError "loading <file>" with the cause nested (missing or malformed file, unknown
/// extension, a mesh the conversion rejects); Cancelled (not wrapped) through params.progress.
ddf::DisplacementField loadPart(const std::filesystem::path& path,
                                const LoadPartParams& params = {},
                                LoadPartReport* report = nullptr);

}  // namespace ddfcam::io
