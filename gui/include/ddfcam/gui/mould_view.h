// SPDX-License-Identifier: MIT
// ddfcam gui: the mould view: mould and formed surfaces side by side (linked cameras) or overlaid.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/mould/mould_study.h>

#include <Eigen/Core>

#include <QPointF>
#include <QString>
#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

namespace ddfcam::gui {

class VtkView;

/// @brief Two 3D views of the mould study: the primary view shows the mould side (plain or
/// coloured by the signed deviation with a tolerance band), the secondary view the formed side
/// (plain or coloured by a forming field such as thickness). Side by side the two cameras are
/// linked (moving one moves the other); in overlay the primary view alone shows the formed
/// surface semi-transparent over the coloured mould. A click on a surface emits pointPicked().
class MouldView : public QWidget {
  Q_OBJECT

 public:
  /// @brief How the two surfaces are shown.
  enum class Layout {
    SideBySide,  ///< two views, linked cameras (default)
    Overlay      ///< the primary view only, secondary surface translucent over the primary
  };

  /// @brief Index of the primary view in pointPicked().
  static constexpr int kPrimary = 0;
  /// @brief Index of the secondary view in pointPicked().
  static constexpr int kSecondary = 1;
  /// @brief Opacity of the secondary surface in the overlay layout, in (0, 1).
  static constexpr double kOverlayOpacity = 0.45;

  /// @brief Object names: "mouldPrimaryView", "mouldSecondaryView".
  explicit MouldView(QWidget* parent = nullptr);
  ~MouldView() override;

  /// @brief Switches the layout; keeps what is shown.
  void setLayout(Layout layout);
  /// @brief The current layout.
  Layout layout() const { return layout_; }

  /// @brief Shows @p mesh (mm, mould frame) in the primary view coloured by @p vertexValuesMm
  /// (one signed deviation per vertex, NaN = no value, shown grey) on the tolerance map:
  /// green inside @p band, blue above (short of the mould), red below (beyond the mould), with
  /// a scalar bar "deviation [mm]". The colour range is symmetric, at least twice the band.
  /// @throws InvalidInput if the sizes differ or the band is invalid.
  void showPrimary(const ddf::TriangleMesh& mesh, std::vector<float> vertexValuesMm,
                   const planning::ToleranceBand& band);
  /// @brief Shows @p mesh (mm, mould frame) plain grey in the primary view.
  void showPrimaryPlain(const ddf::TriangleMesh& mesh);
  /// @brief Shows @p mesh (mm, mould frame) in the secondary view (and translucent in the
  /// overlay): plain, or coloured by @p field (per vertex or per triangle, Viridis, with a
  /// scalar bar) when given. Keeps the camera unless nothing was shown before.
  /// @throws InvalidInput if the field's size does not fit the mesh.
  void showSecondary(const ddf::TriangleMesh& mesh, const planning::MeshField* field = nullptr);
  /// @brief Replaces only the vertex positions of the secondary surface (same triangles as the
  /// last showSecondary(); used by the live morph slider). @return false if the vertex count
  /// differs (then nothing changes).
  bool updateSecondaryPoints(const std::vector<Eigen::Vector3d>& vertices);
  /// @brief Draws poly-lines (mm, mould frame; e.g. the cross-section line and its curves) in
  /// both views in @p rgb (components in [0, 1]); replaces earlier overlay lines.
  void showOverlayLines(const std::vector<std::vector<Eigen::Vector3d>>& polylines,
                        const Eigen::Vector3d& rgb = Eigen::Vector3d(1.0, 0.85, 0.0));
  /// @brief Highlights the triangles @p triangles of the primary mesh (e.g. crossing faces) as a
  /// magenta wireframe; an empty list removes the highlight.
  void showHighlightedTriangles(const std::vector<int>& triangles);
  /// @brief Removes every surface, line and highlight from both views.
  void clear();
  /// @brief Fits both cameras to their contents (isometric direction).
  void fitCameras();

  /// @brief The mould-side view.
  VtkView& primaryView() const { return *primary_; }
  /// @brief The formed-side view (hidden in the overlay layout).
  VtkView& secondaryView() const { return *secondary_; }
  /// @brief Number of points of the secondary surface shown (0 if none).
  int secondaryPointCount() const;
  /// @brief Point @p i of the secondary surface as shown, mm (for tests).
  Eigen::Vector3d secondaryPoint(int i) const;
  /// @brief True if the primary surface is coloured by deviation (not plain).
  bool primaryColoured() const;

  /// @brief Picks the surface under widget position @p widgetPos of view @p view (kPrimary or
  /// kSecondary), as a click does, and emits pointPicked() on a hit.
  /// @return the picked point, or std::nullopt if nothing was hit.
  std::optional<Eigen::Vector3d> pickAt(int view, QPointF widgetPos);

  /// @brief Writes both views (side by side: one image, the views next to each other; overlay:
  /// the primary view) to @p path (format from the suffix). @return false if not written.
  bool saveScreenshot(const QString& path);

 signals:
  /// @brief A click hit a surface of view @p view (kPrimary or kSecondary) at @p point (mm,
  /// mould frame; cell picking).
  void pointPicked(int view, Eigen::Vector3d point);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  struct Scene;
  void linkCameras();
  /// Colours the secondary surface by @p field (values already checked against the mesh).
  void colourSecondary(const planning::MeshField& field);

  VtkView* primary_ = nullptr;
  VtkView* secondary_ = nullptr;
  Layout layout_ = Layout::SideBySide;
  std::unique_ptr<Scene> scene_;
};

}  // namespace ddfcam::gui
