// SPDX-License-Identifier: MIT
// ddfcam gui: the options of a grinding simulation shared by playback and the "Simulate" job.
#pragma once

#include <ddfcam/planning/simulation/grinding_simulation.h>
#include <ddfcam/planning/simulation/preston_removal.h>

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;

namespace ddfcam::gui {

/// @brief How material is removed by a simulation.
enum class RemovalModel {
  Rigid = 0,    ///< the tool's volume is cut by the DDF depth buffer (GrindingSimulation)
  Preston = 1,  ///< compliant removal, depth proportional to pressure x speed / feed
};

/// @brief Widget of the simulation options. Child object names: "sweepModeCombo" (Discrete /
/// Swept volume), "vConvexityCheck", "collisionCheck", "removalModelCombo" (Rigid / Preston),
/// "prestonCoefficientSpin" (K_p in units of 1e-7 mm^2/N), "prestonForceSpin" (N),
/// "prestonSpeedSpin" (wheel surface speed, m/s), "prestonFeedSpin" (feed, mm/min). The Preston
/// fields are enabled only for the Preston model. The feed is not an option of its own: the
/// owner shows the selected path's ToolPath::feedMmPerMin in it (showFeed) and stores an edit
/// in the path (feedEdited), so the simulation and exported programs use one feed.
class SimulationOptions : public QWidget {
  Q_OBJECT

 public:
  explicit SimulationOptions(QWidget* parent = nullptr);

  /// @brief Mode and checks of the rigid model (depth buffer defaults).
  planning::GrindingSimulationParams grindingParams() const;
  /// @brief Preston parameters converted to mm, N, s (progress and normals left empty; the feed
  /// is the one shown, which the owner keeps equal to the selected path's).
  planning::PrestonParams prestonParams() const;
  RemovalModel removalModel() const;

  void setSweepMode(planning::SweepMode mode);
  void setRemovalModel(RemovalModel model);
  void setChecks(bool vConvexity, bool collisions);
  /// @brief Sets the Preston fields: K_p in mm^2/N, F in N, v_s in m/s, feed in mm/min (as if
  /// typed: a changed feed emits feedEdited).
  void setPreston(double coefficientMm2PerN, double forceN, double speedMPerS, double feedMmPerMin);
  /// @brief Shows @p feedMmPerMin (the selected path's feed) without emitting feedEdited.
  void showFeed(double feedMmPerMin);

 signals:
  /// @brief Any option changed.
  void changed();
  /// @brief The user set the feed to @p feedMmPerMin (mm/min), for the selected path.
  void feedEdited(double feedMmPerMin);

 private:
  void updateEnabled();

  QComboBox* mode_ = nullptr;
  QCheckBox* vConvexity_ = nullptr;
  QCheckBox* collisions_ = nullptr;
  QComboBox* model_ = nullptr;
  QDoubleSpinBox* coefficient_ = nullptr;
  QDoubleSpinBox* force_ = nullptr;
  QDoubleSpinBox* speed_ = nullptr;
  QDoubleSpinBox* feed_ = nullptr;
};

}  // namespace ddfcam::gui
