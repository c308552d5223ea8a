// SPDX-License-Identifier: MIT
// Core values -> vtkPolyData, and the display policy, against counts and shapes known in advance.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/live_surface.h>
#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/part_geometry.h>

#include <QtTest/QtTest>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>

using ddfcam::ddf::TriangleMesh;

namespace {

/// Regular octahedron, vertices at distance 1 on the axes, outward counter-clockwise faces.
TriangleMesh octahedron() {
  TriangleMesh m;
  m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                 {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

Eigen::Vector3d pointOf(vtkPolyData* poly, vtkIdType id) {
  double p[3];
  poly->GetPoint(id, p);
  return {p[0], p[1], p[2]};
}

std::vector<vtkIdType> cellPoints(vtkPolyData* poly, vtkIdType cell) {
  auto ids = vtkSmartPointer<vtkIdList>::New();
  poly->GetCellPoints(cell, ids);
  std::vector<vtkIdType> out(static_cast<std::size_t>(ids->GetNumberOfIds()));
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) out[k] = ids->GetId(k);
  return out;
}

/// Barycentric coordinates of @p p in triangle (a, b, c), all projected onto the xy plane.
Eigen::Vector3d baryXy(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                       const Eigen::Vector3d& c) {
  Eigen::Matrix2d m;
  m << b.x() - a.x(), c.x() - a.x(), b.y() - a.y(), c.y() - a.y();
  const Eigen::Vector2d st = m.inverse() * Eigen::Vector2d(p.x() - a.x(), p.y() - a.y());
  return {1.0 - st.x() - st.y(), st.x(), st.y()};
}

/// The raster mesh of @p ddf (fig. 7.1a) at parameter position (u, w), raster steps, of face
/// @p f: linear over the raster triangle holding it.
Eigen::Vector3d rasterMeshPoint(const ddfcam::ddf::DisplacementField& ddf, int f, double u,
                                double w) {
  const int n = ddf.resolution() - 1;
  const int i = std::clamp(static_cast<int>(std::floor(u)), 0, n - 1);
  const int k = std::clamp(static_cast<int>(std::floor(w)), 0, n - 1 - i);
  const double a = u - i, b = w - k;
  const auto p = [&](int ii, int kk) { return ddf.surfacePoint(f, ii, kk); };
  if (a + b <= 1.0 || i + k + 2 > n)
    return p(i, k) + a * (p(i + 1, k) - p(i, k)) + b * (p(i, k + 1) - p(i, k));
  return p(i + 1, k + 1) + (1.0 - a) * (p(i, k + 1) - p(i + 1, k + 1)) +
         (1.0 - b) * (p(i + 1, k) - p(i + 1, k + 1));
}

}  // namespace

class AdaptersTest : public QObject {
  Q_OBJECT

 private slots:
  void surfaceHasOutwardFlatNormalsOnSharpEdges();
  void wireframeDrawsEveryEdgeOnce();
  void segmentsKeepTheirEndpoints();
  void planePatchRasterOrAdaptiveByBudget();
  void surfaceKeepsVertexOfSplitPointsAndFaceOfCells();
  void planeGeometryFacesAndSamplesMatchTheSupport();
  void adaptiveCornerParamsLieOnTheRasterMesh();
  void liveSurfaceSharesCornersWithinAFace();
  void polylinesKeepPointOrder();
  void glyphsAreArrowsOfTheGivenLength();
};

void AdaptersTest::surfaceHasOutwardFlatNormalsOnSharpEdges() {
  auto poly = ddfcam::gui::toSurfacePolyData(octahedron());
  QCOMPARE(poly->GetNumberOfPolys(), vtkIdType{8});
  vtkDataArray* normals = poly->GetPointData()->GetNormals();
  QVERIFY(normals != nullptr);
  // Dihedral normals differ by 70.5 degrees > the 40-degree feature angle: every corner of
  // face (sx, sy, sz) carries the exact face normal (sx, sy, sz) / sqrt(3).
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c) {
    poly->GetCellPoints(c, ids);
    QCOMPARE(ids->GetNumberOfIds(), vtkIdType{3});
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) centroid += pointOf(poly, ids->GetId(k)) / 3.0;
    const Eigen::Vector3d expected = centroid.cwiseSign() / std::sqrt(3.0);
    for (int k = 0; k < 3; ++k) {
      double n[3];
      normals->GetTuple(ids->GetId(k), n);
      QVERIFY((Eigen::Vector3d(n[0], n[1], n[2]) - expected).norm() < 1e-6);
    }
  }
  QCOMPARE(ddfcam::gui::toSurfacePolyData(TriangleMesh{})->GetNumberOfCells(), vtkIdType{0});
}

void AdaptersTest::wireframeDrawsEveryEdgeOnce() {
  const TriangleMesh mesh = octahedron();
  auto poly = ddfcam::gui::toWireframePolyData(mesh);
  QCOMPARE(poly->GetNumberOfPolys(), vtkIdType{0});
  // Euler: V - E + F = 2 with V = 6, F = 8 gives E = 12; the edges are all pairs of
  // vertices that are not antipodal (15 pairs minus 3).
  QCOMPARE(poly->GetNumberOfLines(), vtkIdType{12});
  std::set<std::pair<vtkIdType, vtkIdType>> edges;
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c) {
    poly->GetCellPoints(c, ids);
    const Eigen::Vector3d a = pointOf(poly, ids->GetId(0)), b = pointOf(poly, ids->GetId(1));
    QVERIFY(std::abs((a - b).norm() - std::sqrt(2.0)) < 1e-12);
    edges.insert(std::minmax(ids->GetId(0), ids->GetId(1)));
  }
  QCOMPARE(edges.size(), std::size_t{12});
}

void AdaptersTest::segmentsKeepTheirEndpoints() {
  const std::vector<Eigen::Vector3d> from = {{0, 0, 0}, {1, 2, 3}};
  const std::vector<Eigen::Vector3d> to = {{0, 0, 1}, {1, 2, 5}};
  auto poly = ddfcam::gui::toSegmentPolyData(from, to);
  QCOMPARE(poly->GetNumberOfLines(), vtkIdType{2});
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType c = 0; c < 2; ++c) {
    poly->GetCellPoints(c, ids);
    QCOMPARE(pointOf(poly, ids->GetId(0)), from[c]);
    QCOMPARE(pointOf(poly, ids->GetId(1)), to[c]);
  }
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, ddfcam::gui::toSegmentPolyData(from, {}));
}

void AdaptersTest::planePatchRasterOrAdaptiveByBudget() {
  // Plane z = 0.25 mm over a 20 x 15 grid (600 faces) at m = 17: 600 * 16^2 raster triangles.
  const ddfcam::ddf::PlanePatchParams plane;
  const auto part = ddfcam::ddf::planePatch(plane);
  ddfcam::gui::DisplayParams params;
  params.rasterTriangleBudget = 1'000'000;
  const auto raster = ddfcam::gui::buildPartGeometry(part.ddf, params);
  QVERIFY(!raster.adaptiveSurface);
  QCOMPARE(raster.surfaceTriangles, std::size_t{600 * 16 * 16});
  params.rasterTriangleBudget = 1000;
  const auto adaptive = ddfcam::gui::buildPartGeometry(part.ddf, params);
  QVERIFY(adaptive.adaptiveSurface);
  QVERIFY(adaptive.surfaceTriangles < raster.surfaceTriangles / 10);
  for (const auto* geometry : {&raster, &adaptive}) {
    vtkPolyData* surface = geometry->scene.surface;
    for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
      QVERIFY(std::abs(pointOf(surface, p).z() - plane.planeZMm) < 1e-6);
    // Grid edges: 20 x 16 along x, 21 x 15 along y and 300 diagonals.
    QCOMPARE(geometry->scene.support->GetNumberOfLines(), vtkIdType{20 * 16 + 21 * 15 + 300});
    const vtkIdType stubbles = geometry->scene.stubbles->GetNumberOfLines();
    QVERIFY(stubbles > 0 && stubbles <= static_cast<vtkIdType>(params.stubbleBudget));
  }
}

void AdaptersTest::surfaceKeepsVertexOfSplitPointsAndFaceOfCells() {
  const TriangleMesh mesh = octahedron();
  const std::vector<int> faces = {7, 6, 5, 4, 3, 2, 1, 0};
  auto poly = ddfcam::gui::toSurfacePolyData(mesh, faces);
  // Every edge is a feature edge: each of the 8 faces gets its own 3 corner points.
  QCOMPARE(poly->GetNumberOfPoints(), vtkIdType{24});
  vtkDataArray* vertex = poly->GetPointData()->GetArray(ddfcam::gui::kVertexArrayName);
  QVERIFY(vertex != nullptr);
  for (vtkIdType p = 0; p < poly->GetNumberOfPoints(); ++p) {
    const auto v = static_cast<std::size_t>(vertex->GetTuple1(p));
    QVERIFY(v < mesh.vertices.size());
    QCOMPARE(pointOf(poly, p), mesh.vertices[v]);
  }
  vtkDataArray* face = poly->GetCellData()->GetArray(ddfcam::gui::kFaceArrayName);
  QVERIFY(face != nullptr);
  for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c) {
    QCOMPARE(static_cast<int>(face->GetTuple1(c)), faces[c]);
    // Cell order is the triangle order: the cell's points copy the triangle's vertices.
    const auto ids = cellPoints(poly, c);
    for (int k = 0; k < 3; ++k)
      QCOMPARE(static_cast<int>(vertex->GetTuple1(ids[k])), mesh.triangles[c][k]);
  }
  QVERIFY(ddfcam::gui::toSurfacePolyData(mesh)->GetCellData()->GetArray("face") == nullptr);
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput,
                           ddfcam::gui::toSurfacePolyData(mesh, std::vector<int>{1, 2}));
}

void AdaptersTest::planeGeometryFacesAndSamplesMatchTheSupport() {
  ddfcam::ddf::PlanePatchParams plane;
  plane.cellsX = 6;
  plane.cellsY = 4;
  plane.m = 9;
  const auto part = ddfcam::ddf::planePatch(plane);
  const auto& ddf = part.ddf;
  for (std::size_t budget : {std::size_t{1'000'000}, std::size_t{10}}) {
    ddfcam::gui::DisplayParams params;
    params.rasterTriangleBudget = budget;
    const auto geometry = ddfcam::gui::buildPartGeometry(ddf, params);
    vtkPolyData* surface = geometry.scene.surface;
    QCOMPARE(geometry.surfaceTriangleFace.size(), geometry.surfaceTriangles);
    QCOMPARE(surface->GetNumberOfCells(), static_cast<vtkIdType>(geometry.surfaceTriangles));
    vtkDataArray* face = surface->GetCellData()->GetArray(ddfcam::gui::kFaceArrayName);
    QVERIFY(face != nullptr);
    // The plane's vectors are vertical: a triangle of face f lies over support triangle f.
    for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c) {
      const int f = geometry.surfaceTriangleFace[c];
      QCOMPARE(static_cast<int>(face->GetTuple1(c)), f);
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (vtkIdType id : cellPoints(surface, c)) centroid += pointOf(surface, id) / 3.0;
      const auto& fv = ddf.faceVertices(f);
      const Eigen::Vector3d b =
          baryXy(centroid, ddf.position(fv[0]), ddf.position(fv[1]), ddf.position(fv[2]));
      QVERIFY2(b.minCoeff() > -1e-9, qPrintable(QString("cell %1 face %2").arg(c).arg(f)));
    }
    // One sample per mesh vertex; each one's support point lies under that vertex.
    vtkDataArray* vertex = surface->GetPointData()->GetArray(ddfcam::gui::kVertexArrayName);
    const auto& samples = geometry.surfaceSamples;
    QCOMPARE(samples.face.size(), static_cast<std::size_t>(vertex->GetRange(0)[1]) + 1);
    QCOMPARE(samples.bary.size(), samples.face.size());
    for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p) {
      const auto v = static_cast<std::size_t>(vertex->GetTuple1(p));
      const auto& fv = ddf.faceVertices(samples.face[v]);
      const Eigen::Vector3d& w = samples.bary[v];
      const Eigen::Vector3d g =
          w[0] * ddf.position(fv[0]) + w[1] * ddf.position(fv[1]) + w[2] * ddf.position(fv[2]);
      const Eigen::Vector3d q = pointOf(surface, p);
      QVERIFY2(std::hypot(g.x() - q.x(), g.y() - q.y()) < 1e-6,
               qPrintable(QString("point %1 budget %2").arg(p).arg(budget)));
    }
  }
}

void AdaptersTest::polylinesKeepPointOrder() {
  const std::vector<std::vector<Eigen::Vector3d>> lines = {
      {{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 1, 1}}, {{9, 9, 9}}, {{5, 5, 5}, {6, 5, 5}, {7, 5, 5}}};
  auto poly = ddfcam::gui::toPolylinePolyData(lines);
  // The single-point line is no line: 2 cells, 4 + 3 points.
  QCOMPARE(poly->GetNumberOfLines(), vtkIdType{2});
  QCOMPARE(poly->GetNumberOfPoints(), vtkIdType{7});
  vtkDataArray* index = poly->GetCellData()->GetArray(ddfcam::gui::kPolylineArrayName);
  QVERIFY(index != nullptr);
  const int expected[2] = {0, 2};
  for (vtkIdType c = 0; c < 2; ++c) {
    const auto& line = lines[expected[c]];
    QCOMPARE(static_cast<int>(index->GetTuple1(c)), expected[c]);
    const auto ids = cellPoints(poly, c);
    QCOMPARE(ids.size(), line.size());
    for (std::size_t k = 0; k < ids.size(); ++k) QCOMPARE(pointOf(poly, ids[k]), line[k]);
  }
  QCOMPARE(ddfcam::gui::toPolylinePolyData({})->GetNumberOfCells(), vtkIdType{0});
}

void AdaptersTest::glyphsAreArrowsOfTheGivenLength() {
  const std::vector<Eigen::Vector3d> points = {{0, 0, 0}, {1, 2, 3}, {-4, 0, 2}};
  const std::vector<Eigen::Vector3d> directions = {{0, 0, 5}, {1, 1, 0}, {-0.1, 0.2, -0.3}};
  const double length = 2.0;
  auto poly = ddfcam::gui::toGlyphPolyData(points, directions, length);
  QCOMPARE(poly->GetNumberOfPoints(), vtkIdType{12});
  QCOMPARE(poly->GetNumberOfLines(), vtkIdType{9});
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d d = directions[i].normalized();
    // Shaft: base to tip = base + length * d.
    const auto shaft = cellPoints(poly, static_cast<vtkIdType>(3 * i));
    QCOMPARE(pointOf(poly, shaft[0]), points[i]);
    const Eigen::Vector3d tip = pointOf(poly, shaft[1]);
    QVERIFY((tip - (points[i] + length * d)).norm() < 1e-12);
    // Heads: from the tip, a quarter of the length, 25 degrees off the reversed shaft,
    // mirror images of each other about the shaft.
    Eigen::Vector3d sideSum = Eigen::Vector3d::Zero();
    for (int h = 1; h <= 2; ++h) {
      const auto head = cellPoints(poly, static_cast<vtkIdType>(3 * i + h));
      QCOMPARE(pointOf(poly, head[0]), tip);
      const Eigen::Vector3d stroke = pointOf(poly, head[1]) - tip;
      QVERIFY(std::abs(stroke.norm() - 0.25 * length) < 1e-12);
      const double angle = std::acos(std::clamp(stroke.normalized().dot(-d), -1.0, 1.0));
      QVERIFY(std::abs(angle - 25.0 * std::numbers::pi / 180.0) < 1e-9);
      sideSum += stroke - stroke.dot(d) * d;
    }
    QVERIFY(sideSum.norm() < 1e-12);
  }
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput,
                           ddfcam::gui::toGlyphPolyData(points, {{1, 0, 0}}, 1.0));
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput,
                           ddfcam::gui::toGlyphPolyData(points, directions, 0.0));
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, ddfcam::gui::toGlyphPolyData(
                                                     {{0, 0, 0}}, {Eigen::Vector3d::Zero()}, 1.0));
}

void AdaptersTest::adaptiveCornerParamsLieOnTheRasterMesh() {
  // A sphere's DDF (320 faces, m = 17) shown adaptively: every triangle corner's raster
  // position must name the point of the surface the corner approximates, within the
  // triangulation's bound (straight midpoints and centroids lie off the surface by up to eps).
  ddfcam::ddf::SphereParams sphere;
  sphere.subdivisions = 2;
  const auto part = ddfcam::ddf::spherePart(sphere);
  ddfcam::gui::DisplayParams params;
  params.rasterTriangleBudget = 1000;
  const auto geometry = ddfcam::gui::buildPartGeometry(part.ddf, params);
  QVERIFY(geometry.adaptiveSurface);
  QCOMPARE(geometry.scene.rasterFaces, part.ddf.faceCount());
  QCOMPARE(geometry.scene.rasterSteps, 16);
  QVERIFY(geometry.scene.surfaceCornerParams != nullptr);
  const std::vector<float>& corners = *geometry.scene.surfaceCornerParams;
  vtkPolyData* surface = geometry.scene.surface;
  QCOMPARE(corners.size(), 6 * static_cast<std::size_t>(surface->GetNumberOfCells()));
  double worst = 0.0;
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c) {
    const auto ids = cellPoints(surface, c);
    for (int k = 0; k < 3; ++k) {
      const double u = corners[6 * c + 2 * k], w = corners[6 * c + 2 * k + 1];
      QVERIFY(u >= 0.0 && w >= 0.0 && u + w <= 16.0 + 1e-4);
      const Eigen::Vector3d onMesh =
          rasterMeshPoint(part.ddf, geometry.surfaceTriangleFace[c], u, w);
      worst = std::max(worst, (onMesh - pointOf(surface, ids[k])).norm());
    }
  }
  QVERIFY2(worst <= geometry.adaptiveEpsMm * (1.0 + 1e-3) + 1e-5,
           qPrintable(QString("corner off its raster position by %1 mm, eps %2 mm")
                          .arg(worst)
                          .arg(geometry.adaptiveEpsMm)));
  // Not trivially zero: the adaptive mesh has straight midpoints off the sphere's raster mesh.
  QVERIFY(worst > 0.0);
}

void AdaptersTest::liveSurfaceSharesCornersWithinAFace() {
  // Two support faces (raster steps 2): face 0 has two triangles over slots 0-1-2 and 1-3-2,
  // face 1 one triangle over slots 1-4-3, so slots 1 and 3 lie on the border between them.
  ddfcam::planning::LiveFrame frame;
  frame.faceCount = 2;
  frame.rasterSteps = 2;
  frame.positions = {0, 0, 0, 2, 0, 0, 0, 2, 0, 2, 2, 0, 4, 1, 0};
  frame.normals.assign(frame.positions.size(), 0.0f);
  for (std::size_t s = 0; s < 5; ++s) frame.normals[3 * s + 2] = 1.0f;
  frame.triangles = {0, 1, 2, 1, 3, 2, 1, 4, 3};
  frame.triangleFace = {0, 0, 1};
  frame.cornerParams = {0, 0, 2, 0, 0, 2, 2, 0, 1, 1, 0, 2, 0, 0, 2, 0, 0, 2};
  frame.toleranceClasses.assign(2 * 6, 1);
  ddfcam::gui::LiveSurfacePolyData surface(2, 2);
  surface.apply(frame);
  vtkPolyData* poly = surface.polyData();
  // Face 0 uses slots 0-3 (4 points), face 1 slots 1, 3, 4 (3 more): 7, not 9.
  QCOMPARE(poly->GetNumberOfPoints(), vtkIdType{7});
  QCOMPARE(poly->GetNumberOfCells(), vtkIdType{3});
  vtkDataArray* tcoords = poly->GetPointData()->GetTCoords();
  QVERIFY(tcoords != nullptr);
  for (vtkIdType c = 0; c < 3; ++c) {
    const auto ids = cellPoints(poly, c);
    for (int k = 0; k < 3; ++k) {
      const std::size_t corner = 3 * static_cast<std::size_t>(c) + k;
      const int slot = frame.triangles[corner];
      QCOMPARE(pointOf(poly, ids[k]),
               Eigen::Vector3d(frame.positions[3 * slot], frame.positions[3 * slot + 1],
                               frame.positions[3 * slot + 2]));
      const auto st = surface.atlas()->texCoord(frame.triangleFace[c],
                                                frame.cornerParams[2 * corner],
                                                frame.cornerParams[2 * corner + 1]);
      QCOMPARE(static_cast<float>(tcoords->GetComponent(ids[k], 0)), st[0]);
      QCOMPARE(static_cast<float>(tcoords->GetComponent(ids[k], 1)), st[1]);
    }
  }
  // A second frame with other triangles refills the same polydata.
  frame.triangles = {0, 1, 2};
  frame.triangleFace = {0};
  frame.cornerParams.resize(6);
  surface.apply(frame);
  QCOMPARE(poly->GetNumberOfPoints(), vtkIdType{3});
  QCOMPARE(poly->GetNumberOfCells(), vtkIdType{1});
}

QTEST_APPLESS_MAIN(AdaptersTest)
#include "adapters_test.moc"
