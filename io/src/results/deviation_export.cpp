// SPDX-License-Identifier: MIT
// ddfcam: deviation map (.vtp) and deviation vectors (.csv) of a mould/formed comparison.
#include <ddfcam/io/results/deviation_export.h>

#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/error.h>
#include <ddfcam/io/results/vtp_writer.h>
#include <ddfcam/planning/mould/mould_study.h>

#include "../common/file_access.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace ddfcam::io {
namespace {

/// The mould's raster mesh and, per mesh vertex, the copy index (layout of allHeights()) whose
/// values it shows: the copy in the lowest-index face.
struct DeviationPoints {
  ddf::TriangleMesh mesh;
  std::vector<std::size_t> copy;
};

DeviationPoints deviationPoints(const planning::SurfaceComparison& comparison) {
  planning::validateSurfaceComparison(comparison);
  ddf::DisplacementField mould = comparison.sequence.stages.front().ddf;
  std::fill(mould.allHeights().begin(), mould.allHeights().end(), 0.0f);
  ddf::RasterMesh raster = ddf::extractRasterMesh(mould);
  DeviationPoints out{std::move(raster.mesh), {}};
  out.copy.reserve(raster.vertexPoint.size());
  const std::size_t perFace = mould.pointsPerFace();
  for (const ddf::PointId p : raster.vertexPoint) {
    ddf::PointCopy lowest{std::numeric_limits<int>::max(), 0};
    mould.topology().forEachCopy(p, [&](ddf::PointCopy c) {
      if (c.face < lowest.face) lowest = c;
    });
    out.copy.push_back(static_cast<std::size_t>(lowest.face) * perFace + lowest.local);
  }
  return out;
}

// Shortest form that reads back to the same value: floats stay short ("0.1", not the digits
// of the double nearest to 0.1f).
template <class T>
void appendNumber(std::string& out, T value) {
  if (std::isnan(value)) {
    out += "nan";
    return;
  }
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

}  // namespace

float toleranceClassOf(double deviationMm, const planning::ToleranceBand& band) {
  if (std::isnan(deviationMm)) return std::numeric_limits<float>::quiet_NaN();
  if (deviationMm < band.lowerMm) return -1.0f;
  return deviationMm > band.upperMm ? 1.0f : 0.0f;
}

std::string formatDeviationVtp(const planning::SurfaceComparison& comparison) {
  const DeviationPoints points = deviationPoints(comparison);
  VtpScalarArray deviation{"deviation", {}};
  VtpScalarArray toleranceClass{"tolerance_class", {}};
  VtpVectorArray vectors{"deviation_vector", {}};
  for (const std::size_t c : points.copy) {
    const float value = comparison.deviation.values[c];
    deviation.values.push_back(value);
    toleranceClass.values.push_back(toleranceClassOf(value, comparison.band));
    vectors.values.push_back(comparison.deviationVectors[c]);
  }
  VtpPointData data;
  data.scalars = {std::move(deviation), std::move(toleranceClass)};
  data.vectors = {std::move(vectors)};
  return formatVtp(points.mesh, data);
}

void writeDeviationVtp(const planning::SurfaceComparison& comparison,
                       const std::filesystem::path& path) {
  detail::writeFileAtomically(path, formatDeviationVtp(comparison));
}

std::string formatDeviationCsv(const planning::SurfaceComparison& comparison) {
  const DeviationPoints points = deviationPoints(comparison);
  std::string out = "x_mm,y_mm,z_mm,dx_mm,dy_mm,dz_mm,deviation_mm\n";
  for (std::size_t v = 0; v < points.copy.size(); ++v) {
    const std::size_t c = points.copy[v];
    const ddf::Vec3& d = comparison.deviationVectors[c];
    for (const double value : {points.mesh.vertices[v].x(), points.mesh.vertices[v].y(),
                               points.mesh.vertices[v].z(), d.x(), d.y(), d.z()}) {
      appendNumber(out, value);
      out += ',';
    }
    appendNumber(out, comparison.deviation.values[c]);
    out += '\n';
  }
  return out;
}

void writeDeviationCsv(const planning::SurfaceComparison& comparison,
                       const std::filesystem::path& path) {
  detail::writeFileAtomically(path, formatDeviationCsv(comparison));
}

}  // namespace ddfcam::io
