// SPDX-License-Identifier: MIT
// ddfcam gui: the workbench document, its undo history and the undo memory budget.
#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>

#include <QScopeGuard>
#include <QUndoCommand>
#include <QUndoStack>

#include <utility>
#include <vector>

namespace ddfcam::gui {
namespace {

/// What the QUndoStack actually holds: a thin owner of the pushed command. QUndoStack can
/// neither hand a command back nor drop its oldest ones, so the command itself lives in a
/// shared_ptr; enforceUndoBudget() keeps the newest commands alive while it clears the stack
/// and pushes fresh entries for them.
class HistoryEntry : public QUndoCommand {
 public:
  /// @param skipFirstRedo the command is already applied; QUndoStack::push must not redo it.
  HistoryEntry(std::shared_ptr<QUndoCommand> command, bool skipFirstRedo)
      : command_(std::move(command)), skipRedo_(skipFirstRedo) {
    sync();
  }

  void redo() override {
    if (std::exchange(skipRedo_, false)) return;
    command_->redo();
    sync();
  }
  void undo() override {
    command_->undo();
    sync();
  }
  // No merging: merged commands would hide their payloads from the budget.
  int id() const override { return -1; }

  const std::shared_ptr<QUndoCommand>& command() const { return command_; }

  std::size_t memoryBytes() const {
    if (const auto* document = dynamic_cast<const DocumentCommand*>(command_.get()))
      return document->memoryBytes();
    return sizeof(QUndoCommand);
  }

 private:
  void sync() {
    setText(command_->text());
    setObsolete(command_->isObsolete());
  }

  std::shared_ptr<QUndoCommand> command_;
  bool skipRedo_;
};

std::size_t entryBytes(const QUndoCommand* command) {
  if (const auto* entry = dynamic_cast<const HistoryEntry*>(command)) return entry->memoryBytes();
  if (const auto* document = dynamic_cast<const DocumentCommand*>(command))
    return document->memoryBytes();
  return sizeof(QUndoCommand);
}

}  // namespace

Document::Document(DocumentParams params, QObject* parent)
    : QObject(parent), undo_(new QUndoStack(this)), params_(params) {
  connect(undo_, &QUndoStack::indexChanged, this, &Document::updateModified);
  connect(undo_, &QUndoStack::cleanChanged, this, &Document::updateModified);
}

Document::~Document() {
  // The stack clears itself (and signals) when deleted; by the time QObject deletes its
  // children the members the slots read are gone, so it goes first, unconnected.
  undo_->disconnect(this);
  delete undo_;
}

void Document::reset(planning::Project project, const QString& filePath) {
  planning::validateProject(project);
  undo_->clear();
  undo_->setClean();
  modifiedWithoutHistory_ = false;
  project_ = std::move(project);
  if (filePath_ != filePath) {
    filePath_ = filePath;
    emit filePathChanged(filePath_);
  }
  notify(Change::All);
  updateModified();
}

void Document::push(std::unique_ptr<QUndoCommand> command) {
  if (!command) throw InvalidInput("Document::push: null command");
  std::shared_ptr<QUndoCommand> shared(std::move(command));
  // The first redo runs here rather than inside QUndoStack::push, so an exception never
  // crosses Qt code and nothing is on the stack when it is thrown.
  shared->redo();
  if (shared->isObsolete()) return;  // the command declared itself a no-op
  undo_->push(new HistoryEntry(std::move(shared), /*skipFirstRedo=*/true));
  enforceUndoBudget();
  updateModified();
}

void Document::markSaved(const QString& filePath) {
  undo_->setClean();
  modifiedWithoutHistory_ = false;
  if (filePath_ != filePath) {
    filePath_ = filePath;
    emit filePathChanged(filePath_);
  }
  updateModified();
}

void Document::markModified() {
  modifiedWithoutHistory_ = true;
  undo_->resetClean();
  updateModified();
}

bool Document::isModified() const {
  return modifiedWithoutHistory_ || !undo_->isClean();
}

std::size_t Document::undoMemoryBytes() const {
  std::size_t total = 0;
  for (int i = 0; i < undo_->count(); ++i) total += entryBytes(undo_->command(i));
  return total;
}

void Document::notify(Changes what) {
  ++revision_;
  emit changed(what);
}

void Document::enforceUndoBudget() {
  const int count = undo_->count();
  std::vector<std::size_t> bytes(static_cast<std::size_t>(count));
  std::size_t total = 0;
  for (int i = 0; i < count; ++i) total += bytes[i] = entryBytes(undo_->command(i));
  // Drop the oldest commands until the rest fits; the newest may not fit on its own, in
  // which case nothing can be undone any more.
  int keepFrom = 0;
  while (keepFrom < count && total > params_.undoBudgetBytes) total -= bytes[keepFrom++];
  if (keepFrom == 0) return;

  std::vector<std::shared_ptr<QUndoCommand>> kept;
  for (int i = keepFrom; i < count; ++i) {
    const auto* entry = dynamic_cast<const HistoryEntry*>(undo_->command(i));
    if (!entry) return;  // pushed past Document::push; cannot be carried over, keep the stack
    kept.push_back(entry->command());
  }
  // Every kept command is applied (push() leaves the index at the top), so re-pushing them
  // with their first redo suppressed rebuilds the same history, minus its oldest part.
  const int oldClean = undo_->cleanIndex();
  const int newClean = oldClean >= keepFrom ? oldClean - keepFrom : -1;
  rebuilding_ = true;
  const auto endRebuild = qScopeGuard([this] { rebuilding_ = false; });
  undo_->clear();
  for (int i = 0; i < static_cast<int>(kept.size()); ++i) {
    if (i == newClean) undo_->setClean();
    undo_->push(new HistoryEntry(kept[static_cast<std::size_t>(i)], /*skipFirstRedo=*/true));
  }
  if (newClean == static_cast<int>(kept.size())) {
    undo_->setClean();
  } else if (newClean < 0) {
    // The saved state is no longer reachable: whatever undo reaches now differs from the file.
    undo_->resetClean();
    modifiedWithoutHistory_ = true;
  }
}

void Document::updateModified() {
  if (rebuilding_) return;
  const bool modified = isModified();
  if (modified == lastModified_) return;
  lastModified_ = modified;
  emit modifiedChanged(modified);
}

}  // namespace ddfcam::gui
