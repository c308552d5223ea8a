// SPDX-License-Identifier: MIT
// ddfcam gui: the base of every undoable document edit, and the edits the shell itself needs.
#pragma once

#include <ddfcam/gui/document.h>
#include <ddfcam/planning/model/height_delta.h>
#include <ddfcam/planning/model/project.h>

#include <QUndoCommand>

#include <cstddef>
#include <optional>

namespace ddfcam::gui {

/// @brief An undoable edit of a Document. Subclasses implement apply() and revert() on
/// document().editableProject() and return what they touched; the base calls notify().
/// The first redo() (inside Document::push) may throw to refuse the edit: apply() must then
/// leave the project unchanged.
class DocumentCommand : public QUndoCommand {
 public:
  DocumentCommand(Document& document, const QString& text);
  void redo() final;
  void undo() final;
  /// @brief Bytes this command holds (for the undo budget); default sizeof(*this).
  virtual std::size_t memoryBytes() const;

 protected:
  // A composite applies its parts' edits in one undo step.
  friend class CompositeCommand;
  /// @brief Performs the edit; returns what changed.
  virtual Changes apply(planning::Project& project) = 0;
  /// @brief Undoes apply(); returns what changed.
  virtual Changes revert(planning::Project& project) = 0;
  Document& document() const { return document_; }

 private:
  Document& document_;
};

/// @brief Replaces the part's heights, stored as a planning::HeightDelta (memory in proportion
/// to the faces that changed); optionally appends a simulation state recording the result.
class SetHeightsCommand : public DocumentCommand {
 public:
  /// @param after new heights, laid out like allHeights() of the current part.
  /// @param state if set, appended to Project::states on redo, removed on undo.
  /// @throws InvalidInput if there is no part or @p after has the wrong size.
  SetHeightsCommand(Document& document, const QString& text, const std::vector<float>& after,
                    std::optional<planning::SimulationState> state = std::nullopt);
  std::size_t memoryBytes() const override;

 protected:
  Changes apply(planning::Project& project) override;
  Changes revert(planning::Project& project) override;

 private:
  planning::HeightDelta delta_;
  std::optional<planning::SimulationState> state_;
};

/// @brief Appends a scalar field (or replaces the field of the same name, keeping its place).
class AddFieldCommand : public DocumentCommand {
 public:
  /// @throws InvalidInput if there is no part or the field has the wrong size.
  AddFieldCommand(Document& document, planning::ScalarField field);
  std::size_t memoryBytes() const override;

 protected:
  Changes apply(planning::Project& project) override;
  Changes revert(planning::Project& project) override;

 private:
  planning::ScalarField field_;
  std::optional<planning::ScalarField> replaced_;
  int index_ = -1;
};

/// @brief Removes the field at an index.
class RemoveFieldCommand : public DocumentCommand {
 public:
  /// @throws InvalidInput if @p index is out of range.
  RemoveFieldCommand(Document& document, int index);
  std::size_t memoryBytes() const override;

 protected:
  Changes apply(planning::Project& project) override;
  Changes revert(planning::Project& project) override;

 private:
  int index_;
  planning::ScalarField removed_;
};

/// @brief Appends a tool path (and its tool, if given, as a new tool the path refers to).
class AddPathCommand : public DocumentCommand {
 public:
  AddPathCommand(Document& document, planning::ToolPath path,
                 std::optional<planning::Tool> tool = std::nullopt);
  std::size_t memoryBytes() const override;

 protected:
  Changes apply(planning::Project& project) override;
  Changes revert(planning::Project& project) override;

 private:
  planning::ToolPath path_;
  std::optional<planning::Tool> tool_;
};

}  // namespace ddfcam::gui
