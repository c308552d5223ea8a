// SPDX-License-Identifier: MIT
// ddfcam gui: the "Mould tools" panel: springback compensation by displacement adjustment on
// the study's mould DDF (dissertation ch. 9), with its history and convergence plot.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/shared_support_shapes.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/gui/workbench.h>
#include <ddfcam/length_unit.h>
#include <ddfcam/planning/mould/blend_function.h>
#include <ddfcam/planning/mould/springback_compensation.h>

#include <Eigen/Core>

#include <QString>

#include <optional>
#include <vector>

class QBoxLayout;
class QCheckBox;
class QComboBox;
class QGroupBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QPushButton;
class QSlider;
class QTableWidget;

namespace ddfcam::gui {

/// @brief Where the forming response of the last mould comes from.
enum class ResponseSource {
  ImportedSurface,  ///< a formed surface the user imported (forming simulation run outside)
  LinearModel       ///< the built-in planning::LinearSpringbackModel
};

/// @brief What a click in the mould view does for the blending group.
enum class BlendPickMode {
  None,        ///< nothing
  PickCentre,  ///< sets the centre of the radial fall-off
  PaintRegion  ///< adds the faces within the brush radius to the painted region
};

/// @brief The mould tools of ch. 9, three groups shown in the mould view (MouldView primary):
///
/// Blending: f = s + d h v over the study's comparison (ddf::morphPositions of its sequence
/// with the weights planning::blendWeights as the per-point times): constant, radial fall-off
/// from a point picked in the mould view, a painted region (clicks add the faces within the
/// brush radius, smooth edge) or distance to the boundary, with a strength value.
///
/// Warps and demos (figs. 9.1-9.3): the cube/sphere morph on a shared support with a slider t
/// in [0, 1] (ddf::morphHeights), and the engraved plate with "Scale vectors" (factor) and
/// "Bend onto cylinder" (radius). "Export shown surface..." writes what blending or the demos
/// last showed (io::writeMesh: STL, OBJ or PLY by the suffix).
///
/// Compensation: mould_{j+1} = mould_j - lambda (formed_j -
/// target) on the heights of the study's mould (target) DDF. "Start" begins a history on the
/// target DDF (the comparison's stages[0] support with zero heights, or the mould mesh
/// converted when there is no comparison). The forming response of the last mould is either
/// imported ("Import formed surface...", heights by planning::formedHeightsFromMesh) or given
/// by the linear model (alpha isotropic or per axis, its relaxed shape calibrated from the
/// study's formed surface, planning::calibrateSpringback). "Step" records the response of the
/// last mould if it has none and appends the next mould (one undo step each); the history table
/// lists iteration, source, max and RMS (mm), and the plot tab kConvergenceTab shows max and RMS
/// per iteration. "Export mould..." writes the chosen iteration's surface (io::writeMesh). Long
/// work runs through the JobRunner; every edit of Project::mould->compensation is undoable.
class MouldToolsPanel : public Panel {
  Q_OBJECT

 public:
  /// Plot tab of the convergence plot (graphs kMaxSeries and kRmsSeries over the iteration).
  static constexpr const char* kConvergenceTab = "Compensation convergence";
  static constexpr const char* kMaxSeries = "max |deviation|";
  static constexpr const char* kRmsSeries = "RMS deviation";

  explicit MouldToolsPanel(Workbench& workbench, QWidget* parent = nullptr);
  QString title() const override { return tr("Mould tools"); }
  QString id() const override { return "mouldTools"; }

  // Blending.
  /// @brief Replaces the blending parameters (kind, value, centre, radius, faces, widths).
  void setBlendParams(planning::BlendParams params);
  /// @brief The blending parameters as the panel shows them (painted faces included).
  planning::BlendParams blendParams() const;
  /// @brief What a click in the mould view does.
  void setBlendPickMode(BlendPickMode mode);
  /// @brief Handles a pick at @p point (mm, mould frame) as a click in the mould view does:
  /// sets the radial centre or paints the faces within the brush radius, then reshows.
  void applyPick(const Eigen::Vector3d& point);
  /// @brief Brush radius of painting, mm (> 0).
  void setBrushRadius(double radiusMm);
  /// @brief Computes the blended surface over the study's comparison and shows it.
  /// @return true if shown (errors are reported).
  bool showBlended();
  /// @brief Weights d per raster point copy of the last blended surface (empty before).
  const std::vector<float>& blendWeightsShown() const { return weights_; }

  // Warps and demos.
  /// @brief Parameters of the cube/sphere demo built by showCubeSphereDemo().
  void setCubeSphereParams(const ddf::CubeSphereParams& params) { cubeSphereParams_ = params; }
  /// @brief Builds the cube/sphere morph (job) and shows it at the slider's t.
  /// @return true if the job started.
  bool showCubeSphereDemo();
  /// @brief Moves the morph slider to @p t in [0, 1] and shows (1 - t) cube + t sphere.
  void setMorphTime(double t);
  /// @brief The cube/sphere morph, once built.
  const std::optional<ddf::CubeSphereMorph>& cubeSphere() const { return cubeSphere_; }
  /// @brief Parameters of the engraved plate built by showEngravedPlate().
  void setEngravedPlateParams(const ddf::EngravedPlateParams& params) { plateParams_ = params; }
  /// @brief Builds the engraved plate of fig. 9.2 a afresh and shows it. @return true if shown.
  bool showEngravedPlate();
  /// @brief Scales the shown plate's vectors by @p factor (fig. 9.2 b/c). @return true if done.
  bool scalePlateVectors(double factor);
  /// @brief Bends the shown plate onto a cylinder of radius @p radiusMm (fig. 9.2 d).
  /// @return true if done.
  bool bendPlateOntoCylinder(double radiusMm);
  /// @brief The engraved plate as last warped, once built.
  const std::optional<ddf::DisplacementField>& plate() const { return plate_; }

  /// @brief The surface blending or a demo showed last, mm (empty before).
  const ddf::TriangleMesh& shownSurface() const { return shown_; }
  /// @brief Writes shownSurface() to @p path (.stl, .obj or .ply). @return true if written.
  bool exportShownSurface(const QString& path);

  // Compensation.

  /// @brief Starts a compensation history on the study's target DDF (undoable; replaces a
  /// history already there). @return true if started.
  bool startCompensation();
  /// @brief Chooses the response source of the next Step.
  void setResponseSource(ResponseSource source);
  ResponseSource responseSource() const;
  /// @brief Sets lambda of the next Step, in (0, 10].
  void setLambda(double lambda);
  double lambda() const;
  /// @brief Replaces the linear model used by the LinearModel source (e.g. a known relaxed
  /// shape in tests); its alpha values are shown in the panel.
  void setLinearModel(planning::LinearSpringbackModel model);
  /// @brief The linear model in use, if set or calibrated.
  const std::optional<planning::LinearSpringbackModel>& linearModel() const { return model_; }
  /// @brief Calibrates the linear model from the study's formed surface with the alpha of the
  /// panel (job). @return true if the job started.
  bool calibrateLinearModel();
  /// @brief Reads @p path (STL/OBJ/PLY) as the part formed in the last mould and records it as
  /// that mould's response (job, one undo step). @return true if the job started.
  bool importFormedSurface(const QString& path);
  /// @brief Unit importFormedSurface() reads its file in (the combo next to the button; default
  /// mm); the mesh is scaled to mm.
  void setFormedUnit(LengthUnit unit);
  /// @brief Records the response of the last mould from the linear model, if it has none (one
  /// undo step; no new mould). @return true if the job started.
  bool evaluateLastMould();
  /// @brief Records the response of the last mould if it has none and appends the next mould
  /// (job, one undo step). @return true if the job started.
  bool step();
  /// @brief Writes the mould surface of iteration @p iteration to @p path (mm; format by the
  /// suffix: .stl, .obj, .ply). @return true if written (errors are reported).
  bool exportMould(int iteration, const QString& path);
  /// @brief Number of rows in the history table (= iterations of the history).
  int historyRows() const;
  /// @brief Shows the mould of iteration @p iteration in the mould view's primary view,
  /// coloured by its offset from the target along the stubbles (mm, positive along the DDF
  /// vectors, i.e. the mould's normal side; the study's band). @return false if there is no
  /// such iteration or no mould view.
  bool showMould(int iteration);
  /// @brief Offset (mm) per vertex of the mould mesh of @p iteration last shown by showMould().
  const std::vector<float>& shownMouldOffsets() const { return shownOffsets_; }

 private:
  QGroupBox* buildBlending();
  QFormLayout* buildBlendForm(QGroupBox* group);
  QGroupBox* buildWarps();
  QGroupBox* buildCompensation();
  QFormLayout* buildCompensationForm(QGroupBox* group);
  void buildCompensationButtons(QGroupBox* group, QBoxLayout* box);
  void buildHistoryTable(QGroupBox* group);
  void connectCompensation();
  void showSurface(ddf::TriangleMesh mesh, bool secondary, bool fitCamera);
  void showMorph();
  void refreshBlendWidgets();
  void refresh();
  void refreshHistory(const planning::CompensationHistory* history);
  void plotConvergence(const planning::CompensationHistory& history);
  planning::LinearSpringbackModel modelWithPanelAlphas() const;
  const planning::CompensationHistory* history() const;
  bool startHistoryJob(const QString& title, bool appendStep);
  QString askSavePath(const QString& title, const QString& filter);
  QString askOpenPath(const QString& title, const QString& filter);

  QComboBox* source_ = nullptr;
  QDoubleSpinBox* lambda_ = nullptr;
  QDoubleSpinBox* alpha_ = nullptr;
  QCheckBox* perAxis_ = nullptr;
  std::vector<QDoubleSpinBox*> axisAlpha_;
  QLabel* modelLabel_ = nullptr;
  QPushButton* start_ = nullptr;
  QPushButton* calibrate_ = nullptr;
  QPushButton* import_ = nullptr;
  QComboBox* importUnit_ = nullptr;
  QPushButton* evaluate_ = nullptr;
  QPushButton* step_ = nullptr;
  QPushButton* export_ = nullptr;
  QTableWidget* table_ = nullptr;
  QComboBox* blendKind_ = nullptr;
  QDoubleSpinBox* blendValue_ = nullptr;
  QDoubleSpinBox* blendRadius_ = nullptr;
  QDoubleSpinBox* blendEdge_ = nullptr;
  QDoubleSpinBox* blendBoundary_ = nullptr;
  QDoubleSpinBox* brush_ = nullptr;
  QComboBox* pickMode_ = nullptr;
  QLabel* blendLabel_ = nullptr;
  QSlider* morphSlider_ = nullptr;
  QDoubleSpinBox* scaleFactor_ = nullptr;
  QDoubleSpinBox* cylinderRadius_ = nullptr;
  planning::BlendParams blend_;
  std::vector<float> weights_;
  ddf::CubeSphereParams cubeSphereParams_;
  std::optional<ddf::CubeSphereMorph> cubeSphere_;
  ddf::EngravedPlateParams plateParams_;
  std::optional<ddf::DisplacementField> plate_;
  ddf::TriangleMesh shown_;
  std::optional<planning::LinearSpringbackModel> model_;
  std::vector<float> shownOffsets_;
  int shownHistorySize_ = 0;
};

}  // namespace ddfcam::gui
