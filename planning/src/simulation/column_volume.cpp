// SPDX-License-Identifier: MIT
// ddfcam: FaceColumnVolume.
#include <ddfcam/planning/simulation/column_volume.h>

namespace ddfcam::planning {
namespace {

double det3(const ddf::Vec3& a, const ddf::Vec3& b, const ddf::Vec3& c) {
  return a.cross(b).dot(c);
}

// Raster sub-triangles of the face incident to (i, k): 6 inside, 3 on an edge, 1 or 2 at a corner.
int incidentTriangles(int n, int i, int k) {
  static constexpr int kRing[6][2] = {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};
  auto valid = [n](int ii, int kk) { return ii >= 0 && kk >= 0 && ii + kk <= n; };
  int count = 0;
  for (int a = 0; a < 6; ++a) {
    const int b = (a + 1) % 6;
    count += valid(i + kRing[a][0], k + kRing[a][1]) && valid(i + kRing[b][0], k + kRing[b][1]);
  }
  return count;
}

}  // namespace

FaceColumnVolume::FaceColumnVolume(const ddf::DisplacementField& field, int face)
    : field_(&field), face_(face) {
  const auto& fv = field.faceVertices(face);
  e1_ = field.position(fv[1]) - field.position(fv[0]);
  e2_ = field.position(fv[2]) - field.position(fv[0]);
  f1_ = field.vector(fv[1]) - field.vector(fv[0]);
  f2_ = field.vector(fv[2]) - field.vector(fv[0]);
  n_ = field.raster().steps();
  nodal_ = 1.0 / (6.0 * n_ * n_);
}

double FaceColumnVolume::column(int i, int k, double h0, double h1) const {
  const ddf::Vec3 v = field_->vectorAt(face_, field_->rasterBary(i, k));
  // det(e1 + h f1, e2 + h f2, v) = j0 + j1 h + j2 h^2, integrated over [h1, h0].
  const double j0 = det3(e1_, e2_, v), j1 = det3(f1_, e2_, v) + det3(e1_, f2_, v),
               j2 = det3(f1_, f2_, v);
  const double integral =
      j0 * (h0 - h1) + j1 * (h0 * h0 - h1 * h1) / 2.0 + j2 * (h0 * h0 * h0 - h1 * h1 * h1) / 3.0;
  return nodal_ * incidentTriangles(n_, i, k) * integral;
}

}  // namespace ddfcam::planning
