// SPDX-License-Identifier: MIT
// ddfcam gui: a form editing every field of a planning::Tool, with an inline message line.
#pragma once

#include <ddfcam/planning/tools/tool.h>

#include <QString>
#include <QWidget>

#include <array>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace ddfcam::gui {

/// @brief The form of the Tools panel: name, kind, every size in mm, chord tolerance and
/// segments. It holds no project state: setTool() fills it, tool() reads it back, edited() is
/// emitted when the user finished changing a field (Enter, focus out, a new kind), and the
/// owner validates (planning::validateTool) and shows the outcome with setMessage().
/// Child object names: "toolName", "toolKind", "toolRadius", "toolWidth", "toolEdgeRadius",
/// "toolCrownRadius", "toolShankRadius", "toolShankLength", "toolHolderRadius",
/// "toolHolderLength", "toolChordTolerance", "toolSegments", "toolMessage".
class ToolEditor : public QWidget {
  Q_OBJECT

 public:
  explicit ToolEditor(QWidget* parent = nullptr);

  /// @brief Shows @p tool (no edited() signal).
  void setTool(const planning::Tool& tool);
  /// @brief The tool the form describes now (it may be invalid).
  planning::Tool tool() const;
  /// @brief Shows @p message under the form in red; empty hides it.
  void setMessage(const QString& message);
  /// @brief The message shown (empty if none).
  QString message() const;

  /// @brief Display name of @p kind, e.g. "grinding roll".
  static QString kindName(planning::ToolKind kind);

 signals:
  /// @brief The user finished editing a field; tool() holds the new values.
  void edited();

 private:
  enum Length {
    Radius,
    Width,
    EdgeRadius,
    CrownRadius,
    ShankRadius,
    ShankLength,
    HolderRadius,
    HolderLength,
    ChordTolerance,
    LengthCount
  };
  QDoubleSpinBox* addLength(QFormLayout* form, Length which, const char* name);
  void relabel(planning::ToolKind kind);
  void emitIfChanged();

  QLineEdit* name_ = nullptr;
  QComboBox* kind_ = nullptr;
  std::array<QDoubleSpinBox*, LengthCount> lengths_{};
  std::array<QLabel*, LengthCount> labels_{};
  QSpinBox* segments_ = nullptr;
  QLabel* message_ = nullptr;
  planning::Tool shown_;  ///< values last set or emitted: edited() fires only on a change
  bool filling_ = false;
};

}  // namespace ddfcam::gui
