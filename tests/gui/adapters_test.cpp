// SPDX-License-Identifier: MIT
// Core values -> vtkPolyData, and the display policy, against counts and shapes known in advance.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/part_geometry.h>

#include <QtTest/QtTest>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cmath>
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

}  // namespace

class AdaptersTest : public QObject {
  Q_OBJECT

 private slots:
  void surfaceHasOutwardFlatNormalsOnSharpEdges();
  void wireframeDrawsEveryEdgeOnce();
  void segmentsKeepTheirEndpoints();
  void planePatchRasterOrAdaptiveByBudget();
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

QTEST_APPLESS_MAIN(AdaptersTest)
#include "adapters_test.moc"
