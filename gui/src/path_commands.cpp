// SPDX-License-Identifier: MIT
// ddfcam gui: ReplacePathCommand.
#include <ddfcam/gui/path_commands.h>

#include <ddfcam/error.h>

#include <string>
#include <utility>

namespace ddfcam::gui {

ReplacePathCommand::ReplacePathCommand(Document& document, int index, planning::ToolPath path,
                                       const QString& text)
    : DocumentCommand(document, text), index_(index), other_(std::move(path)) {
  const planning::Project& project = document.project();
  if (index < 0 || index >= static_cast<int>(project.paths.size()))
    throw InvalidInput("replace path: no path " + std::to_string(index) + " (the project has " +
                       std::to_string(project.paths.size()) + ")");
  planning::Project probe;
  probe.tools = project.tools;
  probe.paths.push_back(other_);
  planning::validateProject(probe);
}

std::size_t ReplacePathCommand::memoryBytes() const {
  return sizeof(*this) + other_.name.capacity() +
         other_.poses.capacity() * sizeof(planning::PathPose) +
         other_.passStarts.capacity() * sizeof(int) +
         planning::rawLinesBytes(other_);
}

Changes ReplacePathCommand::apply(planning::Project& project) {
  std::swap(project.paths[index_], other_);
  return Change::Paths;
}

Changes ReplacePathCommand::revert(planning::Project& project) {
  std::swap(project.paths[index_], other_);
  return Change::Paths;
}

}  // namespace ddfcam::gui
