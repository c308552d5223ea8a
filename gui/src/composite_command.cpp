// SPDX-License-Identifier: MIT
// ddfcam gui: several document edits as one undo step.
#include <ddfcam/error.h>
#include <ddfcam/gui/composite_command.h>

namespace ddfcam::gui {

CompositeCommand::CompositeCommand(Document& document, const QString& text,
                                   std::vector<std::unique_ptr<DocumentCommand>> parts)
    : DocumentCommand(document, text), parts_(std::move(parts)) {
  if (parts_.empty()) throw InvalidInput("a composite edit needs at least one part");
  for (const auto& part : parts_)
    if (!part) throw InvalidInput("a composite edit got an empty part");
}

std::size_t CompositeCommand::memoryBytes() const {
  std::size_t bytes = sizeof(*this);
  for (const auto& part : parts_) bytes += part->memoryBytes();
  return bytes;
}

Changes CompositeCommand::apply(planning::Project& project) {
  Changes changed;
  std::size_t done = 0;
  try {
    for (; done < parts_.size(); ++done) changed |= parts_[done]->apply(project);
  } catch (...) {
    while (done > 0) parts_[--done]->revert(project);
    throw;
  }
  return changed;
}

Changes CompositeCommand::revert(planning::Project& project) {
  Changes changed;
  for (auto it = parts_.rbegin(); it != parts_.rend(); ++it) changed |= (*it)->revert(project);
  return changed;
}

}  // namespace ddfcam::gui
