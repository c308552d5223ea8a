// SPDX-License-Identifier: MIT
// ddfcam gui: the Segmentation panel: automatic segmentation, region list, brush and lasso,
// and the planning choices of the selected region.
#pragma once

#include <ddfcam/gui/panels/region_view_tool.h>
#include <ddfcam/gui/workbench.h>
#include <ddfcam/planning/model/project.h>

#include <QList>
#include <QString>

#include <functional>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSpinBox;
class QTreeWidget;

namespace ddfcam::gui {

class RegionPlanEditor;

/// @brief How the automatic segmentation classifies faces.
enum class SegmentationMethod {
  CurvatureType = 0,  ///< convex / concave / saddle / flat (planning::segmentByCurvatureType)
  ToolRadius,         ///< classes of the largest non-gouging tool (planning::segmentByToolRadius)
  CadFace,  ///< one region per CAD face of a CAD part (planning::segmentByCadFace, minFaces 1)
};

/// @brief Segments the part into regions (sec. 8.1) and edits them: automatic
/// segmentation as a job (curvature, then segmentation by curvature type or tool-radius
/// classes with a minimum region size; or, for a part imported from CAD, one region per CAD
/// face); a region list (name, face count, colour) with rename,
/// merge, split into connected parts and delete; brush, eraser and lasso painting on the view
/// (RegionViewTool); and the planning choices of the selected region (RegionPlanEditor). Every
/// edit is one SetRegionsCommand on the undo stack.
class SegmentationPanel : public Panel {
  Q_OBJECT

 public:
  explicit SegmentationPanel(Workbench& workbench, QWidget* parent = nullptr);
  ~SegmentationPanel() override;
  QString title() const override { return tr("Segmentation"); }
  QString id() const override { return "segmentation"; }

  /// @brief Chooses the automatic method, the flat threshold (1/mm, CurvatureType), the tool
  /// radii (mm, ascending, ToolRadius) and the minimum region size (faces; not for CadFace).
  /// CadFace falls back to CurvatureType unless the part has CAD faces.
  void setSegmentationOptions(SegmentationMethod method, double flatCurvaturePerMm,
                              const std::vector<double>& toolRadiiMm, int minFaces);
  /// @brief Starts the automatic segmentation as a job. @return false if it did not start.
  bool segment();

  /// @brief Selected region indices, ascending (the first is the one brush and lasso paint into
  /// and whose plan is shown).
  std::vector<int> selectedRegions() const;
  /// @brief Selects exactly the regions @p indices.
  void selectRegions(const std::vector<int>& indices);
  /// @brief Appends an empty region "region <n>" and selects it. @return true if added.
  bool addRegion();
  /// @brief Renames region @p index. @return true if renamed.
  bool renameRegion(int index, const QString& name);
  /// @brief Merges the selected regions (at least two). @return true if merged.
  bool mergeSelected();
  /// @brief Splits the selected regions into their connected parts. @return true if any split.
  bool splitSelected();
  /// @brief Deletes the selected regions. @return true if any was deleted.
  bool deleteSelected();
  /// @brief Replaces the plan of the first selected region. @return true if changed.
  bool setSelectedPlan(const planning::RegionPlan& plan);

  /// @brief Brush, eraser, lasso or none (the mode buttons).
  void setEditMode(RegionEditMode mode);
  /// @brief Brush radius, mm.
  void setBrushRadiusMm(double radiusMm);
  /// @brief The colours, brush and lasso on the view.
  RegionViewTool& viewTool() const { return *tool_; }

 private:
  void refreshList();
  void refreshPlan();
  bool pushRegions(const QString& text, const std::function<std::vector<planning::Region>(
                                            const std::vector<planning::Region>&)>& edit);
  QWidget* buildAutomaticGroup();
  /// Enables the CAD-face method only for a CAD part and each method's own controls.
  void updateMethodControls();
  QWidget* buildRegionGroup();
  QWidget* buildPaintGroup();
  /// The paint mode into the status bar (InteractionMode); Esc or leaving the panel ends it.
  void announceEditMode(RegionEditMode mode);

  RegionViewTool* tool_ = nullptr;
  QComboBox* method_ = nullptr;
  QDoubleSpinBox* flatThreshold_ = nullptr;
  QLineEdit* toolRadii_ = nullptr;
  QSpinBox* minFaces_ = nullptr;
  QTreeWidget* list_ = nullptr;
  QCheckBox* showColours_ = nullptr;
  QComboBox* mode_ = nullptr;
  QDoubleSpinBox* radius_ = nullptr;
  RegionPlanEditor* plan_ = nullptr;
  QLabel* status_ = nullptr;
  bool refreshing_ = false;
  std::string lastShownField_;  ///< field shown at the last display change
};

}  // namespace ddfcam::gui
