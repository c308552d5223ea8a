// SPDX-License-Identifier: MIT
// Test support: small projects and height edits shared by the Document tests.
#pragma once

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/planning/model/project.h>

#include <cstddef>
#include <string>
#include <vector>

namespace ddfcam::test {

/// A project of a plane patch of @p cells x @p cells cells: every height is 0.25 (z = 0.25, vectors
/// of 1).
inline planning::Project planeProject(int cells = 4, int m = 5) {
  ddf::PlanePatchParams params;
  params.cellsX = cells;
  params.cellsY = cells;
  params.m = m;
  planning::Project project;
  project.partName = "plane";
  project.part = ddf::planePatch(params).ddf;
  return project;
}

/// A field named @p name (unit mm) of @p value at every stored raster point of @p project.
inline planning::ScalarField constantField(const planning::Project& project,
                                           const std::string& name, float value) {
  planning::ScalarField field;
  field.name = name;
  field.unit = "mm";
  field.values.assign(project.part->allHeights().size(), value);
  return field;
}

/// Heights with the faces in [firstFace, firstFace + faces) set to @p value, others as @p base.
inline std::vector<float> withFaces(std::vector<float> base, std::size_t pointsPerFace,
                                    int firstFace, int faces, float value) {
  for (std::size_t i = firstFace * pointsPerFace; i < (firstFace + faces) * pointsPerFace; ++i)
    base[i] = value;
  return base;
}

}  // namespace ddfcam::test
