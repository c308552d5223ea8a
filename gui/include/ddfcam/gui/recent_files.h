// SPDX-License-Identifier: MIT
// ddfcam gui: the most-recently-used file list, persisted in QSettings, and its menu.
#pragma once

#include <QString>
#include <QStringList>

#include <functional>

class QMenu;
class QSettings;

namespace ddfcam::gui {

/// @brief Most-recently-used list of absolute file paths, most recent first, stored in
/// QSettings under kSettingsKey. Every call reads and writes the settings, so several
/// RecentFiles on the same settings (or the same settings file) agree.
class RecentFiles {
 public:
  /// @brief Settings key of the list (a QStringList).
  static inline const QString kSettingsKey = QStringLiteral("recentFiles");

  /// @brief A list in @p settings (not owned; must outlive this object) keeping at most
  /// @p maxEntries paths (default 8).
  /// @throws InvalidInput if @p settings is null or @p maxEntries < 1.
  explicit RecentFiles(QSettings* settings, int maxEntries = 8);

  /// @brief Puts the absolute, cleaned form of @p path first; an equal entry further down is
  /// removed and entries beyond maxEntries() are dropped. An empty path is ignored.
  void add(const QString& path);

  /// @brief Removes @p path (compared in absolute, cleaned form) if listed.
  void remove(const QString& path);

  /// @brief Empties the list.
  void clear();

  /// @brief The listed paths, most recent first, at most maxEntries().
  QStringList paths() const;

  /// @brief Maximum number of paths kept.
  int maxEntries() const { return maxEntries_; }

  /// @brief Replaces the entries of @p menu: one action per path, text "&<N> <file name>"
  /// (N from 1), tooltip and status tip the full path, objectName "recentFile<N>", which
  /// calls @p open with the path; then a separator and "Clear list" (objectName
  /// "recentFilesClear"). With no paths, a single disabled "No recent files" (objectName
  /// "recentFilesEmpty"). Call it from QMenu::aboutToShow so the menu is always current;
  /// this object must outlive the menu's actions.
  void populate(QMenu* menu, const std::function<void(const QString&)>& open);

 private:
  void store(QStringList paths);

  QSettings* settings_;
  int maxEntries_;
};

}  // namespace ddfcam::gui
