// SPDX-License-Identifier: MIT
// ddfcam gui: undoable edits of existing tool paths (e.g. a smoothed streamline path).
#pragma once

#include <ddfcam/gui/document_command.h>

namespace ddfcam::gui {

/// @brief Replaces the tool path at an index by another (same place in the list); undo puts
/// the old one back.
class ReplacePathCommand : public DocumentCommand {
 public:
  /// @param text undo-stack text, e.g. "Smooth path 'streamline 3'".
  /// @throws InvalidInput if @p index is out of range or @p path fails the project's rules
  /// (planning::validateProject: tool index, pass starts).
  ReplacePathCommand(Document& document, int index, planning::ToolPath path, const QString& text);
  std::size_t memoryBytes() const override;

 protected:
  Changes apply(planning::Project& project) override;
  Changes revert(planning::Project& project) override;

 private:
  int index_;
  planning::ToolPath other_;  ///< the path not in the project: the new one before apply
};

}  // namespace ddfcam::gui
