// SPDX-License-Identifier: MIT
// ddfcam gui: the editor of one region's planning choices (tool, flow field, spacing, feed).
#pragma once

#include <ddfcam/planning/model/region_plan.h>
#include <ddfcam/planning/tools/tool.h>

#include <QWidget>

#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;

namespace ddfcam::gui {

/// @brief Widgets for every field of a planning::RegionPlan. setPlan() shows a plan without
/// emitting anything; each user change (a combo or check box, or a spin box when its editing
/// finishes) emits planEdited() with the whole edited plan, so the owner can push it as one
/// undoable edit.
class RegionPlanEditor : public QWidget {
  Q_OBJECT

 public:
  explicit RegionPlanEditor(QWidget* parent = nullptr);

  /// @brief Shows @p plan; @p tools fill the tool list (entry 0 is "no tool").
  void setPlan(const planning::RegionPlan& plan, const std::vector<planning::Tool>& tools);
  /// @brief The plan the widgets currently show.
  planning::RegionPlan plan() const;

 signals:
  /// @brief The user changed a choice; @p plan is the edited plan.
  void planEdited(const ddfcam::planning::RegionPlan& plan);

 private:
  void emitEdited();
  void updateEnabled();

  planning::RegionPlan shown_;  ///< strokes and anything without a widget are kept from it
  QComboBox* tool_ = nullptr;
  QComboBox* source_ = nullptr;
  QDoubleSpinBox* direction_[3] = {nullptr, nullptr, nullptr};
  QCheckBox* smooth_ = nullptr;
  QDoubleSpinBox* weight_ = nullptr;
  QComboBox* spacingMode_ = nullptr;
  QDoubleSpinBox* spacing_ = nullptr;
  QDoubleSpinBox* tolerance_ = nullptr;
  QComboBox* feed_ = nullptr;
  QComboBox* linking_ = nullptr;
};

}  // namespace ddfcam::gui
