// SPDX-License-Identifier: MIT
// Test support: a workbench window with scripted dialogs, private settings and recovery folder.
#pragma once

#include <ddfcam/gui/main_window.h>
#include <ddfcam/gui/part_import_dialog.h>
#include <ddfcam/gui/path_export_dialog.h>
#include <ddfcam/gui/path_import.h>

#include <QSettings>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>
#include <QtTest/QtTest>

#include <memory>
#include <optional>

namespace ddfcam::test {

/// Answers every dialog of a MainWindow from fields the test sets, and records errors.
struct ScriptedDialogs {
  QString openPath;
  QString saveProjectPath;
  std::optional<gui::ScreenshotRequest> screenshot;
  gui::UnsavedChoice unsaved = gui::UnsavedChoice::Discard;
  int recoveryChoice = -1;
  QStringList offeredRecoveries;
  QStringList errors;
  QString importPathFile;  ///< File > Import tool path's file; empty: cancelled
  /// Answer of the part import dialog. Default: the conversion as before the dialog existed
  /// (input mesh as support, resolution as given, mm), so tests of other features keep their
  /// parts; nullopt: cancelled. acceptInitialImport answers with the dialog's initial choices.
  std::optional<gui::PartImportChoices> importChoices = legacyImport();
  bool acceptInitialImport = false;
  QList<gui::PartImportRequest> importRequests;        ///< every request the dialog got
  QList<gui::PartImportChoices> importInitialChoices;  ///< and what it started with
  QStringList stockOffers;                             ///< "message|largest" of every stock offer
  bool acceptLargestStock = false;                     ///< answer to the stock offer
  QStringList longJobMessages;                         ///< every long-job announcement
  bool confirmLongJobs = true;                         ///< answer to them

  static gui::PartImportChoices legacyImport() {
    gui::PartImportChoices c;
    c.toleranceMm = 0.0;
    c.support = ddf::SupportChoice::Input;
    return c;
  }

  gui::WorkbenchDialogs dialogs() {
    gui::WorkbenchDialogs d;
    d.openPath = [this] { return openPath; };
    d.saveProjectPath = [this] { return saveProjectPath; };
    d.screenshot = [this] { return screenshot; };
    d.unsavedChanges = [this] { return unsaved; };
    d.offerRecovery = [this](const QStringList& entries) {
      offeredRecoveries = entries;
      return recoveryChoice;
    };
    d.error = [this](const QString& title, const QString& message) {
      errors << title + ": " + message;
    };
    // Path export and import (section GX): the option dialogs answer "cancel".
    d.importPathFile = [this] { return importPathFile; };
    d.exportPaths = [](const planning::Project&, const gui::PathExportOptions&) {
      return std::optional<gui::PathExportOptions>();
    };
    d.importPath = [](const gui::PathImportRequest&, const gui::PathImportOptions&) {
      return std::optional<gui::PathImportOptions>();
    };
    d.importPart = [this](const gui::PartImportRequest& request,
                          const gui::PartImportChoices& initial) {
      importRequests << request;
      importInitialChoices << initial;
      return acceptInitialImport ? std::optional(initial) : importChoices;
    };
    d.confirmLongJob = [this](const QString&, const QString& message) {
      longJobMessages << message;
      return confirmLongJobs;
    };
    d.offerLargestStock = [this](const QString& message, double largestMm) {
      stockOffers << message + "|" + QString::number(largestMm);
      return acceptLargestStock;
    };
    return d;
  }
};

/// A MainWindow on private settings and a private recovery folder, shown and exposed.
struct WorkbenchFixture {
  QTemporaryDir dir;
  std::unique_ptr<QSettings> settings;
  ScriptedDialogs script;
  std::unique_ptr<gui::MainWindow> window;

  QString recoveryDir() const { return dir.filePath("recovery"); }

  /// Creates (or re-creates) the window; waits for the start-up job (demo part).
  bool open(bool demo = true) {
    if (!settings)
      settings = std::make_unique<QSettings>(dir.filePath("settings.ini"), QSettings::IniFormat);
    gui::WorkbenchOptions options;
    options.openDemoAtStart = demo;
    options.recoveryDirectory = recoveryDir();
    options.autosaveIntervalMs = 3'600'000;  // tests autosave explicitly
    options.settings = settings.get();
    window = std::make_unique<gui::MainWindow>(script.dialogs(), options);
    window->resize(1000, 700);
    window->show();
    return QTest::qWaitForWindowExposed(window.get()) && window->waitForJobs(120'000);
  }
};

}  // namespace ddfcam::test
