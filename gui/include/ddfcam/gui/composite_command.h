// SPDX-License-Identifier: MIT
// ddfcam gui: several document edits as one undo step (e.g. a refined path and its error map).
#pragma once

#include <ddfcam/gui/document_command.h>

#include <memory>
#include <vector>

namespace ddfcam::gui {

/// @brief Applies its parts in order and reverts them in reverse order, as one undo step.
/// If a part refuses on the first redo, the parts applied before it are reverted and the
/// exception propagates (Document::push then refuses the whole edit).
class CompositeCommand : public DocumentCommand {
 public:
  /// @throws InvalidInput if @p parts is empty or holds a null command.
  CompositeCommand(Document& document, const QString& text,
                   std::vector<std::unique_ptr<DocumentCommand>> parts);
  std::size_t memoryBytes() const override;

 protected:
  Changes apply(planning::Project& project) override;
  Changes revert(planning::Project& project) override;

 private:
  std::vector<std::unique_ptr<DocumentCommand>> parts_;
};

}  // namespace ddfcam::gui
