// SPDX-License-Identifier: MIT
// ddfcam: openProject, the one entry point for "File > Open".
#include <ddfcam/io/project/project_loader.h>

#include <ddfcam/io/cad/cad_model.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/project/project_file.h>
#include <ddfcam/progress.h>

#include "../common/file_access.h"

#include <string>

namespace ddfcam::io {

using detail::lowerExtension;

bool isProjectFile(const std::filesystem::path& path) {
  return lowerExtension(path) == ".ddfproj";
}

bool canOpenAsProject(const std::filesystem::path& path) {
  return isProjectFile(path) || lowerExtension(path) == ".ddf" || meshFormatOf(path).has_value() ||
         isCadFile(path);
}

planning::Project openProject(const std::filesystem::path& path, const LoadPartParams& params,
                              LoadPartReport* out) {
  if (out) *out = LoadPartReport{};
  if (isProjectFile(path)) {
    reportProgress(params.progress, 0.0);
    planning::Project project = readProject(path);
    reportProgress(params.progress, 1.0);
    return project;
  }
  LoadPartReport report;
  planning::Project project;
  LoadedPart part = loadPartWithInput(path, params, &report);
  project.part = std::move(part.ddf);
  project.partName = path.filename().string();
  project.sourcePath = path.string();
  project.sourceUnit = report.unit;
  project.cadFaceOfSupportFace = report.cadFaceOfSupportFace;
  project.cadFaceNames = report.cadFaceNames;
  // The converted triangles (the scaled mesh, or a CAD model's tessellation, also as stored in
  // a .ddf file) are the design: the engineer measures the part against what was delivered.
  if (!part.inputMesh.triangles.empty()) project.designMesh = std::move(part.inputMesh);
  project.states.push_back({"stock", project.part->allHeights()});
  if (out) *out = std::move(report);
  return project;
}

}  // namespace ddfcam::io
