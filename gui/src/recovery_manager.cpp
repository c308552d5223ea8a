// SPDX-License-Identifier: MIT
// ddfcam gui: RecoveryManager, autosave files guarded by per-session lock files.
#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/recovery_manager.h>
#include <ddfcam/io/project/project_file.h>
#include <ddfcam/log.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLockFile>
#include <QSaveFile>
#include <QTimer>
#include <QUuid>

#include <algorithm>
#include <exception>
#include <filesystem>

namespace ddfcam::gui {
namespace {

const QString kRecoveryPrefix = QStringLiteral("recovery-");
const QString kRecoverySuffix = QStringLiteral(".ddfproj");
const QString kSidecarSuffix = QStringLiteral(".info");
const QString kLockPrefix = QStringLiteral("session-");
const QString kLockSuffix = QStringLiteral(".lock");

std::filesystem::path toPath(const QString& path) {
  return std::filesystem::path(QFile::encodeName(path).toStdString());
}

std::string quotedPath(const QString& path) {
  return "'" + path.toStdString() + "'";
}

/// Session id of a recovery file name ("recovery-<id>.ddfproj"); empty if it is not one.
QString sessionIdOf(const QString& recoveryFile) {
  const QString name = QFileInfo(recoveryFile).fileName();
  if (!name.startsWith(kRecoveryPrefix) || !name.endsWith(kRecoverySuffix)) return {};
  return name.mid(kRecoveryPrefix.size(),
                  name.size() - kRecoveryPrefix.size() - kRecoverySuffix.size());
}

QString lockPathOf(const QString& directory, const QString& id) {
  return QDir(directory).filePath(kLockPrefix + id + kLockSuffix);
}

QString sidecarOf(const QString& recoveryFile) {
  QString path = recoveryFile;
  path.chop(kRecoverySuffix.size());
  return path + kSidecarSuffix;
}

/// The lock of @p entry's session, taken; throws if a live session holds it.
std::unique_ptr<QLockFile> lockEntry(const RecoveryEntry& entry) {
  const QString id = sessionIdOf(entry.recoveryFile);
  if (id.isEmpty())
    throw IoError("recovery: " + quotedPath(entry.recoveryFile) + " is not a recovery file");
  auto lock =
      std::make_unique<QLockFile>(lockPathOf(QFileInfo(entry.recoveryFile).absolutePath(), id));
  if (!lock->tryLock(0))
    throw IoError("recovery file " + quotedPath(entry.recoveryFile) +
                  " belongs to a running ddfcam session");
  return lock;
}

void removeFile(const QString& path) {
  if (QFile::exists(path) && !QFile::remove(path))
    throw IoError("recovery: cannot remove " + quotedPath(path));
}

void writeSidecar(const QString& path, const QString& originalPath, const QDateTime& time) {
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
    throw IoError("recovery: cannot write " + quotedPath(path) + ": " +
                  file.errorString().toStdString());
  // One "key=value" per line; the value runs to the end of its line.
  const QString text = "ddfcam recovery 1\noriginal=" + originalPath +
                       "\ntime=" + time.toString(Qt::ISODateWithMs) + "\n";
  file.write(text.toUtf8());
  if (!file.commit())
    throw IoError("recovery: cannot write " + quotedPath(path) + ": " +
                  file.errorString().toStdString());
}

/// Entry of @p recoveryFile from its sidecar; without one (a crash between the two writes) the
/// original path is unknown and the time is the file's.
RecoveryEntry readEntry(const QString& recoveryFile) {
  RecoveryEntry entry;
  entry.recoveryFile = recoveryFile;
  entry.time = QFileInfo(recoveryFile).lastModified().toUTC();
  QFile sidecar(sidecarOf(recoveryFile));
  if (!sidecar.open(QIODevice::ReadOnly | QIODevice::Text)) return entry;
  const QStringList lines = QString::fromUtf8(sidecar.readAll()).split('\n');
  for (const QString& line : lines) {
    if (line.startsWith("original=")) entry.originalPath = line.mid(9);
    if (line.startsWith("time=")) {
      const QDateTime time = QDateTime::fromString(line.mid(5), Qt::ISODateWithMs);
      if (time.isValid()) entry.time = time.toUTC();
    }
  }
  return entry;
}

/// Removes lock files of dead sessions that never autosaved (tryLock takes over a stale lock,
/// unlock deletes it); locks of live sessions cannot be taken and stay.
void removeDeadLocks(const QDir& dir) {
  const QStringList locks = dir.entryList({kLockPrefix + "*" + kLockSuffix}, QDir::Files);
  for (const QString& name : locks) {
    const QString id =
        name.mid(kLockPrefix.size(), name.size() - kLockPrefix.size() - kLockSuffix.size());
    if (QFile::exists(dir.filePath(kRecoveryPrefix + id + kRecoverySuffix))) continue;
    QLockFile lock(dir.filePath(name));
    if (lock.tryLock(0)) lock.unlock();
  }
}

}  // namespace

RecoveryManager::RecoveryManager(const Document& document, RecoveryParams params, QObject* parent)
    : QObject(parent), document_(document), params_(std::move(params)) {
  if (params_.directory.isEmpty() || !QDir().mkpath(params_.directory))
    throw IoError("recovery: cannot create the directory " + quotedPath(params_.directory));
  sessionId_ = QUuid::createUuid().toString(QUuid::Id128);
  lock_ = std::make_unique<QLockFile>(lockPathOf(params_.directory, sessionId_));
  if (!lock_->tryLock(0))
    throw IoError("recovery: cannot take the session lock " +
                  quotedPath(lockPathOf(params_.directory, sessionId_)));
  timer_ = new QTimer(this);
  connect(timer_, &QTimer::timeout, this, &RecoveryManager::onTimer);
  if (params_.intervalMs > 0) timer_->start(params_.intervalMs);
}

RecoveryManager::~RecoveryManager() = default;

QString RecoveryManager::recoveryFilePath() const {
  return QDir(params_.directory).filePath(kRecoveryPrefix + sessionId_ + kRecoverySuffix);
}

QString RecoveryManager::sidecarPath() const {
  return sidecarOf(recoveryFilePath());
}

bool RecoveryManager::autosaveNow() {
  if (!document_.isModified() || savedRevision_ == document_.revision()) return false;
  const QString path = recoveryFilePath();
  try {
    io::writeProject(document_.project(), toPath(path));
    writeSidecar(sidecarPath(), document_.filePath(), QDateTime::currentDateTimeUtc());
  } catch (const std::exception&) {
    std::throw_with_nested(IoError("autosave to " + quotedPath(path) + " failed"));
  }
  savedRevision_ = document_.revision();
  emit autosaved(path);
  return true;
}

void RecoveryManager::discardRecovery() {
  removeFiles();
  savedRevision_.reset();
}

void RecoveryManager::removeFiles() {
  removeFile(recoveryFilePath());
  removeFile(sidecarPath());
}

void RecoveryManager::onTimer() {
  try {
    if (!document_.isModified()) {
      // Saved (or reset) since the last autosave: the project file is newer than ours.
      if (savedRevision_) discardRecovery();
      return;
    }
    autosaveNow();
  } catch (const std::exception& e) {
    const std::string message = unrollMessage(e);
    log(LogLevel::Warning, message);
    emit autosaveFailed(QString::fromStdString(message));
  }
}

std::vector<RecoveryEntry> RecoveryManager::findAbandoned(const QString& directory) {
  std::vector<RecoveryEntry> entries;
  const QDir dir(directory);
  if (directory.isEmpty() || !dir.exists()) return entries;
  const QStringList files =
      dir.entryList({kRecoveryPrefix + "*" + kRecoverySuffix}, QDir::Files, QDir::Name);
  for (const QString& name : files) {
    const QString id = sessionIdOf(name);
    if (id.isEmpty()) continue;
    QLockFile lock(lockPathOf(directory, id));
    if (!lock.tryLock(0)) continue;  // a live session owns it
    lock.unlock();
    entries.push_back(readEntry(dir.filePath(name)));
  }
  removeDeadLocks(dir);
  std::sort(entries.begin(), entries.end(),
            [](const RecoveryEntry& a, const RecoveryEntry& b) { return a.time > b.time; });
  return entries;
}

planning::Project RecoveryManager::recover(const RecoveryEntry& entry) {
  const std::unique_ptr<QLockFile> lock = lockEntry(entry);
  planning::Project project = io::readProject(toPath(entry.recoveryFile));
  removeFile(entry.recoveryFile);
  removeFile(sidecarOf(entry.recoveryFile));
  return project;
}

void RecoveryManager::discard(const RecoveryEntry& entry) {
  const std::unique_ptr<QLockFile> lock = lockEntry(entry);
  removeFile(entry.recoveryFile);
  removeFile(sidecarOf(entry.recoveryFile));
}

}  // namespace ddfcam::gui
