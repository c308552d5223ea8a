// SPDX-License-Identifier: MIT
// ddfcam gui: the list of tool paths with line counts, cutting and idle lengths and a total.
#pragma once

#include <ddfcam/planning/model/project.h>

#include <QWidget>

#include <functional>
#include <string>

class QLabel;
class QTableWidget;

namespace ddfcam::gui {

/// @brief Length summary of one tool path, from its contacts.
struct PathLengths {
  int lines = 0;         ///< number of passes (lines)
  double cuttingMm = 0;  ///< sum of the contact-polyline lengths of all passes, mm
  double idleMm = 0;     ///< sum of the straight links from each pass end to the next start, mm
};

/// @brief Lengths of @p path: passes are ToolPath::passStarts ranges of the contacts.
PathLengths pathLengths(const planning::ToolPath& path);

/// @brief A table of the project's paths (name, lines, cutting length mm, idle length mm: the
/// path's linked idle length (ToolPath::linkedIdleMm, marked "linked") if set, else the
/// straight gaps between passes) with
/// a total line below (path count, lines, cutting and idle length). One row per path, in
/// project order; the selected row picks the path other tools act on.
class PathListWidget : public QWidget {
  Q_OBJECT

 public:
  explicit PathListWidget(QWidget* parent = nullptr);
  /// @brief Rebuilds the rows from @p project; selects the last path when paths were added or
  /// the selected row is gone, else keeps the selection. The box by each name is ticked where
  /// @p visible (by path name) says the path is shown (all when null).
  void refresh(const planning::Project& project,
               const std::function<bool(const std::string&)>& visible = {});
  /// @brief Ticks or unticks the box by path @p index's name (as a click does).
  void setPathChecked(int index, bool checked);
  /// @brief Index of the selected path, -1 if none.
  int selectedPath() const;
  /// @brief Selects path @p index (-1: none).
  void selectPath(int index);
  QTableWidget* table() const { return table_; }
  /// @brief The total line, e.g. "3 paths, 17 lines: cutting 412.5 mm, idle 80.2 mm".
  QString totalText() const;

 signals:
  /// @brief The selected path changed (-1: none).
  void selectionChanged(int index);
  /// @brief The box by path @p index's name was ticked (@p visible) or unticked.
  void visibilityChanged(int index, bool visible);

 private:
  QTableWidget* table_ = nullptr;
  QLabel* total_ = nullptr;
};

}  // namespace ddfcam::gui
