// SPDX-License-Identifier: MIT
// The conversion report: what convertMeshToDdf repaired and dropped, counted exactly, and a
// result that violates a constraint reported as such instead of as a success.
#include <ddfcam/ddf/conversion_report.h>
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/ddf/validation.h>
#include <ddfcam/log.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <mutex>

#include "../support/conversion_meshes.h"

namespace ddfcam::ddf {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

bool startsWith(const std::string& text, const std::string& prefix) {
  return text.rfind(prefix, 0) == 0;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& line : lines) out += line + "\n";
  return out;
}

TEST(ConversionReport, CountsUnusedVerticesAndDuplicateTrianglesExactly) {
  const TriangleMesh input = test::gridWithStrayVerticesAndDuplicates();
  const ConversionResult result = convertMeshToDdf(input);
  const ConversionReport& r = result.report;
  EXPECT_EQ(r.inputVertices, 16 + test::kStrayVertices);
  EXPECT_EQ(r.inputTriangles, 18 + test::kDuplicateTriangles);
  EXPECT_EQ(r.unusedVertices, test::kStrayVertices);
  EXPECT_EQ(r.duplicateFaces, test::kDuplicateTriangles);
  EXPECT_EQ(r.droppedFaces, 0);  // duplicates are not mistaken for non-manifold triangles
  EXPECT_EQ(r.weldedVertices, 0);
  EXPECT_EQ(r.orphanedVertices, 0);
  EXPECT_EQ(r.supportVertices, 16);
  EXPECT_EQ(r.supportFaces, 18);
  EXPECT_EQ(r.boundaryLoops, 1);  // the grid's border
  EXPECT_EQ(r.nonManifoldEdges, 0);
  // Every input vertex is accounted for.
  EXPECT_EQ(r.inputVertices,
            r.weldedVertices + r.unusedVertices + r.orphanedVertices + r.supportVertices);
  EXPECT_TRUE(r.valid());
  const std::string repairs = joined(conversionRepairLines(r));
  EXPECT_TRUE(contains(repairs, "7 unused vertices dropped")) << repairs;
  EXPECT_TRUE(contains(repairs, "2 duplicate triangles dropped")) << repairs;
  EXPECT_TRUE(conversionProblemLines(r).empty());
  EXPECT_TRUE(startsWith(conversionVerdict(r), "valid DDF")) << conversionVerdict(r);
}

TEST(ConversionReport, CountsTheFinAsANonManifoldEdgeAndItsOrphanedApex) {
  auto input = test::heightFieldMesh(0.0, 3.0, 0.0, 3.0, 3, 3, [](double, double) { return 0.0; });
  input.vertices.push_back({1.5, 1.5, 1.0});  // a third triangle on the interior edge (5, 10)
  input.triangles.push_back({5, 10, static_cast<int>(input.vertices.size()) - 1});
  const ConversionReport r = convertMeshToDdf(input).report;
  EXPECT_EQ(r.nonManifoldEdges, 1);
  EXPECT_EQ(r.droppedFaces, 1);
  EXPECT_EQ(r.orphanedVertices, 1);
  EXPECT_EQ(r.unusedVertices, 0);
  EXPECT_TRUE(r.valid());
}

/// Collects warnings while alive.
class WarningCapture {
 public:
  WarningCapture()
      : previous_(setLogSink([this](LogLevel level, const std::string& message) {
          std::lock_guard lock(mutex_);
          if (level == LogLevel::Warning) text_ += message + "\n";
        })) {}
  ~WarningCapture() { setLogSink(previous_); }
  std::string text() {
    std::lock_guard lock(mutex_);
    return text_;
  }

 private:
  std::mutex mutex_;
  std::string text_;
  LogSink previous_;
};

TEST(ConversionReport, AFoldedFanIsReportedAsViolatingConstraint1) {
  WarningCapture warnings;
  const ConversionResult result = convertMeshToDdf(test::foldedFanMesh());
  const ConversionReport& r = result.report;
  ASSERT_TRUE(r.validated);
  EXPECT_FALSE(r.valid());
  // The report is the check `info` runs on the written field.
  EXPECT_EQ(r.validation.count(1), validate(result.ddf).count(1));
  const auto failures = constraintFailures(r.validation);
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].constraint, 1);
  EXPECT_EQ(failures[0].vertices, 1);  // vertex 0, the fan's centre
  EXPECT_GE(failures[0].faces, 1);
  EXPECT_EQ(r.infeasibleVertices, 1);
  EXPECT_TRUE(startsWith(conversionVerdict(r), "INVALID DDF: violates constraint 1"))
      << conversionVerdict(r);
  const std::string problems = joined(conversionProblemLines(r));
  EXPECT_TRUE(contains(problems, "constraint 1 (front-facing vectors) fails at 1 vertex"))
      << problems;
  EXPECT_TRUE(contains(problems, "vertex 0")) << problems;
  EXPECT_TRUE(contains(problems, "Change:")) << problems;
  EXPECT_TRUE(contains(warnings.text(), "INVALID DDF")) << warnings.text();
}

TEST(ConversionReport, UnweldedSeamsGetOneVectorPerPosition) {
  // Two 2 x 2 sheets meeting along x = 2 with their seam vertices 5e-7 mm apart: closer than
  // the 1e-6 mm at which constraint 2 calls vertices coincident.
  const auto flat = [](double, double) { return 0.0; };
  TriangleMesh input = test::heightFieldMesh(0.0, 2.0, 0.0, 2.0, 2, 2, flat);
  TriangleMesh right = test::heightFieldMesh(2.0 + 5e-7, 4.0, 0.0, 2.0, 2, 2, flat);
  for (auto& p : right.vertices) p.z() = 0.5 * (p.x() - 2.0);  // a crease along the seam
  const int base = static_cast<int>(input.vertices.size());
  input.vertices.insert(input.vertices.end(), right.vertices.begin(), right.vertices.end());
  for (const auto& t : right.triangles)
    input.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  // Welded by default: the weld tolerance is at least the coincidence tolerance.
  const ConversionReport welded = convertMeshToDdf(input).report;
  EXPECT_EQ(welded.weldedVertices, 3);
  EXPECT_TRUE(welded.valid());
  // Kept apart by a tiny weld tolerance, the seam's vertices share one vector instead.
  ConversionParams params;
  params.weldToleranceMm = 1e-9;
  const ConversionResult seam = convertMeshToDdf(input, params);
  EXPECT_EQ(seam.report.weldedVertices, 0);
  EXPECT_EQ(seam.report.unifiedVectors, 6);
  EXPECT_TRUE(seam.report.valid()) << joined(conversionProblemLines(seam.report));
  EXPECT_EQ(validate(seam.ddf).count(2), 0);
}

TEST(ConversionReport, CrossingCrustsLeftByTheLengthChoiceAreRepairedWithShorterVectors) {
  // Two parallel 4 x 4 mm sheets 0.5 mm apart, both facing +z: their +-1 crusts [z - l, z + l]
  // overlap unless every vector is at most 0.25 mm long; the mean edge length is ~1.1 mm.
  const auto flat = [](double, double) { return 0.0; };
  TriangleMesh input = test::heightFieldMesh(0.0, 4.0, 0.0, 4.0, 4, 4, flat);
  TriangleMesh upper = test::heightFieldMesh(0.0, 4.0, 0.0, 4.0, 4, 4, flat);
  const int base = static_cast<int>(input.vertices.size());
  for (auto p : upper.vertices) input.vertices.push_back(p + Vec3(0, 0, 0.5));
  for (const auto& t : upper.triangles)
    input.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  ConversionParams params;
  params.lengths.maxIterations = 1;  // one conflict round: not enough to separate the crusts
  params.validateResult = false;
  const ConversionResult unchecked = convertMeshToDdf(input, params);
  EXPECT_GT(validate(unchecked.ddf).count(3), 0);  // what the conversion returned before
  params.validateResult = true;
  const ConversionResult repaired = convertMeshToDdf(input, params);
  EXPECT_GE(repaired.report.lengthRetries, 1);
  EXPECT_TRUE(repaired.report.valid()) << joined(conversionProblemLines(repaired.report));
  double longest = 0.0;
  for (const Vec3& v : repaired.ddf.vectors()) longest = std::max(longest, v.norm());
  EXPECT_LE(longest, 0.25 + 1e-9);
  EXPECT_TRUE(contains(joined(conversionRepairLines(repaired.report)),
                       "made with shorter vectors to repair constraint 3"));
}

}  // namespace
}  // namespace ddfcam::ddf
