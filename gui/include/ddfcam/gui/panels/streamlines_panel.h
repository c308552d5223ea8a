// SPDX-License-Identifier: MIT
// ddfcam gui: the Streamlines panel: tool paths along lines of curvature, seeded by click.
#pragma once

#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/gui/workbench.h>
#include <ddfcam/planning/line_field.h>
#include <ddfcam/planning/streamline.h>

#include <functional>
#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QToolButton;

namespace ddfcam::gui {

struct PickResult;

/// @brief Plans tool paths along the tool flow field (issue 4, first steps): the field follows
/// the k_max or k_min lines of curvature (planning::flowField, optionally smoothed with Ceres);
/// with "Seed by click" on, a click on the part traces a streamline through the picked point
/// (planning::traceStreamline) and adds it as a tool path for the first tool; "Seed family"
/// seeds streamlines every w mm along the transverse line through the last pick
/// (planning::seedAlongTransverse, fig. 8.11). The field is computed as a job and kept until
/// the part or its heights change; every path is one undoable edit.
class StreamlinesPanel : public Panel {
  Q_OBJECT

 public:
  explicit StreamlinesPanel(Workbench& workbench, QWidget* parent = nullptr);
  ~StreamlinesPanel() override;
  QString title() const override { return tr("Streamlines"); }
  QString id() const override { return "streamlines"; }

  /// @brief Turns click seeding on or off (the "Seed by click" button).
  void setSeedByClick(bool on);
  /// @brief Adds the streamline through @p seed as a path (computing the field first if
  /// needed, as a job). @return true if the path was added or the job started.
  bool seedAt(const ddf::SurfaceLocation& seed);
  /// @brief Adds a family of streamlines seeded along the transverse line through the last
  /// pick, spaced as set. @return true if added or the job started.
  bool seedFamily();

  /// @brief The line fields paths follow, cached per state of the part's heights.
  struct Fields;

 private:
  void onPicked(const PickResult& pick);
  bool withFields(const std::function<void()>& then);
  void addPath(std::vector<planning::Streamline> lines, const QString& name);

  QComboBox* direction_ = nullptr;
  QCheckBox* smooth_ = nullptr;
  QToolButton* seedByClick_ = nullptr;
  QDoubleSpinBox* spacing_ = nullptr;
  QLabel* status_ = nullptr;
  std::shared_ptr<Fields> fields_;
  std::optional<ddf::SurfaceLocation> lastPick_;
};

}  // namespace ddfcam::gui
