// SPDX-License-Identifier: MIT
// ddfcam gui: the Part panel: what the document holds, at a glance.
#pragma once

#include <ddfcam/gui/workbench.h>

class QLabel;

namespace ddfcam::gui {

/// @brief Shows the part (name, source, the unit it came in, size in mm, support faces, m and
/// raster spacing, crust reach above and below, CAD faces, and for a part imported in this
/// session the reduction, the both-way distances to the input and the stock verdict; raster
/// points, memory, height range, displayed surface) and the counts of fields, regions, tools,
/// paths, states and surfaces.
class PartPanel : public Panel {
  Q_OBJECT

 public:
  explicit PartPanel(Workbench& workbench, QWidget* parent = nullptr);
  QString title() const override { return tr("Part"); }
  QString id() const override { return "part"; }
  /// @brief The text shown (for tests).
  QString text() const;

 private:
  void refresh();

  QLabel* label_ = nullptr;
};

}  // namespace ddfcam::gui
