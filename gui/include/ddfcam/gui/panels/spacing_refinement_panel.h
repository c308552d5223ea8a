// SPDX-License-Identifier: MIT
// ddfcam gui: the Spacing panel: path spacing from simulated error maps (sec. 8.4.1).
#pragma once

#include <ddfcam/gui/workbench.h>
#include <ddfcam/planning/flow/flow_field_source.h>
#include <ddfcam/planning/lines/spacing_refinement.h>

#include <cstdint>
#include <memory>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSpinBox;

namespace ddfcam::gui {

/// @brief Runs planning::refineSpacing on a region (or the whole part) with a tool, a flow
/// field source and a tolerance as a cancellable job: the flow field is computed as the
/// Streamlines panel does (unsmoothed), then paths are placed by the advancing front and
/// fix-ups. Each iteration is listed (paths added, path count, max error, total length);
/// selecting one draws its paths (overlay kIterationOverlay) and the convergence plot (tab
/// kConvergenceTab) shows max error and path count per iteration. "Apply" adds the final tool
/// path and the final error map (field kErrorField, shown with the band [-tol, tol]) as one
/// undo step.
class SpacingRefinementPanel : public Panel {
  Q_OBJECT

 public:
  static constexpr const char* kIterationOverlay = "refinement iteration";
  static constexpr const char* kConvergenceTab = "Spacing refinement";
  static constexpr const char* kErrorField = "refinement error";

  explicit SpacingRefinementPanel(Workbench& workbench, QWidget* parent = nullptr);
  ~SpacingRefinementPanel() override;
  QString title() const override { return tr("Path spacing"); }
  QString id() const override { return "spacingRefinement"; }

  /// @brief Region @p index of the project (-1: whole part).
  void setRegion(int index);
  /// @brief Tool @p index of the project.
  void setTool(int index);
  /// @brief Flow field source (k_max, k_min or a fixed direction along x).
  void setFieldSource(planning::FlowFieldSource source);
  /// @brief Largest material left allowed, mm.
  void setTolerance(double toleranceMm);
  /// @brief Fix-up iterations after the front.
  void setMaxIterations(int iterations);
  /// @brief Starts the refinement job. @return true if started.
  bool refine();
  /// @brief Result of the last refinement, or null.
  const planning::SpacingRefinementResult* result() const { return result_.get(); }
  /// @brief Shows iteration @p index (paths overlay). @return false if there is none.
  bool showIteration(int index);
  /// @brief Adds the result's tool path and error map to the document (one undo step).
  /// @return true if applied.
  bool apply();

 private:
  void buildForm();
  void refreshChoices();
  void showResult();
  void plotConvergence();

  QComboBox* region_ = nullptr;
  QComboBox* tool_ = nullptr;
  QComboBox* source_ = nullptr;
  QDoubleSpinBox* tolerance_ = nullptr;
  QSpinBox* iterations_ = nullptr;
  QPushButton* refine_ = nullptr;
  QPushButton* apply_ = nullptr;
  QListWidget* list_ = nullptr;
  QLabel* summary_ = nullptr;
  std::shared_ptr<const planning::SpacingRefinementResult> result_;
  int resultTool_ = 0;
  double resultToleranceMm_ = 0.0;
  std::uint64_t resultHeightsDigest_ = 0;  // heights the result was computed on
};

}  // namespace ddfcam::gui
