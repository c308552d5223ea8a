// SPDX-License-Identifier: MIT
// ddfcam gui: the Pick panel: what lies under the last click on the part.
#pragma once

#include <ddfcam/gui/workbench.h>

class QLabel;

namespace ddfcam::gui {

struct PickResult;

/// @brief Shows the last picked surface point (click on the part): support face, barycentric
/// coordinates, height h, 3D point in mm and the shown field's value with its unit.
class PickPanel : public Panel {
  Q_OBJECT

 public:
  explicit PickPanel(Workbench& workbench, QWidget* parent = nullptr);
  QString title() const override { return tr("Pick"); }
  QString id() const override { return "pick"; }
  /// @brief The text shown (for tests).
  QString text() const;

 private:
  void show(const PickResult& pick);

  QLabel* label_ = nullptr;
};

}  // namespace ddfcam::gui
