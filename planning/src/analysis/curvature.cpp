// SPDX-License-Identifier: MIT
// ddfcam: principal curvatures and directions at every raster point of a DDF (sec. 8.2).
#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/analysis/design_curvature.h>
#include <ddfcam/planning/analysis/vertex_curvature.h>

#include "curvature_extension.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace ddfcam::planning {

namespace {

using ddf::Vec3;

struct PointCurvature {
  double kMax = 0.0;
  double kMin = 0.0;
  Vec3 dirMax = Vec3::Zero();
  Vec3 dirMin = Vec3::Zero();
};

// Height derivatives with respect to the face parameters u = j / n, v = k / n.
struct HeightJet {
  double h, hu, hv, huu, huv, hvv;
};

// Fourth-order central differences (5 points, step d, eq. 8.2) along the three lattice
// directions u, v and u - v; the mixed derivative comes from the third one, which keeps every
// sample within 2 d steps of the face. Truncation is O(d^4 / n^4): second-order stencils left
// k errors ~2x those of a 2-ring quadric fit at equal spacing.
HeightJet heightJet(const detail::ExtendedRaster& e, int d, int j, int k) {
  const double step = static_cast<double>(d) / e.n;
  const double h = e.at(j, k);
  auto line = [&](int dj, int dk, double& first, double& second) {
    const double p1 = e.at(j + dj, k + dk), m1 = e.at(j - dj, k - dk);
    const double p2 = e.at(j + 2 * dj, k + 2 * dk), m2 = e.at(j - 2 * dj, k - 2 * dk);
    first = (8.0 * (p1 - m1) - (p2 - m2)) / (12.0 * step);
    second = (16.0 * (p1 + m1) - (p2 + m2) - 30.0 * h) / (12.0 * step * step);
  };
  HeightJet jet{h, 0.0, 0.0, 0.0, 0.0, 0.0};
  double hw = 0.0, hww = 0.0;
  line(d, 0, jet.hu, jet.huu);
  line(0, d, jet.hv, jet.hvv);
  line(d, -d, hw, hww);
  jet.huv = 0.5 * (jet.huu + jet.hvv - hww);
  return jet;
}

// Frame of one face: vertices and vectors in local order.
struct FaceFrame {
  Vec3 p1, gu, gv;  // g = p1 + u gu + v gv
  Vec3 v1, vu, vv;  // vector = v1 + u vu + v vv
};

FaceFrame frameOf(const ddf::DisplacementField& ddf, int face) {
  const auto& vs = ddf.faceVertices(face);
  const Vec3 &p1 = ddf.position(vs[0]), &p2 = ddf.position(vs[1]), &p3 = ddf.position(vs[2]);
  const Vec3 &v1 = ddf.vector(vs[0]), &v2 = ddf.vector(vs[1]), &v3 = ddf.vector(vs[2]);
  return {p1, p2 - p1, p3 - p1, v1, v2 - v1, v3 - v1};
}

// Eigen-decomposition of the symmetric shape operator [s11 s12; s12 s22] given in the
// orthonormal tangent frame (e1, e2); the kMax eigenvector comes from whichever row of
// S - kMax I is better conditioned, without trigonometry.
PointCurvature principal(double s11, double s12, double s22, const Vec3& e1, const Vec3& e2,
                         const Vec3& normal) {
  const double mean = 0.5 * (s11 + s22);
  const double half = 0.5 * (s11 - s22);
  const double radius = std::sqrt(half * half + s12 * s12);
  double x = half >= 0.0 ? half + radius : s12, y = half >= 0.0 ? s12 : radius - half;
  const double length = std::sqrt(x * x + y * y);
  if (length > 0.0) {
    x /= length;
    y /= length;
  } else {
    x = 1.0;  // isotropic: any tangent will do, the umbilic flag says so
    y = 0.0;
  }
  PointCurvature pc;
  pc.kMax = mean + radius;
  pc.kMin = mean - radius;
  pc.dirMax = x * e1 + y * e2;
  pc.dirMin = normal.cross(pc.dirMax);
  return pc;
}

// Fundamental forms of q = g + h v and the eigen-decomposition of the shape operator in an
// orthonormal tangent frame; kappa = -II with the normal on the +v (tool) side.
PointCurvature curvatureAt(const FaceFrame& fr, double u, double v, const HeightJet& jet) {
  const Vec3 vb = fr.v1 + u * fr.vu + v * fr.vv;
  const Vec3 qu = fr.gu + jet.h * fr.vu + jet.hu * vb;
  const Vec3 qv = fr.gv + jet.h * fr.vv + jet.hv * vb;
  const Vec3 quu = 2.0 * jet.hu * fr.vu + jet.huu * vb;
  const Vec3 qvv = 2.0 * jet.hv * fr.vv + jet.hvv * vb;
  const Vec3 quv = jet.hu * fr.vv + jet.hv * fr.vu + jet.huv * vb;
  Vec3 normal = qu.cross(qv).normalized();
  if (normal.dot(vb) < 0.0) normal = -normal;
  const Vec3 e1 = qu.normalized();
  const Vec3 e2 = normal.cross(e1);
  // q_u = (a11, 0), q_v = (a12, a22) in (e1, e2); S = J^-T (-II) J^-1 with J = [a11 a12; 0 a22].
  const double a11 = qu.norm(), a12 = qv.dot(e1), a22 = qv.dot(e2);
  const double L = -quu.dot(normal), M = -quv.dot(normal), N = -qvv.dot(normal);
  const double i11 = 1.0 / a11, i12 = -a12 / (a11 * a22), i22 = 1.0 / a22;
  const double s11 = i11 * i11 * L;
  const double s12 = i11 * (i12 * L + i22 * M);
  const double s22 = i12 * i12 * L + 2.0 * i12 * i22 * M + i22 * i22 * N;
  return principal(s11, s12, s22, e1, e2, normal);
}

void computeFace(const ddf::DisplacementField& ddf, int face, int d, const CurvatureParams& params,
                 detail::ExtendedRaster& ext, CurvatureField& out) {
  detail::fillExtendedRaster(ddf, face, 2 * d, ext);
  const FaceFrame fr = frameOf(ddf, face);
  const ddf::Raster& raster = ddf.raster();
  const int n = raster.steps();
  const std::size_t base = static_cast<std::size_t>(face) * ddf.pointsPerFace();
  for (int k = 0; k <= n; ++k) {
    for (int i = 0; i <= n - k; ++i) {
      const int j = n - i - k;
      const PointCurvature pc = curvatureAt(fr, static_cast<double>(j) / n,
                                            static_cast<double>(k) / n, heightJet(ext, d, j, k));
      const std::size_t at = base + raster.index(i, k);
      out.kMax[at] = static_cast<float>(pc.kMax);
      out.kMin[at] = static_cast<float>(pc.kMin);
      out.mean[at] = static_cast<float>(0.5 * (pc.kMax + pc.kMin));
      out.gaussian[at] = static_cast<float>(pc.kMax * pc.kMin);
      out.dirMax[at] = pc.dirMax;
      out.dirMin[at] = pc.dirMin;
      const double scale = std::max(std::abs(pc.kMax), std::abs(pc.kMin));
      out.umbilic[at] =
          pc.kMax - pc.kMin <= params.umbilicTolerance * scale + params.flatCurvaturePerMm;
    }
  }
}

int resolveStep(const ddf::DisplacementField& ddf, const CurvatureParams& params) {
  if (ddf.faceCount() == 0) throw InvalidInput("computeCurvature: the DDF has no faces");
  if (params.step < 0)
    throw InvalidInput("computeCurvature: step " + std::to_string(params.step) +
                       " must be >= 0 (0 = automatic)");
  const int m = ddf.resolution();
  const int d = params.step == 0 ? automaticCurvatureStep(m) : params.step;
  if (m < 4 || 3 * d > m - 1)
    throw InvalidInput("computeCurvature: step " + std::to_string(d) +
                       " needs m >= 4 and 3 d <= m - 1, but m = " + std::to_string(m));
  return d;
}

}  // namespace

int automaticCurvatureStep(int m) {
  // (48 * 2^-24)^(1/4): see the header for the error balance behind it.
  const double delta = std::pow(48.0 * std::ldexp(1.0, -24), 0.25);
  return std::max(1, static_cast<int>(std::lround((m - 1) * delta)));
}

CurvatureField computeCurvature(const ddf::DisplacementField& ddf, const CurvatureParams& params) {
  const bool automatic = params.method == CurvatureMethod::Automatic;
  const bool flat = automatic && ddf.faceCount() > 0 && hasFlatFaces(ddf);
  if (params.method == CurvatureMethod::DesignMeshFit ||
      (automatic && !flat && params.designMesh && !params.designMesh->triangles.empty())) {
    if (!params.designMesh)
      throw InvalidInput("computeCurvature: the design-mesh fit needs CurvatureParams::designMesh");
    return computeDesignCurvature(ddf, *params.designMesh, params);
  }
  if (params.method == CurvatureMethod::VertexQuadricFit || flat) {
    VertexCurvatureParams vertexParams;
    vertexParams.umbilicTolerance = params.umbilicTolerance;
    vertexParams.flatCurvaturePerMm = params.flatCurvaturePerMm;
    vertexParams.faceLabels = params.faceLabels;
    vertexParams.parallel = params.parallel;
    vertexParams.progress = params.progress;
    return computeVertexCurvature(ddf, vertexParams);
  }
  const int d = resolveStep(ddf, params);
  const std::size_t count = ddf.allHeights().size();
  CurvatureField out;
  out.step = d;
  out.kMax.resize(count);
  out.kMin.resize(count);
  out.mean.resize(count);
  out.gaussian.resize(count);
  out.dirMax.resize(count);
  out.dirMin.resize(count);
  out.umbilic.resize(count);
  // Progress and cancellation are polled from the calling thread between blocks of faces.
  const int faces = ddf.faceCount();
  const int block = params.parallel ? 256 : 64;
  for (int first = 0; first < faces; first += block) {
    reportProgress(params.progress, static_cast<double>(first) / faces);
    const int last = std::min(faces, first + block);
    if (params.parallel) {
      tbb::parallel_for(tbb::blocked_range<int>(first, last),
                        [&](const tbb::blocked_range<int>& r) {
                          detail::ExtendedRaster ext;
                          for (int f = r.begin(); f != r.end(); ++f)
                            computeFace(ddf, f, d, params, ext, out);
                        });
    } else {
      detail::ExtendedRaster ext;
      for (int f = first; f < last; ++f) computeFace(ddf, f, d, params, ext, out);
    }
  }
  reportProgress(params.progress, 1.0);
  return out;
}

ScalarField curvatureScalarField(const CurvatureField& field, CurvatureQuantity quantity) {
  switch (quantity) {
    case CurvatureQuantity::KMax:
      return {"k_max", "1/mm", true, field.kMax, {}};
    case CurvatureQuantity::KMin:
      return {"k_min", "1/mm", true, field.kMin, {}};
    case CurvatureQuantity::Mean:
      return {"mean curvature", "1/mm", true, field.mean, {}};
    case CurvatureQuantity::Gaussian:
      return {"Gaussian curvature", "1/mm^2", true, field.gaussian, {}};
  }
  throw InvalidInput("curvatureScalarField: unknown quantity " +
                     std::to_string(static_cast<int>(quantity)));
}

}  // namespace ddfcam::planning

namespace ddfcam::planning {

CurvatureParams partCurvatureParams(const Project& project) {
  CurvatureParams params;
  if (project.part &&
      project.cadFaceOfSupportFace.size() == static_cast<std::size_t>(project.part->faceCount()))
    params.faceLabels = project.cadFaceOfSupportFace;
  if (!project.sourcePath.empty() && project.designMesh && !project.designMesh->triangles.empty())
    params.designMesh = std::make_shared<const ddf::TriangleMesh>(*project.designMesh);
  return params;
}

}  // namespace ddfcam::planning
