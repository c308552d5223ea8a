// SPDX-License-Identifier: MIT
// ddfcam gui: the Tools panel: the project's tool list, a form per tool, a tool library file.
#pragma once

#include <ddfcam/gui/workbench.h>
#include <ddfcam/planning/tools/tool.h>

class QComboBox;
class QListWidget;
class QPushButton;

namespace ddfcam::gui {

class ToolEditor;

/// @brief Lists Project::tools; adds a tool of a chosen kind, duplicates and deletes tools
/// (refusing to delete one a path uses), edits the selected tool in a ToolEditor (each
/// finished field edit is one undoable SetToolsCommand; an invalid value shows the
/// planning::validateTool message inline and leaves the project as it was), loads tools from a
/// tool library file (appended) and saves the project's tools to one (io tool library). The
/// selected tool is drawn in the part view (cutting and non-cutting parts in two colours) at
/// the first pose of a path using it, or above the part.
class ToolsPanel : public Panel {
  Q_OBJECT

 public:
  explicit ToolsPanel(Workbench& workbench, QWidget* parent = nullptr);
  QString title() const override { return tr("Tools"); }
  QString id() const override { return "tools"; }

  /// @brief A sensible tool of @p kind (sizes in mm) as "Add" creates it.
  static planning::Tool defaultTool(planning::ToolKind kind);

  /// @brief Appends defaultTool(@p kind) and selects it (undoable). @return true if done.
  bool addTool(planning::ToolKind kind);
  /// @brief Appends a copy of tool @p index named "<name> copy" (undoable).
  bool duplicateTool(int index);
  /// @brief Removes tool @p index; refused (error reported) if a path uses it. Paths' tool
  /// indices above it move down by one (undoable).
  bool deleteTool(int index);
  /// @brief Replaces tool @p index by @p tool (undoable). An invalid tool is not applied: its
  /// message is shown in the form and returned false.
  bool editTool(int index, const planning::Tool& tool);
  /// @brief Appends the tools of the library file @p path (one undoable edit).
  bool loadLibrary(const QString& path);
  /// @brief Writes the project's tools to the library file @p path.
  bool saveLibrary(const QString& path);

  /// @brief Selects tool @p index in the list (-1: none).
  void selectTool(int index);
  /// @brief The selected tool's index, -1 if none.
  int selectedTool() const;
  /// @brief The form.
  ToolEditor& editor() const { return *editor_; }

 private:
  void refresh();
  void showSelected();
  void pushTools(std::vector<planning::Tool> tools, std::vector<int> newIndexOfOld,
                 const QString& text);

  QListWidget* list_ = nullptr;
  QComboBox* newKind_ = nullptr;
  QPushButton* duplicate_ = nullptr;
  QPushButton* delete_ = nullptr;
  QPushButton* save_ = nullptr;
  ToolEditor* editor_ = nullptr;
  /// The user picked a tool since the part was opened: only then is it drawn, so a freshly
  /// opened project shows its part unobstructed.
  bool drawTool_ = false;
};

}  // namespace ddfcam::gui
