// SPDX-License-Identifier: MIT
// ddfcam gui: PlotDock, its tabs and the PNG / PDF / CSV export.
#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/plot_series.h>
#include <ddfcam/gui/plot_dock.h>

#include <qcustomplot.h>

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QSaveFile>
#include <QTabWidget>
#include <QToolButton>

namespace ddfcam::gui {
namespace {

// A plot that was never laid out still has the 100 x 30 default size of a child widget,
// which would give an unreadable image.
constexpr int kMinLaidOutSize = 64;
constexpr int kFallbackWidth = 800;
constexpr int kFallbackHeight = 600;

QSize exportSize(const QCustomPlot* plot) {
  if (plot->width() < kMinLaidOutSize || plot->height() < kMinLaidOutSize) {
    return {kFallbackWidth, kFallbackHeight};
  }
  return {0, 0};  // QCustomPlot: the widget's own size
}

void writeCsv(QCustomPlot* plot, const QString& path) {
  QSaveFile file(path);
  const QByteArray bytes = plotToCsv(plot).toUtf8();
  if (!file.open(QIODevice::WriteOnly | QIODevice::Text) || file.write(bytes) != bytes.size() ||
      !file.commit()) {
    throw IoError("cannot write plot CSV " + path.toStdString() + ": " +
                  file.errorString().toStdString());
  }
}

}  // namespace

PlotDock::PlotDock(QWidget* parent) : QDockWidget(QStringLiteral("Plots"), parent) {
  setObjectName(QStringLiteral("plotDock"));
  tabs_ = new QTabWidget(this);
  tabs_->setObjectName(QStringLiteral("plotTabs"));
  tabs_->setDocumentMode(true);
  exportAction_ = new QAction(QStringLiteral("Export..."), this);
  exportAction_->setObjectName(QStringLiteral("plotExportAction"));
  exportAction_->setIconText(QStringLiteral("Export..."));  // the derived one drops the "..."
  exportAction_->setToolTip(QStringLiteral("Export the current plot as PNG, PDF or CSV"));
  exportAction_->setEnabled(false);
  connect(exportAction_, &QAction::triggered, this, &PlotDock::exportCurrentPlot);
  auto* button = new QToolButton(tabs_);
  button->setObjectName(QStringLiteral("plotExportButton"));
  button->setDefaultAction(exportAction_);
  button->setAutoRaise(true);
  tabs_->setCornerWidget(button, Qt::TopRightCorner);
  setWidget(tabs_);
  reportError_ = messageBoxReporter(this);
}

QCustomPlot* PlotDock::plot(const QString& name) {
  if (QCustomPlot* existing = findPlot(name)) return existing;
  auto* created = new QCustomPlot(tabs_);
  created->setObjectName(QStringLiteral("plot_") + name);
  created->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  tabs_->addTab(created, name);
  exportAction_->setEnabled(true);
  return created;
}

void PlotDock::clear() {
  while (tabs_->count() > 0) {
    QWidget* plot = tabs_->widget(0);
    tabs_->removeTab(0);
    plot->deleteLater();  // a slot of the plot may be on the stack
  }
  exportAction_->setEnabled(false);
}

QCustomPlot* PlotDock::findPlot(const QString& name) const {
  for (int i = 0; i < tabs_->count(); ++i) {
    if (tabs_->tabText(i) == name) return qobject_cast<QCustomPlot*>(tabs_->widget(i));
  }
  return nullptr;
}

QStringList PlotDock::plotNames() const {
  QStringList names;
  for (int i = 0; i < tabs_->count(); ++i) names << tabs_->tabText(i);
  return names;
}

QString PlotDock::currentPlotName() const {
  const int index = tabs_->currentIndex();
  return index < 0 ? QString() : tabs_->tabText(index);
}

bool PlotDock::showPlot(const QString& name) {
  QCustomPlot* target = findPlot(name);
  if (target != nullptr) tabs_->setCurrentWidget(target);
  return target != nullptr;
}

void PlotDock::showHistogram(const planning::Histogram& histogram, const QString& xLabel) {
  QCustomPlot* target = plot(kHistogramTab);
  setHistogramBars(target, histogram, xLabel);
  tabs_->setCurrentWidget(target);
}

bool PlotDock::exportPlot(const QString& tabName, const QString& path) {
  QCustomPlot* target = findPlot(tabName);
  if (target == nullptr) return false;
  const QString suffix = QFileInfo(path).suffix().toLower();
  const QSize size = exportSize(target);
  bool written = false;
  if (suffix == QLatin1String("png")) {
    written = target->savePng(path, size.width(), size.height());
  } else if (suffix == QLatin1String("pdf")) {
    written = target->savePdf(path, size.width(), size.height());
  } else if (suffix == QLatin1String("csv")) {
    writeCsv(target, path);
    written = true;
  } else {
    throw IoError("cannot export plot to " + path.toStdString() +
                  ": unknown file type (use .png, .pdf or .csv)");
  }
  if (!written) {
    throw IoError("cannot write plot '" + tabName.toStdString() + "' to " + path.toStdString());
  }
  return true;
}

void PlotDock::setExportPathProvider(std::function<QString()> provider) {
  exportPath_ = std::move(provider);
}

void PlotDock::setErrorReporter(ErrorReporter reporter) {
  reportError_ = std::move(reporter);
}

void PlotDock::exportCurrentPlot() {
  const QString name = currentPlotName();
  if (name.isEmpty()) return;
  const QString path = exportPath_ ? exportPath_() : askExportPath();
  if (path.isEmpty()) return;
  runUserAction(reportError_, QStringLiteral("Export plot"), [&] { exportPlot(name, path); });
}

QString PlotDock::askExportPath() {
  const QString png = QStringLiteral("PNG image (*.png)");
  const QString pdf = QStringLiteral("PDF document (*.pdf)");
  const QString csv = QStringLiteral("CSV table (*.csv)");
  QString filter = png;
  QString path = QFileDialog::getSaveFileName(
      this, QStringLiteral("Export plot"), QString(),
      png + QStringLiteral(";;") + pdf + QStringLiteral(";;") + csv, &filter);
  if (!path.isEmpty() && QFileInfo(path).suffix().isEmpty()) {
    path += filter == pdf ? QStringLiteral(".pdf")
                          : (filter == csv ? QStringLiteral(".csv") : QStringLiteral(".png"));
  }
  return path;
}

}  // namespace ddfcam::gui
