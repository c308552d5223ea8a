// SPDX-License-Identifier: MIT
// Tests of the mould study's invariants and exact equality, alone and inside a project.
#include <ddfcam/error.h>
#include <ddfcam/planning/model/project.h>
#include <ddfcam/planning/mould/mould_study.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "../../support/mould_study_sample.h"

namespace ddfcam::planning {
namespace {

using Edit = std::function<void(MouldStudy&)>;

std::string validationMessage(const MouldStudy& study) {
  try {
    validateMouldStudy(study);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return {};
}

TEST(MouldStudy, SampleAndDefaultAreValid) {
  EXPECT_NO_THROW(validateMouldStudy(test::sampleMouldStudy()));
  EXPECT_NO_THROW(validateMouldStudy(MouldStudy{}));
}

TEST(MouldStudy, ValidationNamesTheOffendingItem) {
  const std::vector<std::pair<Edit, std::string>> cases = {
      {[](MouldStudy& s) { s.mould.mesh.triangles[1][2] = 9; }, "mould mesh: triangle 1"},
      {[](MouldStudy& s) { s.formed->fields[0].values.push_back(1.0f); },
       "formed surface field 'strain' (per cell): 3 values, expected 2"},
      {[](MouldStudy& s) { s.mould.fields[0].values.pop_back(); }, "mould field 'thickness'"},
      {[](MouldStudy& s) { s.alignment.pointPairs.pop_back(); }, "at least three pairs"},
      {[](MouldStudy& s) { s.alignment.transform[5] = INFINITY; }, "transform is not finite"},
      {[](MouldStudy& s) { s.alignment.method = static_cast<AlignmentMethod>(7); },
       "unknown method 7"},
      {[](MouldStudy& s) { s.comparison.resolution = 1; }, "resolution 1"},
      {[](MouldStudy& s) { s.comparison.sequence.maxStages = 0; }, "at least one stage"},
      {[](MouldStudy& s) { s.result->sequence.stages.clear(); }, "no stage"},
      {[](MouldStudy& s) { s.result->deviation.values.pop_back(); },
       "comparison deviation: 47 values, expected 48"},
      {[](MouldStudy& s) { s.result->deviationVectors.clear(); }, "deviation vectors: 0 values"},
      {[](MouldStudy& s) { s.result->sequence.deformedPoints.pop_back(); }, "deformed points"},
      {[](MouldStudy& s) {
         s.result->sequence.crossingFaces = {4, 1};
       },
       "ascending"},
      {[](MouldStudy& s) { s.result->sequence.unresolvedFaces = {8}; }, "face 8 out of range"},
      {[](MouldStudy& s) { s.result->sequence.stages[0].crossingFaces = {-1}; }, "stage 0"},
      {[](MouldStudy& s) { s.result->sequence.missingPoints = 49; }, "49 missing points"},
      {[](MouldStudy& s) { s.compensation->iterations.clear(); }, "no iteration"},
      {[](MouldStudy& s) { s.compensation->iterations[1].mouldHeights.pop_back(); },
       "compensation iteration 1 mould heights"},
      {[](MouldStudy& s) { s.compensation->iterations[0].formedHeights.resize(3); },
       "iteration 0 formed heights: 3 values"},
  };
  for (const auto& [edit, expected] : cases) {
    MouldStudy study = test::sampleMouldStudy();
    edit(study);
    const std::string message = validationMessage(study);
    EXPECT_NE(message.find(expected), std::string::npos)
        << "expected '" << expected << "', got '" << message << "'";
  }
}

TEST(MouldStudy, EqualityIsExactOnEveryMember) {
  const MouldStudy base = test::sampleMouldStudy();
  EXPECT_TRUE(mouldStudiesEqual(base, test::sampleMouldStudy()));  // NaNs at the same places
  const std::vector<Edit> edits = {
      [](MouldStudy& s) { s.mould.name += "x"; },
      [](MouldStudy& s) { s.mould.sourcePath.clear(); },
      [](MouldStudy& s) { s.mould.mesh.vertices[0].x() = -0.0; },
      [](MouldStudy& s) { s.mould.fields[0].unit = "um"; },
      [](MouldStudy& s) { s.formed.reset(); },
      [](MouldStudy& s) { s.formed->fields[0].perCell = false; },
      [](MouldStudy& s) { s.formed->fields[0].values[1] = 0.0f; },  // -0 -> +0
      [](MouldStudy& s) { s.alignment.method = AlignmentMethod::BestFit; },
      [](MouldStudy& s) { s.alignment.transform[15] = 2.0; },
      [](MouldStudy& s) { s.alignment.rmsMm = 0.5; },
      [](MouldStudy& s) { s.alignment.pointPairs[2][1].y() = 3.0; },
      [](MouldStudy& s) { s.comparison.resolution = 4; },
      [](MouldStudy& s) { s.comparison.band.upperMm = 0.5; },
      [](MouldStudy& s) { s.comparison.flipNormal = false; },
      [](MouldStudy& s) { s.comparison.sequence.reachMm = 0.0; },
      [](MouldStudy& s) { s.comparison.sequence.crustSafety = 0.8; },
      [](MouldStudy& s) { s.comparison.sequence.maxStages = 6; },
      [](MouldStudy& s) { s.result.reset(); },
      [](MouldStudy& s) { s.result->sequence.stages[1].fraction = 0.75; },
      [](MouldStudy& s) { s.result->sequence.stages[0].crossingFaces.pop_back(); },
      [](MouldStudy& s) { s.result->sequence.stages[0].ddf.allHeights()[7] = 0.0f; },
      [](MouldStudy& s) { s.result->sequence.deformedPoints[3].z() = 1.0; },
      [](MouldStudy& s) { s.result->sequence.crossingFaces = {1}; },
      [](MouldStudy& s) { s.result->sequence.unresolvedFaces.clear(); },
      [](MouldStudy& s) { s.result->sequence.missingPoints = 2; },
      [](MouldStudy& s) { s.result->deviation.isSigned = false; },
      [](MouldStudy& s) { s.result->deviation.values[0] = 0.5f; },
      [](MouldStudy& s) { s.result->deviationVectors[0].x() = 1.0; },
      [](MouldStudy& s) { s.result->statistics.inTolerancePercent = 91.0; },
      [](MouldStudy& s) { s.result->statistics.points = 25; },
      [](MouldStudy& s) { s.result->band.lowerMm = -0.5; },
      [](MouldStudy& s) { s.compensation.reset(); },
      [](MouldStudy& s) { s.compensation->target.allHeights()[0] = 0.5f; },
      [](MouldStudy& s) { s.compensation->iterations[0].formedSource = "model"; },
      [](MouldStudy& s) { s.compensation->iterations[0].formedHeights[2] = 0.3f; },
      [](MouldStudy& s) { s.compensation->iterations[1].maxDeviationMm = 0.0; },
      [](MouldStudy& s) { s.compensation->iterations[1].lambda = 0.5; },
      [](MouldStudy& s) { s.compensation->iterations[1].pointsOutsideCrust = 0; },
  };
  for (std::size_t i = 0; i < edits.size(); ++i) {
    MouldStudy changed = test::sampleMouldStudy();
    edits[i](changed);
    EXPECT_FALSE(mouldStudiesEqual(base, changed)) << "edit " << i;
    EXPECT_FALSE(mouldStudiesEqual(changed, base)) << "edit " << i;
  }
}

TEST(MouldStudy, ProjectCoversTheStudy) {
  Project a;
  Project b;
  a.mould = test::sampleMouldStudy();
  EXPECT_NO_THROW(validateProject(a));  // a mould study needs no part
  EXPECT_FALSE(projectsEqual(a, b));
  b.mould = test::sampleMouldStudy();
  EXPECT_TRUE(projectsEqual(a, b));
  b.mould->result->deviation.values[3] = 0.0f;
  EXPECT_FALSE(projectsEqual(a, b));
  a.mould->mould.mesh.triangles[0][0] = -1;
  EXPECT_THROW(validateProject(a), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
