// SPDX-License-Identifier: MIT
// ddfcam gui: the Error map panel: deviation of the simulated from the desired surface with a
// tolerance band, its statistics and histogram, the deviation along a path, and the scallop
// table.
#pragma once

#include <ddfcam/gui/workbench.h>
#include <ddfcam/planning/inspection/coverage.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/inspection/scallop_prediction.h>

#include <optional>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace ddfcam::gui {

/// @brief Compares the part's current heights with a desired surface on the same support
/// (sec. 8.4.1): a simulation state (e.g. "stock" of the demo) or the design mesh converted onto
/// the part's support (planning::workpieceFromStockMesh). "Compute" runs planning::deviationMap
/// as a job and stores the result as field kDeviationField (one undo step); the view then shows
/// it with the tolerance band (blue = material left, green = in tolerance, red = overcut).
/// Statistics (planning::errorStatistics) and the area histogram (planning::errorHistogram, plot
/// tab kHistogramTab) follow the band and the chosen region at once, with their coverage (the
/// share of the region's area that has a deviation: raster points whose stubble misses the
/// design mesh have none) and the points a cut left at the crust bottom (planning::
/// crustClamping: the true overcut is deeper there, the minimum only a bound). "Plot along path"
/// draws planning::deviationAlongPath of the selected path (plot tab kAlongPathTab). "Scallop
/// table" runs planning::scallopTable on defaultScallopCases() as a job and fills the table.
class ErrorMapPanel : public Panel {
  Q_OBJECT

 public:
  static constexpr const char* kDeviationField = "deviation";
  static constexpr const char* kHistogramTab = "Error histogram";
  static constexpr const char* kAlongPathTab = "Deviation along path";

  explicit ErrorMapPanel(Workbench& workbench, QWidget* parent = nullptr);
  QString title() const override { return tr("Error map"); }
  QString id() const override { return "errorMap"; }

  /// @brief Chooses the desired surface: simulation state @p index, or -1 for the design mesh.
  /// @return false if there is no such state (or no design mesh for -1).
  bool setDesiredSurface(int stateIndex);
  /// @brief Restricts statistics and histogram to region @p index (-1: whole part).
  void setRegion(int index);
  /// @brief Sets the tolerance band [e_l, e_u], mm (recolours and updates the statistics).
  void setToleranceBand(const planning::ToleranceBand& band);
  planning::ToleranceBand toleranceBand() const;
  /// @brief Starts the error-map job. @return true if started.
  bool computeErrorMap();
  /// @brief Statistics of the shown error map over the chosen region, if there is one.
  const std::optional<planning::ErrorStatistics>& statistics() const { return statistics_; }
  /// @brief True if the shown error map was computed from heights the part no longer has.
  bool isStale() const { return stale_; }
  /// @brief Share of the chosen region with a deviation, beside statistics().
  const std::optional<planning::Coverage>& coverage() const { return coverage_; }
  /// @brief Points of the region at the crust bottom with an overcut, beside statistics().
  const std::optional<planning::CrustClamping>& clamping() const { return clamping_; }
  /// @brief Plots the deviation along path @p index. @return true if plotted.
  bool plotAlongPath(int index);
  /// @brief Starts the scallop-table job. @return true if started.
  bool computeScallopTable();
  /// @brief Rows of the last scallop table.
  const std::vector<planning::ScallopRow>& scallopRows() const { return scallopRows_; }
  /// @brief How the scallop table simulates its cases (passes, raster, tool mesh) from the next
  /// computeScallopTable() on; default planning::ScallopSimulationParams{}, whose fine tool
  /// meshes take about a minute on two cores. Its progress callback is replaced by the job's.
  void setScallopSimulation(const planning::ScallopSimulationParams& params) {
    scallopSimulation_ = params;
  }
  /// @brief The cases of the scallop table: ball on a plane and on a convex cylinder, a flat
  /// wheel on a convex cylinder, a tilted flat end on a plane.
  static std::vector<planning::ScallopCase> defaultScallopCases();

 private:
  void buildInputs();
  void buildOutputs();
  void refreshChoices();
  void onBandEdited();
  void updateStatistics();
  void showStatistics();
  void showScallopRows();
  const planning::ScalarField* deviationField() const;

  QComboBox* desired_ = nullptr;
  QComboBox* region_ = nullptr;
  QComboBox* path_ = nullptr;
  QDoubleSpinBox* lower_ = nullptr;
  QDoubleSpinBox* upper_ = nullptr;
  QPushButton* compute_ = nullptr;
  QPushButton* alongPath_ = nullptr;
  QPushButton* scallop_ = nullptr;
  QLabel* stats_ = nullptr;
  QTableWidget* scallopTable_ = nullptr;
  std::optional<planning::ErrorStatistics> statistics_;
  bool stale_ = false;  // the shown map was computed from other heights than the part's
  std::optional<planning::Coverage> coverage_;
  std::optional<planning::CrustClamping> clamping_;
  std::vector<planning::ScallopRow> scallopRows_;
  planning::ScallopSimulationParams scallopSimulation_;
};

}  // namespace ddfcam::gui
