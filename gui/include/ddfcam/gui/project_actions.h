// SPDX-License-Identifier: MIT
// ddfcam gui: the File menu's work: new, open (parts and projects, as jobs), save, recent files,
// the unsaved-changes prompt and crash recovery.
#pragma once

#include <ddfcam/gui/part_import_dialog.h>
#include <ddfcam/gui/user_action.h>
#include <ddfcam/io/mesh/part_loader.h>

#include <QObject>
#include <QSize>
#include <QString>
#include <QStringList>

#include <functional>
#include <memory>
#include <optional>

namespace ddfcam::planning {
struct Project;
}

namespace ddfcam::ddf {
struct ConversionReport;
}

namespace ddfcam::gui {

class Document;
class JobRunner;
class RecentFiles;
class RecoveryManager;
struct PathExportOptions;  // path_export_dialog.h
struct PathImportOptions;  // path_import.h
struct PathImportRequest;  // path_import.h

/// @brief Answer to "the project has unsaved changes".
enum class UnsavedChoice { Save, Discard, Cancel };

/// @brief Where and how large a screenshot should be written.
struct ScreenshotRequest {
  QString path;  ///< PNG file
  QSize size;    ///< device pixels; an invalid size means the view's current size
};

/// @brief The interactive parts of the workbench that tests replace. Empty members get the
/// defaults (file dialogs, message boxes).
struct WorkbenchDialogs {
  /// Asks for a part or project to open; an empty string means the user cancelled.
  std::function<QString()> openPath;
  /// Asks where to save the project; an empty string means the user cancelled.
  std::function<QString()> saveProjectPath;
  /// Asks for the screenshot file and size; nullopt means the user cancelled.
  std::function<std::optional<ScreenshotRequest>()> screenshot;
  /// Asks what to do with unsaved changes before they would be lost.
  std::function<UnsavedChoice()> unsavedChanges;
  /// Offers recovery files of sessions that ended abnormally (one line per file); returns the
  /// index of the one to recover or -1.
  std::function<int(const QStringList& entries)> offerRecovery;
  /// Shows an error of a user action.
  ErrorReporter error;
  /// Asks for a tool-path file to import (File > Import tool path); empty means cancelled.
  std::function<QString()> importPathFile;
  /// Asks for the export options of @p project's paths, starting from @p initial (the last
  /// choices); nullopt means cancelled.
  std::function<std::optional<PathExportOptions>(const planning::Project& project,
                                                 const PathExportOptions& initial)>
      exportPaths;
  /// Asks how to place a program read from a file, starting from @p initial; nullopt means
  /// cancelled.
  std::function<std::optional<PathImportOptions>(const PathImportRequest& request,
                                                 const PathImportOptions& initial)>
      importPath;
  /// Asks how to import the mesh or CAD part @p request (unit, accuracy, support, stock),
  /// starting from @p initial; nullopt means cancelled.
  std::function<std::optional<PartImportChoices>(const PartImportRequest& request,
                                                 const PartImportChoices& initial)>
      importPart;
  /// Tells that the crust cannot hold the requested stock (@p message: where and why) and
  /// offers to import again with the largest allowance it holds, @p largestMm; true: re-import.
  std::function<bool(const QString& message, double largestMm)> offerLargestStock;
  /// Announces a long job before it starts (@p title, e.g. "Simulate path", and @p message
  /// with its size and estimated time); true: go on.
  std::function<bool(const QString& title, const QString& message)> confirmLongJob;
};

/// @brief File operations on a Document. Loading runs as a job (a big mesh converts for a
/// while); the document is replaced only when loading succeeded, so a failed or cancelled open
/// keeps the current project.
class ProjectActions : public QObject {
  Q_OBJECT

 public:
  ProjectActions(Document& document, JobRunner& jobs, RecentFiles& recent,
                 const WorkbenchDialogs& dialogs, QObject* parent = nullptr);

  /// @brief File suffix of project files, "ddfproj".
  static QString projectSuffix();
  /// @brief True if @p path names a file the workbench can open (project, .ddf or mesh).
  static bool canOpen(const QString& path);

  /// @brief Starts opening @p path: a project replaces the document, a .ddf, mesh or CAD file
  /// starts a new project on it (the mesh or tessellation also becomes the design mesh). Asks
  /// about unsaved changes first, then, for a mesh or CAD file, how to import it
  /// (WorkbenchDialogs::importPart; the session's last choices start the next dialog).
  /// @return true if the load job started.
  bool openPath(const QString& path);
  /// @brief Starts importing the mesh or CAD file @p path with @p choices, no dialog (e.g. again
  /// with the largest stock the crust holds). @return true if the load job started.
  bool importPart(const QString& path, const PartImportChoices& choices);
  /// @brief The session's last import choices (the defaults before the first import).
  const PartImportChoices& recentImportChoices() const { return recentChoices_; }
  /// @brief What loading the document's part did, when it was imported from a mesh or CAD file
  /// in this session (nullopt after opening a project, a .ddf, the demo or a new project).
  const std::optional<io::LoadPartReport>& partReport() const { return partReport_; }
  /// @brief Replaces the document by an empty project (asks about unsaved changes first).
  /// @return true if done.
  bool newProject();
  /// @brief Starts a new project on the built-in demo part (a job). @return true if started.
  bool openDemo();
  /// @brief Saves to the document's file, or asks for one. @return true if saved.
  bool save();
  /// @brief Saves to @p path (suffix added if missing) and makes it the document's file.
  /// @return true if saved; errors are reported.
  bool saveAs(const QString& path);
  /// @brief Asks about unsaved changes and saves if wanted.
  /// @return true if the caller may go on (saved, discarded or nothing to save).
  bool maybeSave();
  /// @brief Looks for recovery files in @p recovery's directory and offers them; recovers the
  /// chosen one into the document (marked modified). @return true if a project was recovered.
  bool offerRecovery(RecoveryManager& recovery);

 signals:
  /// @brief A project or part was loaded into the document from @p path.
  void opened(const QString& path);
  /// @brief A mesh file was converted to the document's part (emitted after opened()):
  /// @p verdict is "<file>: valid DDF ..." or "<file>: INVALID DDF: violates constraint ...",
  /// the same words `ddfcam-cli convert` prints; the repairs and problems went to the log.
  void conversionReported(const QString& verdict, bool valid);
  /// @brief partReport() changed (after opened()).
  void partReportChanged();

 private:
  /// Runs on the UI thread after a load replaced the document: the path and the load's report.
  using LoadedStep = std::function<void(const QString&, std::shared_ptr<io::LoadPartReport>)>;
  bool startLoad(const QString& title, const QString& path, io::LoadPartParams params,
                 LoadedStep onLoaded);
  /// After an import: keeps the report, and when the stock was not held says so and offers the
  /// largest allowance.
  void takePartReport(const QString& path, std::shared_ptr<io::LoadPartReport> report,
                      const PartImportChoices& choices);
  /// Logs what converting @p path did (repairs at Info, problems at Warning) and emits
  /// conversionReported().
  void announceConversion(const QString& path, const ddf::ConversionReport& report);

  Document& document_;
  JobRunner& jobs_;
  RecentFiles& recent_;
  const WorkbenchDialogs& dialogs_;
  PartImportChoices recentChoices_;
  std::optional<io::LoadPartReport> partReport_;
};

}  // namespace ddfcam::gui
