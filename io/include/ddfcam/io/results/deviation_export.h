// SPDX-License-Identifier: MIT
// ddfcam: export of a mould/formed comparison: deviation map (.vtp) and deviation vectors (.csv).
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/planning/inspection/surface_comparison.h>

#include <filesystem>
#include <string>

namespace ddfcam::io {

/// @brief Where a deviation lies with respect to @p band: -1 beyond the mould (deviation <
/// band.lowerMm, red), 0 inside the band (green), +1 short of the mould (> band.upperMm, blue);
/// NaN for a NaN deviation.
float toleranceClassOf(double deviationMm, const planning::ToleranceBand& band);

/// @brief The text of a VTK XML PolyData file of the comparison: the mould's raster mesh
/// (ddf::extractRasterMesh of stages[0].ddf with zero heights: one vertex per distinct raster
/// point on the mould, mm, mould frame) with point data "deviation" (signed, mm), "tolerance_class"
/// (toleranceClassOf with comparison.band) and the vectors "deviation_vector" (formed - mould,
/// mm). A shared raster point takes the value of its copy in the lowest-index face.
/// @throws InvalidInput if the comparison's arrays are not sized like stages[0]'s heights (see
/// planning::validateSurfaceComparison).
std::string formatDeviationVtp(const planning::SurfaceComparison& comparison);

/// @brief Writes formatDeviationVtp(@p comparison) to @p path atomically.
/// @throws InvalidInput as formatDeviationVtp; IoError naming @p path if it cannot be written.
void writeDeviationVtp(const planning::SurfaceComparison& comparison,
                       const std::filesystem::path& path);

/// @brief The deviation vectors as CSV text: a header line
/// "x_mm,y_mm,z_mm,dx_mm,dy_mm,dz_mm,deviation_mm", then one row per distinct raster point of
/// stages[0].ddf in raster point order (PointId): the mould point x, y, z, the deviation vector
/// dx, dy, dz (formed - mould) and the signed deviation, all mm, mould frame, '.' decimal point,
/// shortest round-trip form; "nan" where the formed point is missing. A shared raster point
/// takes the values of its copy in the lowest-index face.
/// @throws InvalidInput as formatDeviationVtp.
std::string formatDeviationCsv(const planning::SurfaceComparison& comparison);

/// @brief Writes formatDeviationCsv(@p comparison) to @p path atomically.
/// @throws InvalidInput as formatDeviationCsv; IoError naming @p path if it cannot be written.
void writeDeviationCsv(const planning::SurfaceComparison& comparison,
                       const std::filesystem::path& path);

}  // namespace ddfcam::io
