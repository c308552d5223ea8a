// SPDX-License-Identifier: MIT
// ddfcam: ready-made DDFs of analytic surfaces with their exact surface (test parts, demo part).
#include <ddfcam/ddf/analytic_generators.h>
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

void require(bool ok, const std::string& what) {
  if (!ok) throw InvalidInput(what);
}

void requireFraction(double fraction, const char* generator) {
  require(fraction > 0.0 && fraction < 1.0,
          std::string(generator) + ": crust/curvature fraction must lie in (0, 1)");
}

/// Triangles of an nu x nv quad grid over parameters (a, b), two per quad, counter-clockwise
/// in (a, b) so the front side is d/da x d/db. A periodic direction wraps around instead of
/// repeating its first vertex column. Vertex (a, b) has index b * columns + a.
Triangles gridTriangles(int nu, int nv, bool periodicU, bool periodicV) {
  const int columns = periodicU ? nu : nu + 1;
  const int rows = periodicV ? nv : nv + 1;
  auto at = [&](int a, int b) { return (b % rows) * columns + (a % columns); };
  Triangles triangles;
  triangles.reserve(2 * static_cast<std::size_t>(nu) * nv);
  for (int b = 0; b < nv; ++b) {
    for (int a = 0; a < nu; ++a) {
      triangles.push_back({at(a, b), at(a + 1, b), at(a + 1, b + 1)});
      triangles.push_back({at(a, b), at(a + 1, b + 1), at(a, b + 1)});
    }
  }
  return triangles;
}

/// Unit icosahedron refined @p levels times by midpoint splitting, midpoints pushed onto the
/// unit sphere; faces oriented outwards.
std::pair<std::vector<Vec3>, Triangles> unitIcosphere(int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> points = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                              {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                              {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& p : points) p.normalize();
  Triangles triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                         {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                         {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                         {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto [it, inserted] = midpoints.try_emplace(key, static_cast<int>(points.size()));
      if (inserted) points.push_back((points[a] + points[b]).normalized());
      return it->second;
    };
    Triangles finer;
    finer.reserve(4 * triangles.size());
    for (const auto& [a, b, c] : triangles) {
      const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      finer.insert(finer.end(), {{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {ab, bc, ca}});
    }
    triangles = std::move(finer);
  }
  // The vertex table is the classic outward list; enforce it so a typo cannot flip a face.
  for (auto& tri : triangles) {
    const Vec3 n = (points[tri[1]] - points[tri[0]]).cross(points[tri[2]] - points[tri[0]]);
    if (n.dot(points[tri[0]] + points[tri[1]] + points[tri[2]]) < 0.0) std::swap(tri[1], tri[2]);
  }
  return {std::move(points), std::move(triangles)};
}

/// Largest |principal curvature| of @p surface over the vertices and cell centres of the grid.
double maxAbsCurvature(const HeightFieldSurface& surface, const GraphPatchParams& p) {
  double kmax = 0.0;
  for (int b = 0; b <= 2 * p.cellsY; ++b) {
    for (int a = 0; a <= 2 * p.cellsX; ++a) {
      const double x = p.origin.x() + 0.5 * a * p.size.x() / p.cellsX;
      const double y = p.origin.y() + 0.5 * b * p.size.y() / p.cellsY;
      const auto [k1, k2] = surface.principalCurvatures(x, y);
      kmax = std::max({kmax, std::abs(k1), std::abs(k2)});
    }
  }
  return kmax;
}

/// Support on the surface over the grid of @p p and exact normals of length @p length.
std::pair<SupportMesh, std::vector<Vec3>> graphSupport(const HeightFieldSurface& surface,
                                                       const GraphPatchParams& p, double length) {
  std::vector<Vec3> points, vectors;
  for (int b = 0; b <= p.cellsY; ++b) {
    for (int a = 0; a <= p.cellsX; ++a) {
      const double x = p.origin.x() + a * p.size.x() / p.cellsX;
      const double y = p.origin.y() + b * p.size.y() / p.cellsY;
      points.push_back(surface.pointAbove(x, y));
      vectors.push_back(surface.normal(points.back()) * length);
    }
  }
  return {makeSupportMesh(points, gridTriangles(p.cellsX, p.cellsY, false, false)),
          std::move(vectors)};
}

void validateGraph(const GraphPatchParams& p, const char* generator) {
  const std::string who(generator);
  require(p.size.x() > 0.0 && p.size.y() > 0.0, who + ": grid size must be positive");
  require(p.cellsX >= 1 && p.cellsY >= 1, who + ": grid needs at least one cell per direction");
  require(p.m >= 2, who + ": raster resolution m must be >= 2");
  require(p.maxVectorLengthMm > 0.0, who + ": maxVectorLengthMm must be positive");
  requireFraction(p.curvatureFraction, generator);
}

/// The vector length rule of GraphPatchParams.
double graphVectorLength(const HeightFieldSurface& surface, const GraphPatchParams& p) {
  const double kmax = maxAbsCurvature(surface, p);
  return kmax > 0.0 ? std::min(p.maxVectorLengthMm, p.curvatureFraction / kmax)
                    : p.maxVectorLengthMm;
}

}  // namespace

GeneratedSurface planePatch(const PlanePatchParams& p) {
  require(p.size.x() > 0.0 && p.size.y() > 0.0, "planePatch: size must be positive");
  require(p.cellsX >= 1 && p.cellsY >= 1, "planePatch: needs at least one cell per direction");
  require(p.vectorLengthMm > 0.0, "planePatch: vectorLengthMm must be positive");
  require(std::abs(p.planeZMm) < p.vectorLengthMm,
          "planePatch: |planeZMm| must be below vectorLengthMm (inside the crust)");
  std::vector<Vec3> points;
  for (int b = 0; b <= p.cellsY; ++b) {
    for (int a = 0; a <= p.cellsX; ++a) {
      points.emplace_back(p.origin.x() + a * p.size.x() / p.cellsX,
                          p.origin.y() + b * p.size.y() / p.cellsY, 0.0);
    }
  }
  const SupportMesh mesh = makeSupportMesh(points, gridTriangles(p.cellsX, p.cellsY, false, false));
  std::vector<Vec3> vectors(points.size(), Vec3(0.0, 0.0, p.vectorLengthMm));
  return fromAnalytic(mesh, std::move(vectors), p.m, std::make_shared<PlaneSurface>(p.planeZMm));
}

GeneratedSurface spherePart(const SphereParams& p) {
  auto surface = std::make_shared<SphereSurface>(p.radiusMm);
  require(p.subdivisions >= 0 && p.subdivisions <= 7, "spherePart: subdivisions must be 0..7");
  requireFraction(p.crustFraction, "spherePart");
  auto [points, triangles] = unitIcosphere(p.subdivisions);
  std::vector<Vec3> vectors;
  vectors.reserve(points.size());
  for (Vec3& q : points) {
    vectors.push_back(q * (p.crustFraction * p.radiusMm));
    q *= p.radiusMm;
  }
  return fromAnalytic(makeSupportMesh(points, triangles), std::move(vectors), p.m, surface);
}

GeneratedSurface cylinderPart(const CylinderParams& p) {
  auto surface = std::make_shared<CylinderSurface>(p.radiusMm);
  require(p.lengthMm > 0.0, "cylinderPart: length must be positive");
  require(p.segments >= 3 && p.rings >= 1, "cylinderPart: needs >= 3 segments and >= 1 ring");
  requireFraction(p.crustFraction, "cylinderPart");
  std::vector<Vec3> points, vectors;
  for (int b = 0; b <= p.rings; ++b) {
    for (int a = 0; a < p.segments; ++a) {
      const double angle = 2.0 * std::numbers::pi * a / p.segments;
      const Vec3 radial(std::cos(angle), std::sin(angle), 0.0);
      points.push_back(p.radiusMm * radial + Vec3(0.0, 0.0, p.lengthMm * b / p.rings));
      vectors.push_back(p.crustFraction * p.radiusMm * radial);
    }
  }
  const Triangles triangles = gridTriangles(p.segments, p.rings, true, false);
  return fromAnalytic(makeSupportMesh(points, triangles), std::move(vectors), p.m, surface);
}

GeneratedSurface torusPart(const TorusParams& p) {
  auto surface = std::make_shared<TorusSurface>(p.majorRadiusMm, p.minorRadiusMm);
  require(p.segmentsU >= 3 && p.segmentsV >= 3, "torusPart: needs >= 3 segments each way");
  requireFraction(p.crustFraction, "torusPart");
  const double length =
      p.crustFraction * std::min(p.minorRadiusMm, p.majorRadiusMm - p.minorRadiusMm);
  std::vector<Vec3> points, vectors;
  for (int b = 0; b < p.segmentsV; ++b) {
    for (int a = 0; a < p.segmentsU; ++a) {
      const double u = 2.0 * std::numbers::pi * a / p.segmentsU,
                   v = 2.0 * std::numbers::pi * b / p.segmentsV;
      points.push_back(surface->point(u, v));
      vectors.emplace_back(length * std::cos(v) * std::cos(u), length * std::cos(v) * std::sin(u),
                           length * std::sin(v));
    }
  }
  const Triangles triangles = gridTriangles(p.segmentsU, p.segmentsV, true, true);
  return fromAnalytic(makeSupportMesh(points, triangles), std::move(vectors), p.m, surface);
}

GeneratedSurface graphPatch(std::shared_ptr<const HeightFieldSurface> surface,
                            const GraphPatchParams& p) {
  require(surface != nullptr, "graphPatch: no surface given");
  validateGraph(p, "graphPatch");
  auto [mesh, vectors] = graphSupport(*surface, p, graphVectorLength(*surface, p));
  return fromAnalytic(mesh, std::move(vectors), p.m, std::move(surface));
}

GeneratedSurface saddlePatch(const SaddleParams& p) {
  return graphPatch(std::make_shared<SaddleSurface>(p.a, p.b), p.grid);
}

GeneratedSurface sinSinPatch(const SinSinParams& p) {
  return graphPatch(std::make_shared<SinSinSurface>(p.amplitudeMm, p.scaleMm), p.grid);
}

namespace {

// Sampling grid over the rectangle of a B-spline patch (free-form patch, demo part).
template <class Params>
GraphPatchParams gridOver(const Params& p) {
  return {.origin = p.shape.origin,
          .size = p.shape.size,
          .cellsX = p.cellsX,
          .cellsY = p.cellsY,
          .m = p.m,
          .maxVectorLengthMm = p.maxVectorLengthMm,
          .curvatureFraction = p.curvatureFraction};
}

}  // namespace

GeneratedSurface freeformPatch(const FreeformPatchParams& p) {
  const GraphPatchParams grid = gridOver(p);
  return graphPatch(std::make_shared<BSplinePatch>(makeBumpPatch(p.shape)), grid);
}

GeneratedSurface demoPart(const DemoPartParams& p) {
  const GraphPatchParams grid = gridOver(p);
  validateGraph(grid, "demoPart");
  auto design = std::make_shared<BSplinePatch>(makeBumpPatch(p.shape));
  const double length = graphVectorLength(*design, grid);
  // Along a normal stubble the stock lies a / W <= a above the design; the margin covers the
  // interpolated (not exactly normal) vectors inside the faces.
  require(p.allowanceMm >= 0.0 && p.allowanceMm < 0.9 * length,
          "demoPart: allowanceMm must lie in [0, 0.9 L) with L = " + std::to_string(length) +
              " mm the vector length");
  auto [mesh, vectors] = graphSupport(*design, grid, length);
  auto stock = std::make_shared<RaisedHeightField>(design, p.allowanceMm);
  GeneratedSurface out = fromAnalytic(mesh, std::move(vectors), p.m, std::move(stock));
  out.design = std::move(design);
  return out;
}

GeneratedSurface ellipsoidPart(const EllipsoidParams& p) {
  auto surface = std::make_shared<EllipsoidSurface>(p.axesMm.x(), p.axesMm.y(), p.axesMm.z());
  require(p.subdivisions >= 0 && p.subdivisions <= 7, "ellipsoidPart: subdivisions must be 0..7");
  requireFraction(p.crustFraction, "ellipsoidPart");
  const double rmin = p.axesMm.minCoeff() * p.axesMm.minCoeff() / p.axesMm.maxCoeff();
  auto [points, triangles] = unitIcosphere(p.subdivisions);
  std::vector<Vec3> vectors;
  vectors.reserve(points.size());
  for (Vec3& q : points) {
    q = q.cwiseProduct(p.axesMm);
    vectors.push_back(surface->normal(q) * (p.crustFraction * rmin));
  }
  return fromAnalytic(makeSupportMesh(points, triangles), std::move(vectors), p.m, surface);
}

}  // namespace ddfcam::ddf
