// SPDX-License-Identifier: MIT
// ddfcam gui: the Fields panel: compute fields, choose the shown one, its colour map and range.
#pragma once

#include <ddfcam/gui/workbench.h>
#include <ddfcam/planning/model/project.h>

#include <functional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QHBoxLayout;
class QListWidget;
class QPushButton;

namespace ddfcam::gui {

class HistogramRangeMarkers;

/// @brief Fields the panel can compute (each through the core, as a job).
enum class FieldKind {
  Height,             ///< planning::heightField
  HeightMm,           ///< planning::heightMmField
  MaterialRemoved,    ///< planning::materialRemovedField against the first state ("stock")
  Deviation,          ///< planning::deviationField against the design mesh
  KMax,               ///< planning::computeCurvature, larger principal curvature (tool side)
  KMin,               ///< smaller principal curvature
  MeanCurvature,      ///< mean curvature
  GaussianCurvature,  ///< Gaussian curvature
  CurvatureType,      ///< planning::curvatureTypeField: flat, convex, concave, saddle (0..3)
  MaxToolRadius,      ///< planning::maxToolRadiusField: largest ball that does not gouge
};

/// @brief Lists the document's fields; selecting one colours the surface by it (PartView) and
/// shows its histogram over the colour range in the plot dock. Computes the built-in fields as
/// jobs whose result is an undoable AddFieldCommand; removes fields (undoable).
class FieldsPanel : public Panel {
  Q_OBJECT

 public:
  explicit FieldsPanel(Workbench& workbench, QWidget* parent = nullptr);
  QString title() const override { return tr("Fields"); }
  QString id() const override { return "fields"; }
  QString menuTitle() const override { return tr("F&ields"); }
  QList<QAction*> menuActions() const override { return actions_; }

  /// @brief Starts computing @p kind as a job (the Compute menu). @return true if started.
  bool compute(FieldKind kind);
  /// @brief Computes the selected field again from the current heights (it must be one of the
  /// Compute menu's); fields computed from other heights are listed as stale. @return true if
  /// the job started.
  bool recomputeSelected();
  /// @brief Number of bins of the histogram. Default 64.
  static constexpr int kHistogramBins = 64;

 private:
  void buildControls();
  QListWidget* buildFieldList();
  QHBoxLayout* buildListButtons();
  QFormLayout* buildColourControls();
  void refreshList();
  void refreshDisplayControls();
  void updateHistogram();
  void onSelectionChanged();
  void applyRangeFromControls();

  QList<QAction*> actions_;
  QListWidget* list_ = nullptr;
  QPushButton* remove_ = nullptr;
  QPushButton* recompute_ = nullptr;
  QComboBox* colourMap_ = nullptr;
  QCheckBox* autoRange_ = nullptr;
  HistogramRangeMarkers* rangeMarkers_ = nullptr;  ///< the colour range on the histogram
  QDoubleSpinBox* min_ = nullptr;
  QDoubleSpinBox* max_ = nullptr;
  bool updating_ = false;
};

}  // namespace ddfcam::gui
