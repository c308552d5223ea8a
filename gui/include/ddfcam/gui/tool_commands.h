// SPDX-License-Identifier: MIT
// ddfcam gui: undoable edits of the project's tool list (add, edit, duplicate, delete, load).
#pragma once

#include <ddfcam/gui/document_command.h>
#include <ddfcam/planning/tools/tool.h>

#include <vector>

namespace ddfcam::gui {

/// @brief Replaces Project::tools by another list and renumbers the paths' tool indices so
/// that every path keeps its tool; undo puts the old list and indices back exactly.
class SetToolsCommand : public DocumentCommand {
 public:
  /// @param tools the new tool list.
  /// @param newIndexOfOld #old-tools entries: the index in @p tools of each current tool, or
  /// -1 for a tool that is removed. Empty: identity (the first tools keep their places).
  /// @param text undo-stack text, e.g. "Edit tool 'roll R5 W10'".
  /// @throws InvalidInput if a tool fails planning::validateTool(), if @p newIndexOfOld has
  /// the wrong size or an index out of range, or if a removed tool is still used by a path
  /// (the message names the path).
  SetToolsCommand(Document& document, std::vector<planning::Tool> tools,
                  std::vector<int> newIndexOfOld, const QString& text);
  std::size_t memoryBytes() const override;

 protected:
  Changes apply(planning::Project& project) override;
  Changes revert(planning::Project& project) override;

 private:
  std::vector<planning::Tool> other_;  ///< the list not in the project
  std::vector<int> pathToolsBefore_;   ///< #paths tool indices before apply
  std::vector<int> pathToolsAfter_;    ///< #paths tool indices after apply
};

/// @brief The tool list with @p tool appended (a helper for "Add" and "Duplicate").
std::vector<planning::Tool> toolsWithAppended(const planning::Project& project,
                                              const planning::Tool& tool);

}  // namespace ddfcam::gui
