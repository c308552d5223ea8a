// SPDX-License-Identifier: MIT
// ddfcam gui: SetMouldStudyCommand, SetCompensationCommand and the size estimate of a mould
// study.
#include <ddfcam/error.h>
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

std::size_t historyBytes(const std::optional<planning::CompensationHistory>& history) {
  if (!history) return 0;
  std::size_t bytes = history->target.memoryBytes();
  for (const planning::CompensationIteration& it : history->iterations)
    bytes += (it.mouldHeights.size() + it.formedHeights.size()) * sizeof(float);
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
  return bytes + historyBytes(study.compensation);
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

SetCompensationCommand::SetCompensationCommand(Document& document, const QString& text,
                                               std::optional<planning::CompensationHistory> after)
    : DocumentCommand(document, text), after_(std::move(after)) {}

std::size_t SetCompensationCommand::memoryBytes() const {
  return sizeof(*this) + historyBytes(before_) + historyBytes(after_);
}

Changes SetCompensationCommand::apply(planning::Project& project) {
  if (!project.mould) throw InvalidInput("the project has no mould study");
  before_ = project.mould->compensation;
  project.mould->compensation = after_;
  return Change::Mould;
}

Changes SetCompensationCommand::revert(planning::Project& project) {
  project.mould->compensation = before_;
  return Change::Mould;
}

}  // namespace ddfcam::gui
