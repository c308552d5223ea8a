// SPDX-License-Identifier: MIT
// Tests on the shared STEP parts (skipped without ../shared/data): faces, units and bounds as
// the files state them and the represented surface's distance to the exact CAD surface (the
// curvature oracles are in cad_curvature_shared_test.cpp).
#include <ddfcam/error.h>
#include <ddfcam/io/cad/cad_model.h>
#include <ddfcam/io/mesh/part_loader.h>
#include <ddfcam/io/project/project_loader.h>
#include <ddfcam/planning/analysis/curvature.h>

#include <gtest/gtest.h>

#include "cad_shared_files.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace ddfcam::io {
namespace {

using Eigen::Vector3d;

using test::cadPath;

struct Expected {
  const char* file;
  int faces;
  ddfcam::LengthUnit unit;
  Vector3d lo, hi;  // mm
};

// Faces and units from cad/SOURCES.md; bounds from the files' coordinates times their unit
// (boxed_sphere's coordinates span +-0.5 cm: +-5 mm).
const std::vector<Expected>& expectedParts() {
  static const std::vector<Expected> parts = {
      {"biquartic_sphere.step", 6, ddfcam::LengthUnit::Millimetre, Vector3d(-1, -1, -1),
       Vector3d(1, 1, 1)},
      {"bolt_clip.step", 20, ddfcam::LengthUnit::Metre, Vector3d(0, -2.54, -1.6002),
       Vector3d(11.684, 2.54, 1.6002)},
      {"boxed_sphere.step", 192, ddfcam::LengthUnit::Centimetre, Vector3d(-5, -5, -5),
       Vector3d(5, 5, 5)},
      {"open_cylinder.step", 4, ddfcam::LengthUnit::Centimetre, Vector3d(0, -100, 0),
       Vector3d(100, 100, 137.1675)},
      {"revolved_sphere.step", 1, ddfcam::LengthUnit::Millimetre, Vector3d(-5, -5, -5),
       Vector3d(5, 5, 5)},
      {"sliced_cylinder.step", 5, ddfcam::LengthUnit::Centimetre, Vector3d(0, -100, 0),
       Vector3d(100, 100, 137.1675)},
  };
  return parts;
}

TEST(CadPartShared, FacesUnitsAndBoundsAsTheFilesState) {
  for (const Expected& part : expectedParts()) {
    REQUIRE_SHARED(cadPath(part.file));
    const CadModel model = readCadModel(cadPath(part.file));
    EXPECT_EQ(model.faceCount(), part.faces) << part.file;
    EXPECT_EQ(model.fileUnit(), part.unit) << part.file << ": '" << model.fileUnitName() << "'";
    EXPECT_TRUE(model.unitFromFile()) << part.file;
    const double tolerance = 1e-4 * (part.hi - part.lo).norm();
    EXPECT_LE((model.boundsMm()[0] - part.lo).cwiseAbs().maxCoeff(), tolerance) << part.file;
    EXPECT_LE((model.boundsMm()[1] - part.hi).cwiseAbs().maxCoeff(), tolerance) << part.file;
    for (const std::string& line : model.healing())
      std::printf("[%s] %s\n", part.file, line.c_str());
  }
}

TEST(CadPartShared, TruncatedStepIsAnError) {
  const auto path = cadPath("boxed_sphere.step");
  REQUIRE_SHARED(path);
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto cut = std::filesystem::temp_directory_path() / "ddfcam_cad_truncated.step";
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  try {
    readCadModel(cut);
    ADD_FAILURE() << "a truncated STEP file was accepted";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("ddfcam_cad_truncated.step"), std::string::npos);
  }
  std::filesystem::remove(cut);
}

// Edges used by one triangle only: none on a closed solid whose faces were welded.
int openEdges(const ddf::TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  return static_cast<int>(
      std::count_if(uses.begin(), uses.end(), [](const auto& entry) { return entry.second == 1; }));
}

// One test per shared part for the heavy checks below, so that each stays a short CTest test.
class CadPartFile : public testing::TestWithParam<Expected> {};

void PrintTo(const Expected& part, std::ostream* out) {
  *out << part.file;
}

std::string partName(const testing::TestParamInfo<Expected>& info) {
  std::string name = info.param.file;
  return name.substr(0, name.find('.'));
}

INSTANTIATE_TEST_SUITE_P(Parts, CadPartFile, testing::ValuesIn(expectedParts()), partName);

TEST_P(CadPartFile, TessellationMeetsTheChordDeflectionAndStaysClosed) {
  const Expected& expected = GetParam();
  const auto path = cadPath(expected.file);
  REQUIRE_SHARED(path);
  const CadModel model = readCadModel(path);
  CadTessellationParams params;
  params.chordDeflectionMm = 2e-4 * (expected.hi - expected.lo).norm();
  const auto start = std::chrono::steady_clock::now();
  const CadTessellation tessellation = tessellateCadModel(model, params);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Oracle: the global closest point of the exact model to each triangle's centroid and edge
  // midpoints, on a deterministic sample of about 3000 triangles.
  const CadSurfaceQuery query(model);
  const auto& mesh = tessellation.mesh;
  const std::size_t stride = std::max<std::size_t>(1, mesh.triangles.size() / 3000);
  double maxMm = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); t += stride) {
    const auto& tri = mesh.triangles[t];
    const Vector3d a = mesh.vertices[tri[0]], b = mesh.vertices[tri[1]], c = mesh.vertices[tri[2]];
    for (const Vector3d& p : {Vector3d((a + b + c) / 3), Vector3d((a + b) / 2),
                              Vector3d((b + c) / 2), Vector3d((c + a) / 2)}) {
      const auto hit = query.project(p);
      ASSERT_TRUE(hit.has_value()) << expected.file;
      maxMm = std::max(maxMm, hit->distanceMm);
    }
  }
  std::printf(
      "[%s] chord %.4g mm: BRepMesh %.4g mm, after re-meshing %zu faces %.4g mm (exact "
      "projection of a sample: %.4g mm, model tolerance %.3g mm); %zu triangles, %d open "
      "edges; %.2f s\n",
      expected.file, params.chordDeflectionMm, tessellation.initialChordErrorMm,
      tessellation.refinedFaces.size(), tessellation.chordErrorMm, maxMm, model.toleranceMm(),
      mesh.triangles.size(), openEdges(mesh), seconds);
  EXPECT_LE(tessellation.chordErrorMm, params.chordDeflectionMm) << expected.file;
  // Near a face border the trimmed face is only defined to the model's own tolerance
  // (boxed_sphere's edges lie up to 0.06 mm off their faces).
  EXPECT_LE(maxMm, params.chordDeflectionMm + model.toleranceMm()) << expected.file;
  if (model.solidCount() > 0) {
    EXPECT_EQ(openEdges(mesh), 0) << expected.file;
  }
}

// The raster points of a converted part: all of them, or every stride-th face's.
std::vector<Vector3d> rasterSample(const ddf::DisplacementField& part, std::size_t limit) {
  const std::size_t perFace = part.pointsPerFace();
  const int stride = std::max<int>(
      1, static_cast<int>(part.faceCount() * perFace / std::max<std::size_t>(limit, 1)));
  std::vector<Vector3d> points;
  const int steps = part.resolution() - 1;
  for (int f = 0; f < part.faceCount(); f += stride)
    for (int k = 0; k <= steps; ++k)
      for (int i = 0; i <= steps - k; ++i) points.push_back(part.surfacePoint(f, i, k));
  return points;
}

TEST_P(CadPartFile, RepresentedSurfaceLiesWithinTheToleranceOfTheExactSurface) {
  const Expected& expected = GetParam();
  const auto path = cadPath(expected.file);
  REQUIRE_SHARED(path);
  // boxed_sphere's edges lie up to 0.06 mm off their faces (CadModel::toleranceMm), more than
  // 2e-3 x its diagonal: its tolerance is 1e-2 x the diagonal, which also keeps it quick.
  const double share = std::string(expected.file) == "boxed_sphere.step" ? 1e-2 : 2e-3;
  const double toleranceMm = share * (expected.hi - expected.lo).norm();
  LoadPartParams params;
  params.conversion.resolution = 4;
  params.conversion.toleranceMm = toleranceMm;
  LoadPartReport report;
  const auto start = std::chrono::steady_clock::now();
  const ddf::DisplacementField part = loadPart(path, params, &report);
  const double loadSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const CadSurfaceQuery query(readCadModel(path));
  const std::vector<Vector3d> points = rasterSample(part, 3000);
  double maxMm = 0.0, sumMm = 0.0;
  for (const Vector3d& p : points) {
    const auto hit = query.project(p);
    ASSERT_TRUE(hit.has_value()) << expected.file;
    maxMm = std::max(maxMm, hit->distanceMm);
    sumMm += hit->distanceMm;
  }
  std::printf(
      "[%s] tolerance %.4g mm, chord %.4g mm: %d triangles -> %d faces (m = %d), %zu raster "
      "points to the exact surface: max %.4g mm, mean %.4g mm; load %.2f s, measure %.2f s\n",
      expected.file, toleranceMm, cadChordDeflectionMm(params.conversion, 0), report.meshTriangles,
      part.faceCount(), part.resolution(), points.size(), maxMm, sumMm / points.size(), loadSeconds,
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() -
          loadSeconds);
  EXPECT_LE(maxMm, toleranceMm) << expected.file;
  EXPECT_EQ(static_cast<int>(report.cadFaceOfSupportFace.size()), part.faceCount());
  EXPECT_EQ(static_cast<int>(report.cadFaceNames.size()), expected.faces);
}

}  // namespace
}  // namespace ddfcam::io
