// SPDX-License-Identifier: MIT
// ddfcam gui: the workbench document: one planning::Project, its undo stack and change signals.
#pragma once

#include <ddfcam/planning/model/project.h>

#include <QFlags>
#include <QObject>
#include <QString>

#include <cstddef>
#include <cstdint>
#include <memory>

class QUndoCommand;
class QUndoStack;

namespace ddfcam::gui {

/// @brief What part of the project an edit touched; views refresh only what changed.
enum class Change : unsigned {
  Part = 1u << 0,      ///< the part was replaced (support, vectors, heights, name)
  Heights = 1u << 1,   ///< the part's heights changed (e.g. a simulated pass, an undo of one)
  Fields = 1u << 2,    ///< fields were added, removed or changed
  Regions = 1u << 3,   ///< regions
  Tools = 1u << 4,     ///< tools
  Paths = 1u << 5,     ///< tool paths
  States = 1u << 6,    ///< simulation states
  Surfaces = 1u << 7,  ///< deformed / mould surfaces
  Design = 1u << 8,    ///< the design (reference) mesh
  Mould = 1u << 9,     ///< mould planning: surfaces, alignment, comparison, compensation
  All = 0x3ffu,
};
Q_DECLARE_FLAGS(Changes, Change)
Q_DECLARE_OPERATORS_FOR_FLAGS(Changes)

/// @brief Parameters of Document.
struct DocumentParams {
  /// Memory the undo history may hold, bytes: when the commands on the stack hold more, the
  /// oldest are dropped (they can no longer be undone). Default 512 MiB.
  std::size_t undoBudgetBytes = std::size_t{512} << 20;
};

/// @brief Owns the project of a session. Every edit goes through push() as a DocumentCommand,
/// so it can be undone; whole-document operations (new, open, recover) go through reset(),
/// which clears the history. Emits changed() after every edit, undo and redo. Lives on the
/// UI thread; jobs compute on copies of the values they need and push their result.
class Document : public QObject {
  Q_OBJECT

 public:
  explicit Document(DocumentParams params = {}, QObject* parent = nullptr);
  ~Document() override;

  /// @brief The project (read only; edit through push()).
  const planning::Project& project() const { return project_; }
  /// @brief The undo stack (for Edit > Undo/Redo actions and an undo view).
  QUndoStack* undoStack() const { return undo_; }

  /// @brief Replaces the whole project, clears the undo history, sets the file path (empty for
  /// an unsaved project) and marks the document unmodified. Emits changed(Change::All).
  /// @throws InvalidInput (planning::validateProject) before anything is replaced.
  void reset(planning::Project project, const QString& filePath = {});
  /// @brief Runs @p command's redo() and puts it on the undo stack (takes ownership). An
  /// exception from the first redo() propagates and leaves the document unchanged.
  void push(std::unique_ptr<QUndoCommand> command);

  /// @brief Project file the document was loaded from or saved to; empty if none.
  QString filePath() const { return filePath_; }
  /// @brief Records that the project was saved to @p filePath now (clean undo state).
  void markSaved(const QString& filePath);
  /// @brief Marks the project as differing from its file without an undoable edit (e.g. a
  /// project recovered after a crash); it stays modified until markSaved() or reset().
  void markModified();
  /// @brief True if the project differs from the last save (or reset).
  bool isModified() const;
  /// @brief Number of edits since the document was created (never decreases; autosave uses it
  /// to notice new edits, undo and redo included).
  std::uint64_t revision() const { return revision_; }
  /// @brief Bytes held by the commands on the undo stack (DocumentCommand::memoryBytes()).
  std::size_t undoMemoryBytes() const;
  /// @brief The undo budget in use.
  const DocumentParams& params() const { return params_; }

  /// @brief Mutable access for DocumentCommand implementations only; call notify() after.
  planning::Project& editableProject() { return project_; }
  /// @brief Signals @p what as changed and counts a revision; commands call it after editing.
  void notify(Changes what);

 signals:
  /// @brief Emitted after every reset, edit, undo and redo with what it touched.
  void changed(ddfcam::gui::Changes what);
  /// @brief Emitted when isModified() flips.
  void modifiedChanged(bool modified);
  /// @brief Emitted when filePath() changes.
  void filePathChanged(const QString& filePath);

 private:
  void enforceUndoBudget();
  void updateModified();

  planning::Project project_;
  QUndoStack* undo_ = nullptr;
  QString filePath_;
  DocumentParams params_;
  std::uint64_t revision_ = 0;
  bool lastModified_ = false;
  // Set when no state reachable through the undo stack equals the saved one (markModified(),
  // or the saved state was dropped from the history by the undo budget).
  bool modifiedWithoutHistory_ = false;
  // True while enforceUndoBudget() rebuilds the stack: its transient signals are not edits.
  bool rebuilding_ = false;
};

}  // namespace ddfcam::gui
