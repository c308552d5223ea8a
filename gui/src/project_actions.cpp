// SPDX-License-Identifier: MIT
// ddfcam gui: ProjectActions, File menu operations on the document.
#include <ddfcam/gui/project_actions.h>

#include <ddfcam/ddf/conversion_report.h>
#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/recent_files.h>
#include <ddfcam/gui/recovery_manager.h>
#include <ddfcam/io/project/project_file.h>
#include <ddfcam/io/project/project_loader.h>
#include <ddfcam/log.h>
#include <ddfcam/planning/model/demo_project.h>

#include <QDateTime>
#include <QFileInfo>
#include <QPointer>

#include <filesystem>
#include <memory>

namespace ddfcam::gui {

namespace {

std::filesystem::path toPath(const QString& path) {
  return std::filesystem::path(path.toStdU16String());
}

}  // namespace

ProjectActions::ProjectActions(Document& document, JobRunner& jobs, RecentFiles& recent,
                               const WorkbenchDialogs& dialogs, QObject* parent)
    : QObject(parent), document_(document), jobs_(jobs), recent_(recent), dialogs_(dialogs) {}

QString ProjectActions::projectSuffix() {
  return QStringLiteral("ddfproj");
}

bool ProjectActions::canOpen(const QString& path) {
  return io::canOpenAsProject(toPath(path));
}

bool ProjectActions::openPath(const QString& path) {
  if (!maybeSave()) return false;
  if (isImportablePart(path)) {
    const PartImportRequest request = readImportRequest(path);
    const PartImportChoices initial = initialImportChoices(request, recentChoices_);
    const std::optional<PartImportChoices> choices =
        dialogs_.importPart ? dialogs_.importPart(request, initial) : initial;
    if (!choices) return false;
    recentChoices_ = *choices;
    return importPart(path, *choices);
  }
  const QString title = tr("Open %1").arg(QFileInfo(path).fileName());
  return startLoad(title, path, {}, [this](const QString& loaded, auto) {
    recent_.add(loaded);
    partReport_.reset();
    emit opened(loaded);
    emit partReportChanged();
  });
}

bool ProjectActions::importPart(const QString& path, const PartImportChoices& choices) {
  const QString title = tr("Import %1").arg(QFileInfo(path).fileName());
  return startLoad(title, path, loadParamsFor(choices),
                   [this, choices](const QString& loaded, std::shared_ptr<io::LoadPartReport> r) {
                     recent_.add(loaded);
                     emit opened(loaded);
                     takePartReport(loaded, std::move(r), choices);
                   });
}

bool ProjectActions::newProject() {
  if (!maybeSave()) return false;
  return runUserAction(dialogs_.error, tr("New project"), [&] {
    document_.reset(planning::Project{});
    partReport_.reset();
    emit partReportChanged();
  });
}

bool ProjectActions::openDemo() {
  if (!maybeSave()) return false;
  return startLoad(tr("Open demo part"), QString(), {}, [this](const QString&, auto) {
    partReport_.reset();
    emit opened({});
    emit partReportChanged();
  });
}

bool ProjectActions::startLoad(const QString& title, const QString& path, io::LoadPartParams params,
                               LoadedStep onLoaded) {
  Document* document = &document_;
  const bool isProject = !path.isEmpty() && io::isProjectFile(toPath(path));
  const QPointer<ProjectActions> self(this);
  JobWork work = [path, isProject, document, onLoaded, self,
                  params = std::move(params)](const ProgressCallback& progress) mutable {
    params.progress = progress;
    auto report = std::make_shared<io::LoadPartReport>();
    auto project = std::make_shared<planning::Project>(
        path.isEmpty() ? planning::demoProject()
                       : io::openProject(toPath(path), params, report.get()));
    return std::function<void()>([project, report, path, isProject, document, onLoaded, self] {
      document->reset(std::move(*project), isProject ? path : QString());
      onLoaded(path, report);
      if (report->converted && self) self->announceConversion(path, report->conversion);
    });
  };
  if (!jobs_.start(title, std::move(work))) {
    if (dialogs_.error)
      dialogs_.error(
          title,
          tr("Another job is running (%1); wait for it or cancel it first.").arg(jobs_.title()));
    return false;
  }
  return true;
}

void ProjectActions::takePartReport(const QString& path, std::shared_ptr<io::LoadPartReport> report,
                                    const PartImportChoices& choices) {
  partReport_ = *report;
  emit partReportChanged();
  if (!report->stock || report->stock->holds) return;
  const ddf::StockFit& fit = *report->stock;
  const QString message =
      fit.limit
          ? QString::fromStdString(fit.limit->message)
          : tr("The crust does not reach %1 mm above the surface everywhere.").arg(fit.requestedMm);
  ddfcam::log(LogLevel::Warning, QFileInfo(path).fileName().toStdString() +
                                     ": stock not held: " + message.toStdString());
  const double largest = fit.limit ? fit.limit->largestAllowanceMm : 0.0;
  // After the job has finished: the offer may start the next import.
  QMetaObject::invokeMethod(
      this,
      [this, path, message, largest, choices] {
        if (!dialogs_.offerLargestStock || !dialogs_.offerLargestStock(message, largest)) return;
        PartImportChoices again = choices;
        again.stockMm = largest;
        recentChoices_ = again;
        importPart(path, again);
      },
      Qt::QueuedConnection);
}

void ProjectActions::announceConversion(const QString& path, const ddf::ConversionReport& report) {
  const std::string file = QFileInfo(path).fileName().toStdString();
  const std::string verdict = file + ": " + ddf::conversionVerdict(report);
  ddfcam::log(LogLevel::Info, "converted " + file + ": " + std::to_string(report.inputVertices) +
                                  " vertices, " + std::to_string(report.inputTriangles) +
                                  " triangles -> support of " +
                                  std::to_string(report.supportVertices) + " vertices, " +
                                  std::to_string(report.supportFaces) + " faces");
  for (const std::string& line : ddf::conversionRepairLines(report))
    ddfcam::log(LogLevel::Info, "  repaired: " + line);
  ddfcam::log(report.valid() ? LogLevel::Info : LogLevel::Warning, verdict);
  for (const std::string& line : ddf::conversionProblemLines(report))
    ddfcam::log(LogLevel::Warning, "  " + line);
  emit conversionReported(QString::fromStdString(verdict), report.valid());
}

bool ProjectActions::save() {
  if (document_.filePath().isEmpty()) {
    const QString path = dialogs_.saveProjectPath ? dialogs_.saveProjectPath() : QString();
    return !path.isEmpty() && saveAs(path);
  }
  return saveAs(document_.filePath());
}

bool ProjectActions::saveAs(const QString& requested) {
  QString path = requested;
  if (QFileInfo(path).suffix().compare(projectSuffix(), Qt::CaseInsensitive) != 0)
    path += "." + projectSuffix();
  const bool ok = runUserAction(dialogs_.error, tr("Save %1").arg(QFileInfo(path).fileName()),
                                [&] { io::writeProject(document_.project(), toPath(path)); });
  if (ok) {
    document_.markSaved(path);
    recent_.add(path);
  }
  return ok;
}

bool ProjectActions::maybeSave() {
  if (!document_.isModified()) return true;
  const UnsavedChoice choice =
      dialogs_.unsavedChanges ? dialogs_.unsavedChanges() : UnsavedChoice::Cancel;
  switch (choice) {
    case UnsavedChoice::Save:
      return save();
    case UnsavedChoice::Discard:
      return true;
    case UnsavedChoice::Cancel:
      break;
  }
  return false;
}

bool ProjectActions::offerRecovery(RecoveryManager& recovery) {
  const auto entries = RecoveryManager::findAbandoned(recovery.directory());
  if (entries.empty() || !dialogs_.offerRecovery) return false;
  QStringList lines;
  for (const auto& entry : entries)
    lines << tr("%1 (autosaved %2)")
                 .arg(entry.originalPath.isEmpty() ? tr("unsaved project") : entry.originalPath,
                      entry.time.toString(Qt::ISODate));
  const int chosen = dialogs_.offerRecovery(lines);
  if (chosen < 0 || chosen >= static_cast<int>(entries.size())) return false;
  return runUserAction(dialogs_.error, tr("Recover project"), [&] {
    const auto& entry = entries[static_cast<std::size_t>(chosen)];
    planning::Project project = recovery.recover(entry);
    document_.reset(std::move(project), entry.originalPath);
    document_.markModified();
    partReport_.reset();
    emit partReportChanged();
  });
}

}  // namespace ddfcam::gui
