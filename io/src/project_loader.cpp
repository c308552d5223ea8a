// SPDX-License-Identifier: MIT
// ddfcam: openProject, the one entry point for "File > Open".
#include <ddfcam/io/project_loader.h>

#include <ddfcam/io/mesh_io.h>
#include <ddfcam/io/project_file.h>
#include <ddfcam/progress.h>

#include "file_access.h"

#include <string>

namespace ddfcam::io {

using detail::lowerExtension;

bool isProjectFile(const std::filesystem::path& path) {
  return lowerExtension(path) == ".ddfproj";
}

bool canOpenAsProject(const std::filesystem::path& path) {
  return isProjectFile(path) || lowerExtension(path) == ".ddf" || meshFormatOf(path).has_value();
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
  project.part = loadPart(path, params, &report);
  project.partName = path.filename().string();
  project.sourcePath = path.string();
  // The conversion only reads the mesh; keeping it as the design lets the engineer measure
  // the part against what was delivered. A second read costs a small share of the conversion.
  if (report.converted) project.designMesh = readMesh(path);
  project.states.push_back({"stock", project.part->allHeights()});
  if (out) *out = std::move(report);
  return project;
}

}  // namespace ddfcam::io
