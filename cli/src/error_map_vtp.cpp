// SPDX-License-Identifier: MIT
// ddfcam-cli: the error map of a produced surface as a .vtp mesh (simulate and run commands).
#include <ddfcam/ddf/raster_mesh.h>

#include "error_map_vtp.h"

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace ddfcam::cli {

ddf::TriangleMesh errorMapMesh(const ddf::DisplacementField& produced,
                               const planning::ScalarField& deviation,
                               const planning::ToleranceBand& band, io::VtpPointData& data) {
  ddf::RasterMesh raster = ddf::extractRasterMesh(produced);
  const std::size_t perFace = produced.pointsPerFace();
  std::vector<float> values, classes;
  values.reserve(raster.vertexPoint.size());
  classes.reserve(raster.vertexPoint.size());
  for (const ddf::PointId p : raster.vertexPoint) {
    int face = produced.faceCount();
    float value = std::numeric_limits<float>::quiet_NaN();
    produced.topology().forEachCopy(p, [&](ddf::PointCopy c) {
      if (c.face >= face) return;
      face = c.face;
      value = deviation.values[static_cast<std::size_t>(c.face) * perFace + c.local];
    });
    values.push_back(value);
    const planning::ToleranceClass cls = planning::classify(value, band);
    classes.push_back(std::isnan(value)                               ? value
                      : cls == planning::ToleranceClass::Overcut      ? -1.0f
                      : cls == planning::ToleranceClass::MaterialLeft ? 1.0f
                                                                      : 0.0f);
  }
  data.scalars.push_back({"deviation_mm", std::move(values)});
  data.scalars.push_back({"tolerance_class", std::move(classes)});
  return std::move(raster.mesh);
}

}  // namespace ddfcam::cli
