// SPDX-License-Identifier: MIT
// ddfcam: the unit normal of a DDF's represented raster surface at a raster point.
#include <ddfcam/ddf/raster_normal.h>

namespace ddfcam::ddf {

Vec3 rasterNormal(const DisplacementField& ddf, int f, int i, int k) {
  static constexpr int kRing[6][2] = {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};
  const int n = ddf.raster().steps();
  auto valid = [n](int ii, int kk) { return ii >= 0 && kk >= 0 && ii + kk <= n; };
  const Vec3 q = ddf.surfacePoint(f, i, k);
  Vec3 normal = Vec3::Zero();
  for (int a = 0; a < 6; ++a) {
    const int b = (a + 1) % 6;
    const int ia = i + kRing[a][0], ka = k + kRing[a][1];
    const int ib = i + kRing[b][0], kb = k + kRing[b][1];
    if (!valid(ia, ka) || !valid(ib, kb)) continue;
    normal += (ddf.surfacePoint(f, ia, ka) - q).cross(ddf.surfacePoint(f, ib, kb) - q);
  }
  const Vec3 v = ddf.vectorAt(f, ddf.rasterBary(i, k));
  if (normal.squaredNorm() == 0.0) return v.normalized();
  normal.normalize();
  return normal.dot(v) < 0.0 ? Vec3(-normal) : normal;
}

}  // namespace ddfcam::ddf
