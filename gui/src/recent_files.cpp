// SPDX-License-Identifier: MIT
// ddfcam gui: RecentFiles, the persisted most-recently-used list and its menu entries.
#include <ddfcam/error.h>
#include <ddfcam/gui/recent_files.h>

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

#include <string>

namespace ddfcam::gui {
namespace {

QString normalised(const QString& path) {
  return QDir::cleanPath(QFileInfo(path).absoluteFilePath());
}

// '&' in a file name would otherwise become a mnemonic and vanish from the menu.
QString menuText(int number, const QString& path) {
  QString name = QFileInfo(path).fileName();
  name.replace(QLatin1Char('&'), QStringLiteral("&&"));
  const QString prefix =
      number < 10 ? QStringLiteral("&%1 ").arg(number) : QStringLiteral("%1 ").arg(number);
  return prefix + name;
}

}  // namespace

RecentFiles::RecentFiles(QSettings* settings, int maxEntries)
    : settings_(settings), maxEntries_(maxEntries) {
  if (settings_ == nullptr) throw InvalidInput("recent files: no QSettings given");
  if (maxEntries_ < 1) {
    throw InvalidInput("recent files: maxEntries must be at least 1, got " +
                       std::to_string(maxEntries_));
  }
}

void RecentFiles::add(const QString& path) {
  if (path.isEmpty()) return;
  const QString entry = normalised(path);
  QStringList list = paths();
  list.removeAll(entry);
  list.prepend(entry);
  store(list);
}

void RecentFiles::remove(const QString& path) {
  QStringList list = paths();
  if (list.removeAll(normalised(path)) > 0) store(list);
}

void RecentFiles::clear() {
  store({});
}

QStringList RecentFiles::paths() const {
  QStringList list = settings_->value(kSettingsKey).toStringList();
  list.removeAll(QString());
  list.removeDuplicates();
  if (list.size() > maxEntries_) list.erase(list.begin() + maxEntries_, list.end());
  return list;
}

void RecentFiles::store(QStringList list) {
  if (list.size() > maxEntries_) list.erase(list.begin() + maxEntries_, list.end());
  settings_->setValue(kSettingsKey, list);
  // Another QSettings on the same file (another window, the next session) reads the file.
  settings_->sync();
}

void RecentFiles::populate(QMenu* menu, const std::function<void(const QString&)>& open) {
  menu->clear();
  const QStringList list = paths();
  if (list.isEmpty()) {
    QAction* empty = menu->addAction(QStringLiteral("No recent files"));
    empty->setObjectName(QStringLiteral("recentFilesEmpty"));
    empty->setEnabled(false);
    return;
  }
  for (int i = 0; i < list.size(); ++i) {
    const QString path = list[i];
    QAction* entry = menu->addAction(menuText(i + 1, path));
    entry->setObjectName(QStringLiteral("recentFile%1").arg(i + 1));
    entry->setToolTip(path);
    entry->setStatusTip(path);
    QObject::connect(entry, &QAction::triggered, menu, [open, path] { open(path); });
  }
  menu->setToolTipsVisible(true);
  menu->addSeparator();
  QAction* clearEntry = menu->addAction(QStringLiteral("Clear list"));
  clearEntry->setObjectName(QStringLiteral("recentFilesClear"));
  QObject::connect(clearEntry, &QAction::triggered, menu, [this] { clear(); });
}

}  // namespace ddfcam::gui
