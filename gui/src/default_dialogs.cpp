// SPDX-License-Identifier: MIT
// ddfcam gui: interactive defaults of WorkbenchDialogs.
#include <ddfcam/gui/default_dialogs.h>

#include <ddfcam/gui/part_import_dialog.h>
#include <ddfcam/gui/path_export_dialog.h>
#include <ddfcam/gui/path_import.h>

#include <QFileDialog>
#include <QInputDialog>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QRegularExpression>

namespace ddfcam::gui {

namespace {

std::function<QString()> openDialog(QPointer<QWidget> parent) {
  return [parent] {
    return QFileDialog::getOpenFileName(
        parent, QObject::tr("Open project or part"), QString(),
        QObject::tr("Projects and parts (*.ddfproj *.ddf *.stl *.obj *.ply *.off *.step *.stp "
                    "*.iges *.igs);;Projects (*.ddfproj);;DDF (*.ddf);;"
                    "Meshes (*.stl *.obj *.ply *.off);;CAD (*.step *.stp *.iges *.igs);;"
                    "All files (*)"));
  };
}

std::function<std::optional<ScreenshotRequest>()> screenshotDialog(QPointer<QWidget> parent) {
  return [parent]() -> std::optional<ScreenshotRequest> {
    const QString path = QFileDialog::getSaveFileName(
        parent, QObject::tr("Save screenshot"), "ddfcam.png", QObject::tr("PNG images (*.png)"));
    if (path.isEmpty()) return std::nullopt;
    bool ok = false;
    const QString size = QInputDialog::getText(
        parent, QObject::tr("Screenshot size"),
        QObject::tr("Size in pixels (width x height), empty for the view's size:"),
        QLineEdit::Normal, "1920x1080", &ok);
    if (!ok) return std::nullopt;
    ScreenshotRequest request{path, QSize()};
    const auto match = QRegularExpression(R"(^\s*(\d+)\s*[xX*]\s*(\d+)\s*$)").match(size);
    if (match.hasMatch())
      request.size = QSize(match.captured(1).toInt(), match.captured(2).toInt());
    return request;
  };
}

std::function<UnsavedChoice()> unsavedDialog(QPointer<QWidget> parent) {
  return [parent] {
    const auto answer = QMessageBox::warning(
        parent, QObject::tr("Unsaved changes"),
        QObject::tr("The project has unsaved changes. Save them first?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save) return UnsavedChoice::Save;
    if (answer == QMessageBox::Discard) return UnsavedChoice::Discard;
    return UnsavedChoice::Cancel;
  };
}

std::function<int(const QStringList&)> recoveryDialog(QPointer<QWidget> parent) {
  return [parent](const QStringList& entries) {
    bool ok = false;
    const QString chosen = QInputDialog::getItem(
        parent, QObject::tr("Recover work"),
        QObject::tr("A previous session ended without saving. Recover its autosaved project?"),
        entries, 0, false, &ok);
    return ok ? static_cast<int>(entries.indexOf(chosen)) : -1;
  };
}

void addPathDialogs(WorkbenchDialogs& d, QPointer<QWidget> parent) {
  if (!d.importPathFile)
    d.importPathFile = [parent] {
      return QFileDialog::getOpenFileName(parent, QObject::tr("Import tool path"), QString(),
                                          pathFileFilter());
    };
  if (!d.exportPaths)
    d.exportPaths = [parent](const planning::Project& project,
                             const PathExportOptions& initial) -> std::optional<PathExportOptions> {
      PathExportDialog dialog(project, initial, parent);
      if (dialog.exec() != QDialog::Accepted) return std::nullopt;
      return dialog.options();
    };
  if (!d.importPath)
    d.importPath = [parent](const PathImportRequest& request,
                            const PathImportOptions& initial) -> std::optional<PathImportOptions> {
      PathImportDialog dialog(request, initial, parent);
      if (dialog.exec() != QDialog::Accepted) return std::nullopt;
      return dialog.options();
    };
}

void addPartDialogs(WorkbenchDialogs& d, QPointer<QWidget> parent) {
  if (!d.importPart)
    d.importPart = [parent](const PartImportRequest& request,
                            const PartImportChoices& initial) -> std::optional<PartImportChoices> {
      PartImportDialog dialog(request, initial, parent);
      if (dialog.exec() != QDialog::Accepted) return std::nullopt;
      return dialog.choices();
    };
  if (!d.offerLargestStock)
    d.offerLargestStock = [parent](const QString& message, double largestMm) {
      QMessageBox box(QMessageBox::Warning, QObject::tr("Stock not held"), message,
                      QMessageBox::NoButton, parent);
      QPushButton* again =
          box.addButton(QObject::tr("Import again with %1 mm").arg(largestMm, 0, 'g', 3),
                        QMessageBox::AcceptRole);
      box.addButton(QObject::tr("Keep the part as imported"), QMessageBox::RejectRole);
      again->setEnabled(largestMm > 0.0);
      box.exec();
      return box.clickedButton() == again;
    };
}

}  // namespace

WorkbenchDialogs withDefaultDialogs(WorkbenchDialogs d, QWidget* parent) {
  QPointer<QWidget> guarded(parent);
  if (!d.openPath) d.openPath = openDialog(guarded);
  if (!d.saveProjectPath)
    d.saveProjectPath = [guarded] {
      return QFileDialog::getSaveFileName(guarded, QObject::tr("Save project"), "project.ddfproj",
                                          QObject::tr("ddfcam projects (*.ddfproj)"));
    };
  if (!d.screenshot) d.screenshot = screenshotDialog(guarded);
  if (!d.unsavedChanges) d.unsavedChanges = unsavedDialog(guarded);
  if (!d.offerRecovery) d.offerRecovery = recoveryDialog(guarded);
  if (!d.error) d.error = messageBoxReporter(parent);
  addPathDialogs(d, guarded);
  addPartDialogs(d, guarded);
  if (!d.confirmLongJob)
    d.confirmLongJob = [guarded](const QString& title, const QString& message) {
      return QMessageBox::question(guarded, title, message, QMessageBox::Yes | QMessageBox::No,
                                   QMessageBox::Yes) == QMessageBox::Yes;
    };
  return d;
}

}  // namespace ddfcam::gui
