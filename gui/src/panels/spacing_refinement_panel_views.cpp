// SPDX-License-Identifier: MIT
// ddfcam gui: SpacingRefinementPanel: iteration list, paths overlay, convergence plot.
#include <ddfcam/gui/adapters/plot_series.h>
#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/panels/spacing_refinement_panel.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/plot_dock.h>
#include <ddfcam/gui/vtk_view.h>

#include <QLabel>
#include <QListWidget>
#include <QPushButton>

#include <algorithm>

namespace ddfcam::gui {
namespace {

QString iterationText(int index, const planning::RefinementIteration& it) {
  const QString what = index == 0 ? QObject::tr("front") : QObject::tr("fix-up %1").arg(index);
  return QObject::tr("%1: +%2 paths, %3 in all, max error %4 mm, length %5 mm")
      .arg(what)
      .arg(it.pathsAdded)
      .arg(it.pathCount)
      .arg(it.maxErrorMm, 0, 'f', 4)
      .arg(it.totalLengthMm, 0, 'f', 1);
}

}  // namespace

void SpacingRefinementPanel::showResult() {
  list_->clear();
  PartScene& scene = workbench().partView.scene();
  if (!result_) {
    scene.removeOverlay(kIterationOverlay);
    summary_->setText(tr("Set region, tool and tolerance, then refine."));
    apply_->setEnabled(false);
    return;
  }
  for (std::size_t i = 0; i < result_->iterations.size(); ++i)
    list_->addItem(iterationText(static_cast<int>(i), result_->iterations[i]));
  summary_->setText(tr("%1: %2 paths, %3 mm of path, max error %4 mm (tolerance %5 mm)")
                        .arg(result_->converged ? tr("within tolerance") : tr("NOT converged"))
                        .arg(result_->paths.size())
                        .arg(result_->totalLengthMm, 0, 'f', 1)
                        .arg(result_->maxErrorMm, 0, 'f', 4)
                        .arg(resultToleranceMm_, 0, 'f', 4));
  apply_->setEnabled(true);
  plotConvergence();
  list_->setCurrentRow(list_->count() - 1);
}

bool SpacingRefinementPanel::showIteration(int index) {
  if (!result_ || index < 0 || index >= static_cast<int>(result_->iterations.size())) return false;
  std::vector<std::vector<Eigen::Vector3d>> lines;
  for (const planning::Streamline& line : result_->iterations[index].paths)
    lines.push_back(line.polyline());
  OverlayStyle style;
  style.rgb = {0.1, 0.45, 0.95};
  style.lineWidth = 2.0;
  style.onTop = true;
  workbench().partView.scene().setOverlay(kIterationOverlay, toPolylinePolyData(lines), style);
  workbench().partView.view().requestRender();
  return true;
}

void SpacingRefinementPanel::plotConvergence() {
  std::vector<double> iteration, maxError;
  for (std::size_t i = 0; i < result_->iterations.size(); ++i) {
    iteration.push_back(static_cast<double>(i));
    maxError.push_back(result_->iterations[i].maxErrorMm);
  }
  QCustomPlot* plot = workbench().plots.plot(kConvergenceTab);
  const QString x = tr("iteration (0 = front)"), y = tr("max material left [mm]");
  setLineSeries(plot, tr("tolerance"), {0.0, std::max(1.0, iteration.back())},
                {resultToleranceMm_, resultToleranceMm_}, x, y);
  setLineSeries(plot, tr("max error"), iteration, maxError, x, y);
}

}  // namespace ddfcam::gui
