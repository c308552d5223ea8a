// SPDX-License-Identifier: MIT
// ddfcam: meshes and surfaces read in a length unit and scaled to millimetres.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/length_unit.h>
#include <ddfcam/planning/mould/mould_study.h>

#include <filesystem>

namespace ddfcam::io {

/// @brief @p mesh with every vertex multiplied by millimetresPer(@p unit): a mesh in file units
/// becomes one in mm (the triangles are unchanged; mm returns it as it is).
ddf::TriangleMesh scaledToMm(ddf::TriangleMesh mesh, ddfcam::LengthUnit unit);

/// @brief Length of the diagonal of the axis-aligned bounding box of @p mesh, in its units
/// (0 for an empty mesh): the size sizeSuggestsOtherUnit() judges.
double boundingBoxDiagonal(const ddf::TriangleMesh& mesh);

/// @brief readMesh(@p path) scaled from @p unit to mm.
/// @throws IoError as readMesh.
ddf::TriangleMesh readMeshInUnit(const std::filesystem::path& path, ddfcam::LengthUnit unit);

/// @brief readSurfaceFile(@p path) with its mesh scaled from @p unit to mm (the scalar fields
/// are kept as read).
/// @throws IoError as readSurfaceFile.
planning::LoadedSurface readSurfaceFileInUnit(const std::filesystem::path& path,
                                              ddfcam::LengthUnit unit);

}  // namespace ddfcam::io
