// SPDX-License-Identifier: MIT
// Tests of CAD reading (IGES samples made by OpenCASCADE), exact-surface queries against the
// analytic cylinder, and loading parts in their length unit.
#include <ddfcam/error.h>
#include <ddfcam/io/cad/cad_model.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/mesh/part_loader.h>
#include <ddfcam/io/project/project_loader.h>

#include "../io_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace ddfcam::io {
namespace {

using Eigen::Vector3d;
using test::ioErrorMessage;
using test::ScratchDir;

constexpr double kRadius = 5.0;   // tests/data/README.md: BRepPrimAPI_MakeCylinder(5, 12)
constexpr double kHeight = 12.0;  // axis +Z, base at z = 0
constexpr double kPi = std::numbers::pi;

std::filesystem::path dataFile(const std::string& name) {
  return std::filesystem::path(DDFCAM_TEST_DATA_DIR) / name;
}

// Closest point of the closed cylinder surface (side and both caps) to an outside point.
Vector3d closestOnCylinder(const Vector3d& p) {
  const double rho = std::hypot(p.x(), p.y());
  const Vector3d radial = rho > 0 ? Vector3d(p.x() / rho, p.y() / rho, 0) : Vector3d::UnitX();
  const double z = std::clamp(p.z(), 0.0, kHeight);
  const Vector3d side = kRadius * radial + Vector3d(0, 0, z);
  const double capZ = p.z() < 0.5 * kHeight ? 0.0 : kHeight;
  const Vector3d cap = std::min(rho, kRadius) * radial + Vector3d(0, 0, capZ);
  return (side - p).norm() < (cap - p).norm() ? side : cap;
}

void expectCylinderGeometry(const CadModel& model) {
  EXPECT_EQ(model.faceCount(), 3);
  EXPECT_EQ(model.solidCount(), 1);
  std::map<std::string, int> types;
  for (const CadFace& face : model.faces()) ++types[face.surfaceType];
  EXPECT_EQ(types["cylinder"], 1);
  EXPECT_EQ(types["plane"], 2);
  const auto [lo, hi] = model.boundsMm();
  EXPECT_NEAR((lo - Vector3d(-kRadius, -kRadius, 0)).norm(), 0.0, 1e-6);
  EXPECT_NEAR((hi - Vector3d(kRadius, kRadius, kHeight)).norm(), 0.0, 1e-6);
  const double area = 2 * kPi * kRadius * kHeight + 2 * kPi * kRadius * kRadius;
  EXPECT_NEAR(model.areaMm2(), area, 1e-8 * area);  // IGES keeps ~15 digits
}

TEST(CadModel, IgesCylinderReadsWithTheGeometryOcctBuilt) {
  const CadModel model = readCadModel(dataFile("cylinder_r5_h12_mm.igs"));
  expectCylinderGeometry(model);
  EXPECT_EQ(model.fileUnit(), ddfcam::LengthUnit::Millimetre);
  EXPECT_TRUE(model.unitFromFile());
  EXPECT_EQ(model.faces()[0].name.rfind("face 1 (", 0), 0u);
}

TEST(CadModel, IgesInInchesIsConvertedToTheSameMillimetres) {
  const CadModel model = readCadModel(dataFile("cylinder_r5_h12_in.igs"));
  expectCylinderGeometry(model);
  EXPECT_EQ(model.fileUnit(), ddfcam::LengthUnit::Inch);
  EXPECT_EQ(model.unit(), ddfcam::LengthUnit::Inch);
  EXPECT_TRUE(model.unitFromFile());
}

TEST(CadModel, UnitOverrideRescalesFromTheStatedUnit) {
  CadReadParams params;
  params.unit = ddfcam::LengthUnit::Centimetre;  // "the file's numbers are cm", not the stated mm
  const CadModel model = readCadModel(dataFile("cylinder_r5_h12_mm.igs"), params);
  EXPECT_EQ(model.unit(), ddfcam::LengthUnit::Centimetre);
  EXPECT_FALSE(model.unitFromFile());
  EXPECT_NEAR(model.boundsMm()[1].z(), 10 * kHeight, 1e-6);
  EXPECT_NEAR(model.boundsMm()[1].x(), 10 * kRadius, 1e-6);
}

TEST(CadModel, TessellationIsClosedOutwardAndWithinTheChord) {
  const CadModel model = readCadModel(dataFile("cylinder_r5_h12_mm.igs"));
  CadTessellationParams params;
  params.chordDeflectionMm = 0.01;
  const CadTessellation mesh = tessellateCadModel(model, params);
  ASSERT_EQ(mesh.faceOfTriangle.size(), mesh.mesh.triangles.size());
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : mesh.mesh.triangles)
    for (int i = 0; i < 3; ++i) ++edges[std::minmax(t[i], t[(i + 1) % 3])];
  for (const auto& [edge, count] : edges) EXPECT_EQ(count, 2) << edge.first << "-" << edge.second;
  // Outward and closed: the enclosed volume is the cylinder's, less the chord's sliver.
  const double volume = kPi * kRadius * kRadius * kHeight;
  EXPECT_GT(mesh.mesh.signedVolume(), volume * (1 - 2 * params.chordDeflectionMm / kRadius));
  EXPECT_LE(mesh.mesh.signedVolume(), volume);
  for (std::size_t t = 0; t < mesh.mesh.triangles.size(); ++t) {
    const auto& tri = mesh.mesh.triangles[t];
    const Vector3d a = mesh.mesh.vertices[tri[0]], b = mesh.mesh.vertices[tri[1]],
                   c = mesh.mesh.vertices[tri[2]];
    const Vector3d centre = (a + b + c) / 3;
    EXPECT_LE((closestOnCylinder(centre) - centre).norm(), params.chordDeflectionMm * 1.01) << t;
    const std::string& type = model.faces()[mesh.faceOfTriangle[t]].surfaceType;
    if (type == "plane") {
      EXPECT_NEAR(std::abs(centre.z() - 0.5 * kHeight), 0.5 * kHeight, 1e-9);
    }
    if (type == "cylinder") {
      EXPECT_NEAR(std::hypot(a.x(), a.y()), kRadius, 1e-9);
    }
  }
}

TEST(CadSurfaceQuery, ProjectionMatchesTheAnalyticCylinder) {
  const CadModel model = readCadModel(dataFile("cylinder_r5_h12_mm.igs"));
  const CadSurfaceQuery query(model);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-9.0, 9.0), height(-4.0, 16.0);
  int checked = 0;
  for (int i = 0; i < 400; ++i) {
    const Vector3d p(coordinate(random), coordinate(random), height(random));
    const bool inside = std::hypot(p.x(), p.y()) < kRadius && p.z() > 0 && p.z() < kHeight;
    if (inside) continue;  // the oracle above is for outside points
    const auto hit = query.project(p);
    ASSERT_TRUE(hit.has_value()) << p.transpose();
    const Vector3d expected = closestOnCylinder(p);
    EXPECT_NEAR(hit->distanceMm, (expected - p).norm(), 1e-7) << p.transpose();
    EXPECT_NEAR((hit->pointMm - expected).norm(), 0.0, 1e-5) << p.transpose();
    ++checked;
  }
  EXPECT_GT(checked, 200);
  EXPECT_FALSE(query.project(Vector3d(30, 0, 6), 1.0).has_value());
}

TEST(CadSurfaceQuery, CylinderCurvatureIsOneOverRadiusAroundAndZeroAlong) {
  const CadModel model = readCadModel(dataFile("cylinder_r5_h12_mm.igs"));
  const CadSurfaceQuery query(model);
  const auto hit = query.project(Vector3d(7, 1, 4));
  ASSERT_TRUE(hit.has_value());
  ASSERT_EQ(model.faces()[hit->face].surfaceType, "cylinder");
  const auto k = query.curvature(hit->face, hit->pointMm);
  ASSERT_TRUE(k.has_value());
  EXPECT_NEAR(k->k1, 1 / kRadius, 1e-9);  // convex seen from outside
  EXPECT_NEAR(k->k2, 0.0, 1e-9);
  EXPECT_NEAR(std::abs(k->dir2.z()), 1.0, 1e-9);  // zero curvature along the axis
  const Vector3d radial = Vector3d(hit->pointMm.x(), hit->pointMm.y(), 0).normalized();
  EXPECT_NEAR(k->normal.dot(radial), 1.0, 1e-9);  // outward
  EXPECT_THROW(query.curvature(3, hit->pointMm), InvalidInput);
}

TEST(CadModel, ErrorsNameTheFileAndTheProblem) {
  ScratchDir dir;
  EXPECT_NE(ioErrorMessage([&] { readCadModel(dir / "absent.step"); }).find("absent.step"),
            std::string::npos);
  test::writeBytes(dir / "empty.step", "");
  EXPECT_NE(ioErrorMessage([&] { readCadModel(dir / "empty.step"); }).find("empty.step is empty"),
            std::string::npos);
  test::writeBytes(dir / "notes.step", "solid x\nfacet normal 0 0 1\nendsolid\n");
  EXPECT_NE(ioErrorMessage([&] { readCadModel(dir / "notes.step"); }).find("is not a STEP file"),
            std::string::npos);
  test::writeBytes(dir / "notes.igs", "hello\n");
  EXPECT_NE(ioErrorMessage([&] { readCadModel(dir / "notes.igs"); }).find("is not an IGES file"),
            std::string::npos);
  const std::string iges = test::readBytes(dataFile("cylinder_r5_h12_mm.igs"));
  test::writeBytes(dir / "cut.igs", iges.substr(0, iges.size() / 3));
  EXPECT_NE(ioErrorMessage([&] { readCadModel(dir / "cut.igs"); }).find("cut.igs"),
            std::string::npos);
  EXPECT_NE(ioErrorMessage([&] { readCadModel(dir / "part.sat"); }).find("unsupported"),
            std::string::npos);
}

ddf::TriangleMesh scaled(ddf::TriangleMesh mesh, double factor) {
  for (Vector3d& v : mesh.vertices) v *= factor;
  return mesh;
}

TEST(PartLoaderUnits, MetreStlLoadedInMetresIsTheMillimetrePartTimesAThousand) {
  ScratchDir dir;
  const ddf::TriangleMesh bowlMm = readMesh(dataFile("bowl_patch.off"));  // 10 mm across
  writeMesh(scaled(bowlMm, 1e-3), dir / "bowl_m.stl");
  writeMesh(bowlMm, dir / "bowl_mm.stl");
  LoadPartParams metres;
  metres.unit = ddfcam::LengthUnit::Metre;
  LoadPartReport report;
  const ddf::DisplacementField inMetres = loadPart(dir / "bowl_m.stl", metres, &report);
  const ddf::DisplacementField inMm = loadPart(dir / "bowl_mm.stl");
  EXPECT_EQ(report.unit, ddfcam::LengthUnit::Metre);
  EXPECT_FALSE(report.unitFromFile);
  EXPECT_NEAR(report.fileDiagonal * 1000, (report.boundsMm[1] - report.boundsMm[0]).norm(), 1e-9);
  ASSERT_EQ(inMetres.vertexCount(), inMm.vertexCount());
  ASSERT_EQ(inMetres.faceCount(), inMm.faceCount());
  for (int v = 0; v < inMm.vertexCount(); ++v)
    EXPECT_NEAR((inMetres.position(v) - inMm.position(v)).norm(), 0.0, 1e-6) << v;  // STL floats
}

TEST(PartLoaderUnits, SmallPartWithoutUnitIsReportedForTheCallerToAsk) {
  ScratchDir dir;
  // A blade-sized part (about 0.3 m) written in metres, loaded without a unit: read as mm, and
  // the report carries what the CLI warns about and the import dialog asks with.
  const ddf::TriangleMesh bowl = scaled(readMesh(dataFile("bowl_patch.off")), 0.03);
  writeMesh(bowl, dir / "blade.stl");
  LoadPartReport report;
  loadPart(dir / "blade.stl", {}, &report);
  EXPECT_LT(report.fileDiagonal, 1.0);
  EXPECT_TRUE(ddfcam::sizeSuggestsOtherUnit(report.fileDiagonal));
  EXPECT_EQ(ddfcam::likelyUnit(report.fileDiagonal), ddfcam::LengthUnit::Metre);
  EXPECT_EQ(report.unit, ddfcam::LengthUnit::Millimetre);
  EXPECT_FALSE(report.unitFromFile);
  EXPECT_NEAR((report.boundsMm[1] - report.boundsMm[0]).norm(), report.fileDiagonal, 1e-9);
  // With the unit given the part is a thousand times larger.
  LoadPartParams metres;
  metres.unit = ddfcam::LengthUnit::Metre;
  LoadPartReport inMetres;
  loadPart(dir / "blade.stl", metres, &inMetres);
  EXPECT_EQ(inMetres.unit, ddfcam::LengthUnit::Metre);
  EXPECT_NEAR((inMetres.boundsMm[1] - inMetres.boundsMm[0]).norm(), 1000.0 * report.fileDiagonal,
              1e-6);
}

TEST(CadModel, ReadAndTessellationReportProgressAndCancel) {
  std::vector<double> fractions;
  CadReadParams read;
  read.progress = [&](double f) {
    fractions.push_back(f);
    return true;
  };
  const CadModel model = readCadModel(dataFile("cylinder_r5_h12_mm.igs"), read);
  ASSERT_GE(fractions.size(), 3u);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_EQ(fractions.back(), 1.0);
  fractions.clear();
  CadTessellationParams params;
  params.progress = read.progress;
  const CadTessellation mesh = tessellateCadModel(model, params);
  EXPECT_GE(fractions.size(), 3u + model.faces().size());  // at least once per face
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_LE(mesh.chordErrorMm, params.chordDeflectionMm);
  // Cancelling at any call stops with Cancelled, in reading, tessellating and loading.
  for (int stopAt = 0; stopAt < 3; ++stopAt) {
    int calls = 0;
    const auto cancel = [&](double) { return calls++ < stopAt; };
    read.progress = cancel;
    EXPECT_THROW(readCadModel(dataFile("cylinder_r5_h12_mm.igs"), read), Cancelled) << stopAt;
    calls = 0;
    params.progress = cancel;
    EXPECT_THROW(tessellateCadModel(model, params), Cancelled) << stopAt;
    calls = 0;
    LoadPartParams load;
    load.progress = cancel;
    EXPECT_THROW(loadPart(dataFile("cylinder_r5_h12_mm.igs"), load), Cancelled) << stopAt;
  }
}

TEST(PartLoaderCad, IgesLoadsWithCadFacesPerSupportFaceAndTheFileUnit) {
  LoadPartReport report;
  LoadPartParams params;
  params.conversion.resolution = 4;
  const ddf::DisplacementField part = loadPart(dataFile("cylinder_r5_h12_in.igs"), params, &report);
  EXPECT_TRUE(report.converted);
  EXPECT_EQ(report.unit, ddfcam::LengthUnit::Inch);
  EXPECT_TRUE(report.unitFromFile);
  EXPECT_NEAR(report.fileDiagonal * 25.4, std::sqrt(100.0 + 100.0 + 144.0), 1e-6);
  ASSERT_EQ(report.cadFaceNames.size(), 3u);
  ASSERT_EQ(static_cast<int>(report.cadFaceOfSupportFace.size()), part.faceCount());
  for (int f = 0; f < part.faceCount(); ++f) {
    const int cad = report.cadFaceOfSupportFace[f];
    ASSERT_GE(cad, 0);
    const auto& t = part.faceVertices(f);
    const Vector3d c = (part.position(t[0]) + part.position(t[1]) + part.position(t[2])) / 3;
    // Plane faces lie on z = 0 or z = h; cylinder faces on the side.
    if (report.cadFaceNames[cad].find("plane") != std::string::npos)
      EXPECT_NEAR(std::abs(c.z() - 0.5 * kHeight), 0.5 * kHeight, 1e-6) << f;
    else
      EXPECT_GT(std::hypot(c.x(), c.y()), kRadius - 0.05) << f;
  }
}

TEST(PartLoaderCad, OpenProjectKeepsTheTessellationUnitAndCadFaces) {
  EXPECT_TRUE(canOpenAsProject("a.STEP") && canOpenAsProject("a.stp") &&
              canOpenAsProject("a.iges") && canOpenAsProject("a.IGS"));
  LoadPartParams params;
  params.conversion.resolution = 4;
  LoadPartReport report;
  const planning::Project project =
      openProject(dataFile("cylinder_r5_h12_in.igs"), params, &report);
  EXPECT_EQ(project.sourceUnit, ddfcam::LengthUnit::Inch);
  EXPECT_EQ(project.cadFaceNames, report.cadFaceNames);
  EXPECT_EQ(project.cadFaceOfSupportFace, report.cadFaceOfSupportFace);
  ASSERT_TRUE(project.designMesh.has_value());
  EXPECT_EQ(static_cast<int>(project.designMesh->triangles.size()), report.meshTriangles);
  EXPECT_NEAR(project.designMesh->bounds()[1].z(), kHeight, 1e-6);  // 12 mm written in inches
}

}  // namespace
}  // namespace ddfcam::io
