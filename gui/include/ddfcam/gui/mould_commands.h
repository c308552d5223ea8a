// SPDX-License-Identifier: MIT
// ddfcam gui: undoable edits of the project's mould study (Project::mould).
#pragma once

#include <ddfcam/gui/document_command.h>
#include <ddfcam/planning/mould/mould_study.h>

#include <cstddef>
#include <optional>

namespace ddfcam::gui {

/// @brief Bytes a mould study holds (meshes, fields, comparison result, history), for the undo
/// budget; an estimate from the container sizes.
std::size_t mouldStudyBytes(const planning::MouldStudy& study);

/// @brief Replaces Project::mould by @p after (undo restores @p before); notifies
/// Change::Mould. Both states are kept whole: mould edits are rare and whole studies are
/// simpler to restore than deltas.
class SetMouldStudyCommand : public DocumentCommand {
 public:
  /// @param before the study as it is now (what undo restores); std::nullopt = none.
  /// @param after the new study; std::nullopt removes it.
  /// @throws InvalidInput if @p after fails planning::validateMouldStudy.
  SetMouldStudyCommand(Document& document, std::optional<planning::MouldStudy> before,
                       std::optional<planning::MouldStudy> after, const QString& text);
  std::size_t memoryBytes() const override;

 protected:
  Changes apply(planning::Project& project) override;
  Changes revert(planning::Project& project) override;

 private:
  std::optional<planning::MouldStudy> before_;
  std::optional<planning::MouldStudy> after_;
};

/// @brief Replaces the compensation history of Project::mould by @p after (undo restores the
/// history found when it was first applied); notifies Change::Mould. Only the history is kept,
/// not the whole study: a compensation step leaves surfaces and comparison alone.
class SetCompensationCommand : public DocumentCommand {
 public:
  /// @param after the new history; std::nullopt removes it.
  SetCompensationCommand(Document& document, const QString& text,
                         std::optional<planning::CompensationHistory> after);
  std::size_t memoryBytes() const override;

 protected:
  /// @throws InvalidInput if the project has no mould study.
  Changes apply(planning::Project& project) override;
  Changes revert(planning::Project& project) override;

 private:
  std::optional<planning::CompensationHistory> before_;
  std::optional<planning::CompensationHistory> after_;
};

}  // namespace ddfcam::gui
