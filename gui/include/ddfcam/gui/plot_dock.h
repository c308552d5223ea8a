// SPDX-License-Identifier: MIT
// ddfcam gui: the "Plots" dock, a tab per QCustomPlot (histogram, error along a path, ...).
#pragma once

#include <ddfcam/gui/user_action.h>
#include <ddfcam/planning/model/field_statistics.h>

#include <QDockWidget>
#include <QString>
#include <QStringList>

#include <functional>

class QAction;
class QCustomPlot;
class QTabWidget;

namespace ddfcam::gui {

/// @brief Dock (objectName "plotDock", title "Plots") holding a QTabWidget of QCustomPlot
/// widgets, one per named plot, and an "Export..." button (action objectName
/// "plotExportAction") that writes the current plot as PNG, PDF or CSV.
class PlotDock : public QDockWidget {
  Q_OBJECT

 public:
  /// @brief Title of the tab showHistogram draws into.
  static inline const QString kHistogramTab = QStringLiteral("Histogram");

  explicit PlotDock(QWidget* parent = nullptr);

  /// @brief The plot of tab @p name, created (objectName "plot_<name>", tab title @p name,
  /// appended last) if there is none yet. The dock owns it.
  QCustomPlot* plot(const QString& name);

  /// @brief The plot of tab @p name, or nullptr if there is no such tab (creates nothing).
  QCustomPlot* findPlot(const QString& name) const;

  /// @brief Removes every plot (e.g. a new part was opened: they describe the previous one).
  void clear();

  /// @brief Names of all tabs, in tab order.
  QStringList plotNames() const;

  /// @brief Name of the current tab; empty if there is none.
  QString currentPlotName() const;

  /// @brief Makes tab @p name current. @return false if there is no such tab.
  bool showPlot(const QString& name);

  /// @brief Draws @p histogram (setHistogramBars) in tab kHistogramTab with x axis label
  /// @p xLabel and makes that tab current.
  void showHistogram(const planning::Histogram& histogram, const QString& xLabel);

  /// @brief Writes the plot of tab @p tabName to @p path, the format chosen by the suffix
  /// (case-insensitive): ".png" (QCustomPlot::savePng), ".pdf" (savePdf), ".csv" (plotToCsv,
  /// written atomically). Images have the size of the plot widget, or 800 x 600 pixels if it
  /// was never laid out.
  /// @return false if there is no tab @p tabName (nothing written), true once written.
  /// @throws IoError naming @p path if the suffix is none of the above or writing fails.
  bool exportPlot(const QString& tabName, const QString& path);

  /// @brief Replaces how "Export..." asks for the target path; an empty answer cancels.
  /// The default is a QFileDialog that appends the suffix of the chosen filter when the name
  /// has none.
  void setExportPathProvider(std::function<QString()> provider);

  /// @brief Replaces how export errors are shown (default: messageBoxReporter(this)).
  void setErrorReporter(ErrorReporter reporter);

  /// @brief The "Export..." action (also shown as the tab bar's corner button); disabled
  /// while there is no tab.
  QAction* exportAction() const { return exportAction_; }

 public slots:
  /// @brief Asks for a path and exports the current tab to it; errors go to the reporter.
  void exportCurrentPlot();

 private:
  QString askExportPath();

  QTabWidget* tabs_ = nullptr;
  QAction* exportAction_ = nullptr;
  std::function<QString()> exportPath_;
  ErrorReporter reportError_;
};

}  // namespace ddfcam::gui
