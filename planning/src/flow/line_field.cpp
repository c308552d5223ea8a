// SPDX-License-Identifier: MIT
// ddfcam: operations on tangent line fields.
#include <ddfcam/error.h>
#include <ddfcam/planning/flow/line_field.h>
#include <ddfcam/planning/lines/streamline_path.h>

#include <string>

namespace ddfcam::planning {

LineField transverseField(const ddf::DisplacementField& ddf, const LineField& field) {
  if (field.size() != ddf.allHeights().size()) {
    throw InvalidInput("transverseField: line field has " + std::to_string(field.size()) +
                       " entries, expected " + std::to_string(ddf.allHeights().size()));
  }
  LineField out(field.size(), ddf::Vec3::Zero());
  const ddf::Raster& raster = ddf.raster();
  const int n = raster.steps();
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const std::size_t e =
            static_cast<std::size_t>(f) * ddf.pointsPerFace() + raster.index(i, k);
        if (!(field[e].squaredNorm() > 0.0)) continue;
        const ddf::Vec3 t = surfaceNormal(ddf, {f, ddf.rasterBary(i, k)}).cross(field[e]);
        if (t.squaredNorm() > 0.0) out[e] = t.normalized();
      }
  return out;
}

}  // namespace ddfcam::planning
