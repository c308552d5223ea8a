// SPDX-License-Identifier: MIT
// ddfcam gui: the undoable edit of a project's regions (segmentation, brush, lasso, plans).
#pragma once

#include <ddfcam/gui/document_command.h>
#include <ddfcam/planning/model/project.h>

#include <vector>

namespace ddfcam::gui {

/// @brief Replaces Project::regions as a whole: automatic segmentation, a brush stroke, a
/// lasso, merge, split, rename, delete and plan edits are each one such command (the region
/// editing functions of planning/region_editing.h compute the new list). Holds the list before
/// and after (memory in proportion to the regions' faces).
class SetRegionsCommand : public DocumentCommand {
 public:
  /// @param text undo text, e.g. "Paint 12 faces into 'convex 1'".
  /// @param after the new regions, checked against the part by planning::validateProject.
  /// @throws InvalidInput if there is no part and @p after is not empty, or @p after breaks
  /// the project's region rules (faces ascending, unique, in range).
  SetRegionsCommand(Document& document, const QString& text, std::vector<planning::Region> after);
  std::size_t memoryBytes() const override;

 protected:
  Changes apply(planning::Project& project) override;
  Changes revert(planning::Project& project) override;

 private:
  std::vector<planning::Region> other_;  ///< the list not currently in the project
};

}  // namespace ddfcam::gui
