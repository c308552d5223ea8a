// SPDX-License-Identifier: MIT
// ddfcam gui: the "Mould comparison" panel: load, align and compare a formed surface with the
// mould, statistics, histogram, cross sections and the morph slider (dissertation ch. 9).
#pragma once

#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/gui/workbench.h>
#include <ddfcam/length_unit.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/mould/mould_study.h>

#include <Eigen/Core>

#include <QString>

#include <array>
#include <functional>
#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSlider;
class QSpinBox;

namespace ddfcam::gui {

class MouldView;

/// @brief Mould comparison: Load mould / Load formed (STL, OBJ, PLY, OFF, VTP, VTU), alignment
/// (none, picked point pairs, best fit with its warning), resolution, tolerance band and normal
/// flip, Compare (a job with progress and cancel), statistics, the area histogram and the
/// crossing region, cross sections drawn by two clicks on the mould view, deviation export, and
/// the morph slider F(lambda) with its export. Every edit of Project::mould is one undoable
/// SetMouldStudyCommand; the MouldView of the workbench shows the study.
class MouldPanel : public Panel {
  Q_OBJECT

 public:
  /// Plot tab of the area histogram of the deviation.
  static inline const QString kHistogramTab = QStringLiteral("Mould deviation");
  /// Plot tab of the cross-section curves (graphs "mould" and "formed").
  static inline const QString kSectionTab = QStringLiteral("Cross section");
  /// Bins of the area histogram.
  static constexpr int kHistogramBins = 40;

  /// @brief What the next click on the mould view means.
  enum class PickMode {
    None,          ///< clicks do nothing
    PairFormed,    ///< the next click on the formed (secondary) view is a pair's formed point
    PairMould,     ///< the next click on the mould (primary) view completes the pair
    SectionStart,  ///< the next click on the mould view starts the section line
    SectionEnd     ///< the next click ends it and draws the section
  };

  /// @brief Asks for a file path: @p save chooses a save dialog; empty = cancelled.
  using PathProvider =
      std::function<QString(const QString& title, const QString& filter, bool save)>;

  explicit MouldPanel(Workbench& workbench, QWidget* parent = nullptr);
  QString title() const override { return tr("Mould comparison"); }
  QString id() const override { return QStringLiteral("mouldComparison"); }

  /// @brief Replaces the file dialogs (tests). Default: QFileDialog.
  void setPathProvider(PathProvider provider) { askPath_ = std::move(provider); }

  /// @brief Units the next loadMould() and loadFormed() read their files in (the unit combos
  /// next to the buttons; default mm); the meshes are scaled to mm.
  void setSurfaceUnits(LengthUnit mould, LengthUnit formed);
  /// @brief Loads the mould surface from @p path in the mould unit (one undoable edit; drops
  /// formed-side results that referred to the old mould). Errors are reported.
  /// @return true if loaded.
  bool loadMould(const QString& path);
  /// @brief Loads the formed surface from @p path in the formed unit, as positioned (alignment
  /// None). Needs a mould. @return true if loaded.
  bool loadFormed(const QString& path);

  /// @brief Chooses the alignment method of the next applyAlignment().
  void setAlignmentMethod(planning::AlignmentMethod method);
  planning::AlignmentMethod alignmentMethod() const;
  /// @brief Adds a picked pair (formed point as shown now, mould point), mm, mould frame.
  void addPointPair(const Eigen::Vector3d& formedShown, const Eigen::Vector3d& mould);
  /// @brief Removes every pending pair.
  void clearPointPairs();
  /// @brief Pending pairs (formed in its file frame, mould).
  const std::vector<std::array<Eigen::Vector3d, 2>>& pointPairs() const { return pairs_; }
  /// @brief Aligns the formed surface: None resets to the file frame, PointPairs fits the pending
  /// pairs, BestFit runs ICP as a job. @return true if applied (or the job started).
  bool applyAlignment();

  /// @brief Comparison settings for the next compare().
  void setResolution(int m);
  /// @brief Sets the tolerance band, mm; an existing comparison is re-evaluated for it (one undo
  /// step). @throws InvalidInput for an invalid band.
  void setToleranceBand(const planning::ToleranceBand& band);
  /// @brief Reverses the mould normal (the sign of every deviation); re-evaluates an existing
  /// comparison (one undo step).
  void setFlipNormal(bool flip);
  /// @brief Starts the comparison job (planning::compareSurfaces). @return true if started.
  bool compare();

  /// @brief Statistics as shown (empty-study text if there is no result).
  QString statisticsText() const;
  /// @brief The crossing-region label as shown.
  QString crossingText() const;
  /// @brief The alignment label (method, RMS, best-fit warning) as shown.
  QString alignmentText() const;

  /// @brief Sets the morph time lambda in [-1, 2] (0 = mould, 1 = formed) and shows F(lambda) on
  /// the formed side (needs a comparison). @return false if there is no comparison.
  bool setMorphLambda(double lambda);
  double morphLambda() const;
  /// @brief The morph surface at the current lambda: raster mesh of the comparison, mm; vertex v
  /// at the position of the first copy of its raster point (missing points stay at the mould).
  std::optional<ddf::TriangleMesh> morphSurface() const;
  /// @brief Writes morphSurface() to @p path (io::writeMesh). @return true if written.
  bool exportMorphSurface(const QString& path);
  /// @brief Writes the deviation to @p path: .vtp (the mould's raster mesh with the signed
  /// deviation, tolerance class and deviation vectors as point data) or .csv (one row per raster
  /// point: position, deviation vector, signed deviation, mm). @return true if written.
  bool exportDeviation(const QString& path);

  /// @brief Arms picking: the next clicks in the MouldView follow @p mode.
  void setPickMode(PickMode mode);
  PickMode pickMode() const { return mode_; }
  /// @brief Draws the section through mould points @p a and @p b (mm) seen along the current
  /// camera direction: both surfaces' curves in tab kSectionTab and the curves in the view.
  /// @return true if drawn.
  bool drawSection(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

 private:
  /// The pick mode into the status bar (InteractionMode); Esc or leaving the panel ends it.
  void announcePickMode();
  void buildInputs();
  void buildAlignment();
  void applyDirectAlignment(planning::MouldStudy study, planning::AlignmentMethod method);
  bool startBestFit(const planning::MouldStudy& study);
  void buildOutputs();
  void buildMorph();
  void refresh();
  void showStudy();
  // Re-evaluates the stored comparison for the band and orientation in the widgets.
  void applyBandToResult();
  void showResult(const planning::MouldStudy& study);
  void indexRasterCopies(const ddf::DisplacementField& ddf);
  void showResultText(const planning::SurfaceComparison& r);
  void showHistogram(const planning::SurfaceComparison& r, const ddf::DisplacementField& ddf);
  void showDeviation(MouldView& view, const planning::SurfaceComparison& r,
                     const ddf::DisplacementField& ddf);
  void showMorph();
  void onPicked(int view, const Eigen::Vector3d& point);
  void pushStudy(std::optional<planning::MouldStudy> after, const QString& text);
  planning::ComparisonParams comparisonParams() const;
  QString ask(const QString& title, const QString& filter, bool save);

  PathProvider askPath_;
  PickMode mode_ = PickMode::None;
  std::vector<std::array<Eigen::Vector3d, 2>> pairs_;
  std::optional<Eigen::Vector3d> pendingFormed_, sectionStart_;
  /// Raster mesh of the shown comparison and the first copy of each of its vertices.
  std::optional<ddf::RasterMesh> raster_;
  std::vector<std::size_t> vertexCopy_;
  bool morphShown_ = false;

  QComboBox* alignment_ = nullptr;
  QComboBox* mouldUnit_ = nullptr;
  QComboBox* formedUnit_ = nullptr;
  QListWidget* pairList_ = nullptr;
  QLabel* alignmentLabel_ = nullptr;
  QSpinBox* resolution_ = nullptr;
  QDoubleSpinBox* lower_ = nullptr;
  QDoubleSpinBox* upper_ = nullptr;
  QCheckBox* flip_ = nullptr;
  QPushButton* compare_ = nullptr;
  QLabel* files_ = nullptr;
  QLabel* stats_ = nullptr;
  QLabel* crossing_ = nullptr;
  QSlider* morph_ = nullptr;
  QLabel* morphLabel_ = nullptr;
  QComboBox* layout_ = nullptr;
};

}  // namespace ddfcam::gui
