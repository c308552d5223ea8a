// SPDX-License-Identifier: MIT
// ddfcam gui: SetRegionsCommand.
#include <ddfcam/gui/region_commands.h>

#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/region_editing.h>

#include <utility>

namespace ddfcam::gui {

SetRegionsCommand::SetRegionsCommand(Document& document, const QString& text,
                                     std::vector<planning::Region> after)
    : DocumentCommand(document, text), other_(std::move(after)) {
  const planning::Project& project = document.project();
  if (!project.part) {
    if (!other_.empty()) throw InvalidInput("set regions: the project has no part");
    return;
  }
  // The project rules (ascending, unique, in range) plus: no face in two regions.
  planning::faceRegionIndex(other_, project.part->faceCount());
  for (const planning::Region& region : other_) {
    for (std::size_t i = 1; i < region.faces.size(); ++i)
      if (region.faces[i] <= region.faces[i - 1])
        throw InvalidInput("region '" + region.name + "': faces are not ascending and unique");
  }
}

std::size_t SetRegionsCommand::memoryBytes() const {
  std::size_t bytes = sizeof(*this);
  for (const planning::Region& region : other_)
    bytes += sizeof(region) + region.name.capacity() + region.faces.capacity() * sizeof(int);
  return bytes;
}

Changes SetRegionsCommand::apply(planning::Project& project) {
  // A swap cannot throw, so a refused edit is impossible once constructed.
  std::swap(project.regions, other_);
  return Change::Regions;
}

Changes SetRegionsCommand::revert(planning::Project& project) {
  std::swap(project.regions, other_);
  return Change::Regions;
}

}  // namespace ddfcam::gui
