// SPDX-License-Identifier: MIT
// ddfcam: cube/sphere on a shared support (figs. 9.1/9.3) and the engraved plate (fig. 9.2 a).
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/shared_support_shapes.h>
#include <ddfcam/error.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <utility>

namespace ddfcam::ddf {
namespace {

using Triangles = std::vector<std::array<int, 3>>;

// Welded cube surface on the integer grid [0, s]^3, outward counter-clockwise triangles.
TriangleMesh cubeSurface(double edge, int s, const Vec3& centre) {
  TriangleMesh out;
  std::map<std::array<int, 3>, int> index;
  auto vertex = [&](const std::array<int, 3>& g) {
    const auto [it, added] = index.emplace(g, static_cast<int>(out.vertices.size()));
    if (added) {
      const Vec3 grid(g[0], g[1], g[2]);
      out.vertices.push_back(centre + edge * (grid / s - Vec3::Constant(0.5)));
    }
    return it->second;
  };
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;  // e_b x e_c = e_a
    for (int side = 0; side <= s; side += s) {
      for (int u = 0; u < s; ++u) {
        for (int v = 0; v < s; ++v) {
          std::array<int, 4> q{};
          const std::array<std::array<int, 2>, 4> uv{
              {{u, v}, {u + 1, v}, {u + 1, v + 1}, {u, v + 1}}};
          for (int corner = 0; corner < 4; ++corner) {
            std::array<int, 3> g{};
            g[a] = side, g[b] = uv[corner][0], g[c] = uv[corner][1];
            q[corner] = vertex(g);
          }
          if (side == s) {
            out.triangles.push_back({q[0], q[1], q[2]});
            out.triangles.push_back({q[0], q[2], q[3]});
          } else {
            out.triangles.push_back({q[0], q[2], q[1]});
            out.triangles.push_back({q[0], q[3], q[2]});
          }
        }
      }
    }
  }
  return out;
}

// Icosahedron subdivided @p level times, vertices projected onto the sphere (c, r).
TriangleMesh icosphere(const Vec3& centre, double r, int level) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> p{{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                      {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& q : p) q.normalize();
  Triangles tris{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto [it, added] = mid.emplace(key, static_cast<int>(p.size()));
      if (added) p.push_back((p[a] + p[b]).normalized());
      return it->second;
    };
    Triangles next;
    next.reserve(tris.size() * 4);
    for (const auto& [a, b, c] : tris) {
      const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      next.push_back({a, ab, ca});
      next.push_back({b, bc, ab});
      next.push_back({c, ca, bc});
      next.push_back({ab, bc, ca});
    }
    tris = std::move(next);
  }
  TriangleMesh out;
  out.vertices.reserve(p.size());
  for (const Vec3& q : p) out.vertices.push_back(centre + r * q);
  out.triangles = std::move(tris);
  return out;
}

void checkCubeSphere(const CubeSphereParams& p, double r) {
  const double half = p.edgeMm / 2.0;
  if (!(p.edgeMm > 0.0) || !std::isfinite(p.edgeMm))
    throw InvalidInput("cubeSphereMorph: edge " + std::to_string(p.edgeMm) + " mm (must be > 0)");
  if (p.subdivisions < 1 || p.resolution < 2 || p.sphereLevel < 1 || p.sphereLevel > 7)
    throw InvalidInput(
        "cubeSphereMorph: subdivisions >= 1, resolution >= 2 and sphere level "
        "1..7 required");
  if (!(p.vectorReach > 1.0) || !std::isfinite(p.vectorReach))
    throw InvalidInput("cubeSphereMorph: vector reach " + std::to_string(p.vectorReach) +
                       " (must exceed 1)");
  if (!p.centreMm.allFinite() || !std::isfinite(r) || r <= 0.0 ||
      (r >= half && r <= half * std::sqrt(3.0))) {
    throw InvalidInput("cubeSphereMorph: sphere radius " + std::to_string(r) +
                       " mm must lie outside [edge/2, edge sqrt(3)/2] (a radial vector would "
                       "vanish)");
  }
}

void checkPlate(const EngravedPlateParams& p) {
  if (!(p.sizeMm > 0.0) || p.subdivisions < 1 || p.resolution < 2 || !(p.depthMm > 0.0) ||
      !(p.grooveWidthMm > 0.0) || !(p.ringSpacingMm > 0.0) || p.ringCount < 0)
    throw InvalidInput(
        "engravedPlate: size, depth, groove width and ring spacing must be > 0, "
        "subdivisions >= 1, resolution >= 2, ring count >= 0");
  if (!(p.vectorLengthMm > p.depthMm) || !std::isfinite(p.vectorLengthMm))
    throw InvalidInput("engravedPlate: vector length " + std::to_string(p.vectorLengthMm) +
                       " mm must exceed the depth " + std::to_string(p.depthMm) + " mm");
}

// Square plate grid on [-size/2, size/2]^2 at z = 0, counter-clockwise seen from +z.
TriangleMesh plateGrid(double size, int s) {
  TriangleMesh out;
  for (int j = 0; j <= s; ++j)
    for (int i = 0; i <= s; ++i)
      out.vertices.emplace_back(size * (double(i) / s - 0.5), size * (double(j) / s - 0.5), 0.0);
  auto at = [s](int i, int j) { return j * (s + 1) + i; };
  for (int j = 0; j < s; ++j) {
    for (int i = 0; i < s; ++i) {
      out.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      out.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return out;
}

}  // namespace

CubeSphereMorph cubeSphereMorph(const CubeSphereParams& params) {
  const double r = params.sphereRadiusMm == 0.0 ? params.edgeMm : params.sphereRadiusMm;
  checkCubeSphere(params, r);
  const TriangleMesh cube = cubeSurface(params.edgeMm, params.subdivisions, params.centreMm);
  std::vector<Vec3> vectors;
  vectors.reserve(cube.vertices.size());
  for (const Vec3& p : cube.vertices) {
    const Vec3 d = p - params.centreMm;
    const double dist = d.norm();
    vectors.push_back(params.vectorReach * (r - dist) * (d / dist));
  }
  CubeSphereMorph out;
  out.sphereRadiusMm = r;
  out.ddf = DisplacementField(makeSupportMesh(cube.vertices, cube.triangles), std::move(vectors),
                              params.resolution, 0.0f);
  out.sphereMesh = icosphere(params.centreMm, r, params.sphereLevel);
  const CrustHash hash(out.ddf);
  const FillReport report = fillFromMesh(out.ddf, hash, out.sphereMesh);
  if (report.missing > 0) {
    throw InvalidInput("cubeSphereMorph: " + std::to_string(report.missing) +
                       " stubbles miss the sphere mesh; raise vectorReach or sphereLevel");
  }
  out.sphereHeights = out.ddf.allHeights();
  out.cubeHeights.assign(out.sphereHeights.size(), 0.0f);
  out.ddf.allHeights() = out.cubeHeights;
  return out;
}

std::vector<float> morphHeights(std::span<const float> h0, std::span<const float> h1, double t) {
  if (h0.size() != h1.size()) {
    throw InvalidInput("morphHeights: " + std::to_string(h0.size()) + " start heights but " +
                       std::to_string(h1.size()) + " goal heights");
  }
  std::vector<float> out(h0.size());
  for (std::size_t i = 0; i < h0.size(); ++i)
    out[i] = static_cast<float>((1.0 - t) * h0[i] + t * h1[i]);
  return out;
}

double engravingDepthMm(const EngravedPlateParams& params, double x, double y) {
  const double w = params.grooveWidthMm;
  auto groove = [&](double d) {
    d = std::abs(d);
    if (d >= 0.5 * w) return 0.0;
    const double c = std::cos(std::numbers::pi * d / w);
    return params.depthMm * c * c;
  };
  double depth = params.straightGroove ? groove(y) : 0.0;
  const double r = std::hypot(x, y);
  for (int k = 1; k <= params.ringCount; ++k)
    depth = std::max(depth, groove(r - k * params.ringSpacingMm));
  return depth;
}

DisplacementField engravedPlate(const EngravedPlateParams& params) {
  checkPlate(params);
  const TriangleMesh grid = plateGrid(params.sizeMm, params.subdivisions);
  std::vector<Vec3> vectors(grid.vertices.size(), Vec3(0.0, 0.0, params.vectorLengthMm));
  DisplacementField ddf(makeSupportMesh(grid.vertices, grid.triangles), std::move(vectors),
                        params.resolution, 0.0f);
  const Raster& raster = ddf.raster();
  const int n = raster.steps();
  for (int f = 0; f < ddf.faceCount(); ++f) {
    auto heights = ddf.heights(f);
    for (int k = 0; k <= n; ++k) {
      for (int i = 0; i + k <= n; ++i) {
        const Vec3 g = ddf.basePoint(f, ddf.rasterBary(i, k));
        heights[raster.index(i, k)] =
            static_cast<float>(-engravingDepthMm(params, g.x(), g.y()) / params.vectorLengthMm);
      }
    }
  }
  ddf.synchronizeShared(SharedPolicy::Canonical);
  return ddf;
}

}  // namespace ddfcam::ddf
