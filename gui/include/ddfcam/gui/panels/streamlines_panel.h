// SPDX-License-Identifier: MIT
// ddfcam gui: the Streamlines panel: tool flow field display and tool paths along it.
#pragma once

#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/gui/workbench.h>
#include <ddfcam/planning/flow/flow_field.h>
#include <ddfcam/planning/flow/line_field.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/lines/streamline_path.h>
#include <ddfcam/planning/model/region_plan.h>
#include <ddfcam/planning/pipeline/region_planning.h>
#include <ddfcam/planning/placement/path_sampling.h>

#include <QPointF>
#include <cstdint>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLayout;
class QPushButton;
class QSlider;
class QToolButton;

namespace ddfcam::gui {

class FlowFieldDisplay;
class PathListWidget;
struct PickResult;

/// @brief What the flow field depends on besides the part's heights: the field choices of a
/// region plan (its other members at their defaults) and the region's faces.
struct FieldChoice {
  planning::RegionPlan plan;           ///< flow source, fixed direction, strokes, smoothing
  std::vector<std::uint8_t> faceMask;  ///< faces of the region; empty: whole part

  bool operator==(const FieldChoice&) const = default;
};

/// @brief Plans tool paths along the tool flow field (sec. 8.1/8.3). The field
/// (planning::flowField) follows k_max, k_min, a fixed direction projected onto the surface or
/// strokes the user draws on the part ("Draw direction"), optionally smoothed with Ceres, on
/// the whole part or on one region (its faces bound the field and the lines, its plan gives
/// the defaults, tool and linking order). The field, both principal directions and the
/// field's singularities are shown as glyph overlays (FlowFieldDisplay).
/// Seeding: a click traces one streamline with the chosen method (RK4, raster walk or
/// continuous, planning::traceStreamlineWith); a family is seeded every w mm along the
/// transverse line through the last pick (fig. 8.11; the transverse line by RK4, the family's
/// lines by the chosen method); "Cover" fills the region with evenly spaced lines d_sep apart
/// (planning::evenlySpacedStreamlines, always RK4), or, for a region plan in ScallopTolerance
/// mode with a ball tool, lines whose separation follows the scallop-height formula at the
/// local cross-feed curvature (planning/scallop_spacing.h).
/// Direction strokes drawn while a region is chosen belong to its plan (RegionPlan::strokes,
/// each stroke and "Clear strokes" one SetRegionsCommand); on the whole part they belong to
/// the panel. Lines of a family or cover are ordered and oriented by
/// planning::linkStreamlines (zig-zag or one direction) when "link" is on. Each seeding adds
/// one path (one undo step) that keeps the lines as traced and its linking's idle length
/// (ToolPath::rawLines, linkedIdleMm: saved, undone and renamed with the path, and carried
/// over when the path is smoothed or faired). The smoothing slider previews
/// planning::smoothMovingAverage of the selected path's raw lines live (overlay
/// kPreviewOverlay, no undo step); "Apply" replaces the path by the smoothed lines put back
/// on the surface (one undo step); "Fair" replaces it by planning::fairStreamline of the raw
/// lines (a job, one undo step). The "Tool placement" group sets lead and tilt
/// (planning::PlacementParams) and, with "sample from tolerance", resamples the lines along
/// the feed at the tolerance-derived step (or an override; planning::placeAlongPath) whenever
/// the panel creates or replaces a path; a label shows the step and binding rule of the last
/// created path. The path list shows every path's line count, cutting and idle length and a
/// total. Fields and tracing run as cancellable jobs; the field is kept until the part, its
/// heights or the choices change.
class StreamlinesPanel : public Panel {
  Q_OBJECT

 public:
  explicit StreamlinesPanel(Workbench& workbench, QWidget* parent = nullptr);
  ~StreamlinesPanel() override;
  QString title() const override { return tr("Streamlines"); }
  QString id() const override { return "streamlines"; }

  /// Overlay showing the smoothed lines of the selected path while the slider is not zero.
  static constexpr const char* kPreviewOverlay = "smoothing preview";

  /// @brief Selects the raw field: k_max, k_min, a fixed direction (x, y or z axis, else the
  /// nearest of them) or the drawn strokes.
  void setFieldSource(planning::FlowFieldSource source,
                      const ddf::Vec3& fixedDirection = ddf::Vec3::UnitX());
  /// @brief Turns Ceres smoothing of the field on or off, with weight lambda.
  void setFieldSmoothing(bool on, double weight = 0.02);
  /// @brief Restricts field and lines to region @p index of the project (-1: whole part) and
  /// takes the region plan's flow source, smoothing and spacing as the panel's settings.
  void setRegion(int index);
  /// @brief Computes the field if needed (a job) and shows its glyphs.
  /// @return true if shown or the job started.
  bool showField();
  /// @brief The glyph overlays (toggles, last glyphs shown, singularities).
  FlowFieldDisplay& fieldDisplay() const { return *display_; }
  /// @brief The current tool flow field, or null before it was computed.
  const planning::LineField* flowField() const;

  /// Overlay showing the direction strokes drawn by the user.
  static constexpr const char* kStrokeOverlay = "direction strokes";
  /// @brief Turns "Draw direction" on or off: while on, a left-button drag on the part records
  /// a stroke of picked surface points (instead of turning the camera); each finished stroke
  /// is added with addStroke().
  void setDrawDirection(bool on);
  /// @brief Adds a direction stroke (a polyline on the surface, mm, part frame, >= 2 points)
  /// and selects the drawn-strokes field (FlowFieldSource::UserStrokes). With a region chosen
  /// the stroke is appended to its plan's strokes and the plan's flow source set to
  /// UserStrokes, as one undo step.
  void addStroke(std::vector<ddf::Vec3> stroke);
  /// @brief Removes all drawn strokes: the chosen region's (one undo step, none if it has no
  /// strokes), else the panel's.
  void clearStrokes();
  /// @brief The strokes the drawn-strokes field follows: the chosen region plan's, else the
  /// panel's.
  const std::vector<std::vector<ddf::Vec3>>& strokes() const;

  /// @brief Chooses the tracer of click seeding and families (not of "Cover", which is RK4).
  void setStreamlineMethod(planning::StreamlineMethod method);
  /// @brief The tracer of click seeding and families.
  planning::StreamlineMethod streamlineMethod() const;

  /// @brief Turns click seeding on or off (the "Seed by click" button).
  void setSeedByClick(bool on);
  /// @brief Adds the streamline through @p seed as a path. @return true if the job started.
  bool seedAt(const ddf::SurfaceLocation& seed);
  /// @brief Adds a family of streamlines seeded along the transverse line through the last
  /// pick, spaced as set. @return true if the job started.
  bool seedFamily();
  /// @brief Covers the region (or the part) with evenly spaced lines @p dSepMm apart (> 0,
  /// planning::evenlySpacedStreamlines, Jobard-Lefer). For a region whose plan is in
  /// ScallopTolerance mode and whose tool is a ball, the separation follows the scallop-height
  /// formula at the local cross-feed curvature (planning::scallopSpacingField with
  /// RegionPlan::scallopToleranceMm, at least planning::kMinScallopSpacingMm);
  /// with a straight roll the plan's fixed spacing is used and the status label says why
  /// (planning::regionSpacing). @return true if the job started.
  bool coverRegion(double dSepMm);

  /// @brief Sets the moving-average half window k of the slider (0: off); updates the preview.
  void setSmoothingWindow(int halfWindow);
  /// @brief Replaces the selected path by its raw lines smoothed with the slider's window (one
  /// undo step). @return true if the path was replaced.
  bool applySmoothing();
  /// @brief Replaces the selected path by its raw lines faired with Ceres
  /// (planning::fairStreamline) within @p deviationMm of the raw lines, as a job (one undo
  /// step). @return true if the job started.
  bool fairSelected(double deviationMm);
  /// @brief The path list.
  PathListWidget& pathList() const { return *pathList_; }

  /// @brief Sets the lead and tilt angles of the tool on new paths, deg (|angle| < 90; the
  /// spin boxes clamp to +-89).
  void setPlacementAngles(double leadDeg, double tiltDeg);
  /// @brief Turns "sample from tolerance" on or off with tolerance @p toleranceMm (> 0) and an
  /// optional fixed step @p stepOverrideMm (> 0) (spin boxes clamp to their ranges).
  void setSampling(bool fromTolerance, double toleranceMm,
                   std::optional<double> stepOverrideMm = std::nullopt);
  /// @brief Path parameters the panel uses for new paths (placement and sampling from the
  /// "Tool placement" group; name and feed at their defaults).
  planning::StreamlinePathParams placementParams() const;
  /// @brief Sampling of each pass of the last path the panel created or replaced (empty
  /// without sampling or before any path).
  const std::vector<planning::PassSampling>& lastSampling() const { return lastSampling_; }

  /// @brief The line fields paths follow, cached per state of the part's heights.
  struct Fields;

 protected:
  /// Records strokes from mouse drags on the 3D view while "Draw direction" is on.
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void appendStrokePoint(QPointF widgetPos);
  void showStrokes();
  void setPlanStrokes(std::vector<std::vector<ddf::Vec3>> strokes, const QString& text);
  /// Traces lines on a copy of the part with the current fields (worker thread).
  using LineWork = std::function<std::vector<planning::Streamline>(
      const ddf::DisplacementField& part, const Fields& fields, const ProgressCallback& progress)>;
  QWidget* buildFieldGroup();
  QLayout* buildDrawRow(QWidget* group);
  QLayout* buildGlyphToggles(QWidget* group);
  QWidget* buildSeedGroup();
  QWidget* buildSmoothingGroup();
  QWidget* buildPlacementGroup();
  /// Places @p tool along @p lines with the placement group's settings and shows the sampling.
  planning::ToolPath placeLines(const ddf::DisplacementField& part,
                                const std::vector<planning::Streamline>& lines,
                                const planning::Tool& tool, int toolIndex,
                                planning::StreamlinePathParams params);
  void showSampling();
  void onPicked(const PickResult& pick);
  /// The path list with the view's visibility ticks; the view highlights its selection.
  void refreshPathList();
  void refreshRegions();
  FieldChoice currentChoice() const;
  /// @p note, filled by @p work, is added to the status label when the path is added.
  bool runWithFields(const QString& title, LineWork work, const QString& pathName,
                     std::shared_ptr<const QString> note = nullptr);
  void adoptFields(std::shared_ptr<const Fields> fields);
  void addPath(std::vector<planning::Streamline> lines, const QString& name);
  void replaceSelected(std::vector<planning::Streamline> lines, const QString& what);
  const std::vector<planning::Streamline>* selectedRawLines(int* index) const;
  /// The plan of the selected region, null for the whole part.
  const planning::RegionPlan* selectedPlan() const;
  void updatePreview();

  QComboBox* region_ = nullptr;
  QComboBox* direction_ = nullptr;
  QCheckBox* smooth_ = nullptr;
  QDoubleSpinBox* weight_ = nullptr;
  QToolButton* seedByClick_ = nullptr;
  QComboBox* method_ = nullptr;
  QToolButton* draw_ = nullptr;
  QObject* viewWidget_ = nullptr;  ///< the 3D view whose mouse events draw strokes (compared only)
  std::vector<std::vector<ddf::Vec3>> strokes_;
  std::optional<std::vector<ddf::Vec3>> stroke_;  ///< the stroke being drawn
  bool drawing_ = false;                          ///< a pick of a stroke is under way
  QDoubleSpinBox* spacing_ = nullptr;
  QDoubleSpinBox* dSep_ = nullptr;
  QCheckBox* link_ = nullptr;
  QSlider* window_ = nullptr;
  QLabel* windowLabel_ = nullptr;
  QDoubleSpinBox* deviation_ = nullptr;
  QDoubleSpinBox* lead_ = nullptr;
  QDoubleSpinBox* tilt_ = nullptr;
  QCheckBox* sampleFromTolerance_ = nullptr;
  QDoubleSpinBox* tolerance_ = nullptr;
  QCheckBox* overrideStep_ = nullptr;
  QDoubleSpinBox* step_ = nullptr;
  QLabel* samplingLabel_ = nullptr;
  std::vector<planning::PassSampling> lastSampling_;
  std::vector<QCheckBox*> glyphToggles_;  ///< flow, k_max, k_min, singularities
  QLabel* status_ = nullptr;
  PathListWidget* pathList_ = nullptr;
  std::unique_ptr<FlowFieldDisplay> display_;
  std::shared_ptr<const Fields> fields_;
  std::optional<ddf::SurfaceLocation> lastPick_;
  /// Counts changes of the part or its heights: a job's result for an older state is dropped.
  std::uint64_t generation_ = 0;
};

/// The line fields the paths follow, for one state of the part's heights.
struct StreamlinesPanel::Fields : planning::RegionFields {
  FieldChoice choice;
  std::shared_ptr<const planning::CurvatureField> curvature;
};

/// @brief Curvature (reused if @p curvature is given, else computed with @p curvatureParams,
/// e.g. planning::partCurvatureParams of the project) and the region's fields
/// (planning::regionFields). Progress runs over [0, 1]; false cancels.
std::shared_ptr<StreamlinesPanel::Fields> computeStreamlineFields(
    const ddf::DisplacementField& part, const FieldChoice& choice,
    std::shared_ptr<const planning::CurvatureField> curvature,
    const planning::CurvatureParams& curvatureParams, const ProgressCallback& progress);

}  // namespace ddfcam::gui
