// SPDX-License-Identifier: MIT
// ddfcam-cli: the error map of a produced surface as a .vtp mesh (simulate and run commands).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/io/results/vtp_writer.h>
#include <ddfcam/planning/inspection/error_map.h>

namespace ddfcam::cli {

/// @brief The produced surface along its raster lattice, one vertex per raster point (mm, part
/// frame), with two point scalars appended to @p data: "deviation_mm" (the deviation of the
/// point's copy in the lowest-index face, the copy whose position the vertex takes; > 0 material
/// left) and "tolerance_class" (-1 overcut, 0 in tolerance, 1 material left; NaN where the
/// deviation is NaN).
/// @param produced the simulated part.
/// @param deviation per-point values of @p produced (faceCount * pointsPerFace), mm.
/// @param band the tolerance band that sets the classes.
/// @param data receives the two scalars, one value per returned mesh vertex.
ddf::TriangleMesh errorMapMesh(const ddf::DisplacementField& produced,
                               const planning::ScalarField& deviation,
                               const planning::ToleranceBand& band, io::VtpPointData& data);

}  // namespace ddfcam::cli
