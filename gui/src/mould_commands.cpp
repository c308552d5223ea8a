// SPDX-License-Identifier: MIT
// ddfcam gui: SetMouldStudyCommand and the size estimate of a mould study.
#include <ddfcam/gui/mould_commands.h>

namespace ddfcam::gui {
namespace {

std::size_t meshBytes(const ddf::TriangleMesh& mesh) {
  return mesh.vertices.size() * sizeof(ddf::Vec3) +
         mesh.triangles.size() * sizeof(mesh.triangles[0]);
}

std::size_t surfaceBytes(const planning::LoadedSurface& surface) {
  std::size_t bytes = meshBytes(surface.mesh) + surface.name.size() + surface.sourcePath.size();
  for (const planning::MeshField& field : surface.fields)
    bytes += field.values.size() * sizeof(float) + field.name.size();
  return bytes;
}

}  // namespace

std::size_t mouldStudyBytes(const planning::MouldStudy& study) {
  std::size_t bytes = sizeof(study) + surfaceBytes(study.mould);
  if (study.formed) bytes += surfaceBytes(*study.formed);
  if (study.result) {
    const planning::SurfaceComparison& r = *study.result;
    for (const ddf::DeformationStage& stage : r.sequence.stages) bytes += stage.ddf.memoryBytes();
    bytes += r.sequence.deformedPoints.size() * sizeof(ddf::Vec3);
    bytes += r.deviation.values.size() * sizeof(float);
    bytes += r.deviationVectors.size() * sizeof(ddf::Vec3);
  }
  if (study.compensation)
    for (const auto& iteration : study.compensation->iterations)
      bytes += iteration.mouldHeights.size() * sizeof(float) * 3;
  return bytes;
}

SetMouldStudyCommand::SetMouldStudyCommand(Document& document,
                                           std::optional<planning::MouldStudy> before,
                                           std::optional<planning::MouldStudy> after,
                                           const QString& text)
    : DocumentCommand(document, text), before_(std::move(before)), after_(std::move(after)) {
  if (after_) planning::validateMouldStudy(*after_);
}

std::size_t SetMouldStudyCommand::memoryBytes() const {
  return sizeof(*this) + (before_ ? mouldStudyBytes(*before_) : 0) +
         (after_ ? mouldStudyBytes(*after_) : 0);
}

Changes SetMouldStudyCommand::apply(planning::Project& project) {
  project.mould = after_;
  return Change::Mould;
}

Changes SetMouldStudyCommand::revert(planning::Project& project) {
  project.mould = before_;
  return Change::Mould;
}

}  // namespace ddfcam::gui
