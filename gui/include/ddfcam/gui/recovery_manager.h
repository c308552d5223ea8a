// SPDX-License-Identifier: MIT
// ddfcam gui: autosave of the modified document and recovery of the sessions that crashed.
#pragma once

#include <ddfcam/planning/model/project.h>

#include <QDateTime>
#include <QObject>
#include <QStandardPaths>
#include <QString>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

class QLockFile;
class QTimer;

namespace ddfcam::gui {

class Document;

/// @brief Parameters of RecoveryManager.
struct RecoveryParams {
  /// Directory of the recovery files (created if missing). Default: the application's
  /// QStandardPaths::AppLocalDataLocation + "/recovery".
  QString directory =
      QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) + "/recovery";
  /// Autosave period, ms; 0 or less disables the timer (autosaveNow() still works).
  /// Default 120000 (2 min).
  int intervalMs = 120000;
};

/// @brief A recovery file left by a session that ended without discarding it (a crash).
struct RecoveryEntry {
  QString recoveryFile;  ///< the autosaved "recovery-<id>.ddfproj"
  QString originalPath;  ///< project file the document had then; empty if it was never saved
  QDateTime time;        ///< when it was autosaved (UTC)
};

/// @brief Autosave and crash recovery of one session. The session holds the lock file
/// "session-<id>.lock" in the directory for its whole life; on every timer tick, if the
/// document is modified and its revision changed since the last autosave, the project is
/// written atomically to "recovery-<id>.ddfproj" (io::writeProject) with a sidecar
/// "recovery-<id>.info" (original path, time). A tick that finds the document unmodified
/// (saved since) removes the session's files, since the saved file is newer. discardRecovery()
/// on a clean close removes them too; the destructor keeps them (a crash must leave them) and
/// only releases the lock. Writing blocks the UI thread for the time of one encode + write.
class RecoveryManager : public QObject {
  Q_OBJECT

 public:
  /// @param document the observed document; must outlive the manager.
  /// @throws IoError if the directory cannot be created or the session lock not taken.
  explicit RecoveryManager(const Document& document, RecoveryParams params = {},
                           QObject* parent = nullptr);
  /// Stops autosaving and releases the session lock; the recovery files stay.
  ~RecoveryManager() override;

  /// @brief Writes the recovery files now if the document is modified and changed since the
  /// last autosave. @return true if they were written.
  /// @throws IoError naming the file if writing fails (the previous recovery file stays).
  bool autosaveNow();
  /// @brief Removes this session's recovery files (on a clean close or after a save).
  void discardRecovery();
  /// @brief This session's recovery file (it exists only after an autosave).
  QString recoveryFilePath() const;
  /// @brief The parameters in use.
  const RecoveryParams& params() const { return params_; }
  /// @brief The recovery directory (params().directory), for findAbandoned().
  QString directory() const { return params_.directory; }

  /// @brief Recovery files in @p directory whose session lock is not held by a live session
  /// (QLockFile::tryLock succeeds, i.e. the owner exited or crashed), newest first. Lock files
  /// of dead sessions that left nothing to recover are removed on the way.
  static std::vector<RecoveryEntry> findAbandoned(const QString& directory);
  /// @brief Reads @p entry's project (io::readProject) and, after a successful read, removes
  /// its files. The caller resets the document with it, marks it modified and sets the file
  /// path to entry.originalPath.
  /// @throws IoError if the file cannot be read or decoded (the files stay), or if a live
  /// session holds it.
  static planning::Project recover(const RecoveryEntry& entry);
  /// @brief Removes @p entry's files without reading them (the user declined recovery).
  /// @throws IoError if a live session holds it or a file cannot be removed.
  static void discard(const RecoveryEntry& entry);

 signals:
  /// @brief The recovery file @p path was written.
  void autosaved(const QString& path);
  /// @brief A timer-driven autosave failed; @p message is the unrolled error.
  void autosaveFailed(const QString& message);

 private:
  void onTimer();
  QString sidecarPath() const;
  void removeFiles();

  const Document& document_;
  RecoveryParams params_;
  QString sessionId_;
  std::unique_ptr<QLockFile> lock_;
  QTimer* timer_ = nullptr;
  std::optional<std::uint64_t> savedRevision_;  // revision of the last autosave, if any
};

}  // namespace ddfcam::gui
