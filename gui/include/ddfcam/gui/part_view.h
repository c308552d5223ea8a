// SPDX-License-Identifier: MIT
// ddfcam gui: keeps the 3D scene in step with the document: part geometry, field colours,
// path and tool overlays, and turns clicks into surface picks.
#pragma once

#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/gui/adapters/colour_map.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/part_facts.h>
#include <ddfcam/gui/part_geometry.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/tools/tool.h>

#include <Eigen/Geometry>
#include <QObject>
#include <QPointF>

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace ddfcam::gui {

class PartScene;
class VtkView;

/// @brief How the shown field is coloured.
struct FieldDisplay {
  std::string field;                   ///< name of the shown field; empty: plain surface
  ColourMap map = ColourMap::Viridis;  ///< colour map
  bool autoRange = true;               ///< range follows the data (symmetric if signed)
  double lo = 0.0;                     ///< value at the low end of the map (field unit)
  double hi = 1.0;                     ///< value at the high end of the map (field unit)
  /// Tolerance band of an error map (green inside, blue above, red below) instead of the
  /// colour map; cleared when another field is shown (default none).
  std::optional<planning::ToleranceBand> band{};
  /// Support faces the field is drawn on (ascending); the others show "no value" grey and
  /// count for no automatic range, e.g. an error map of one region. Empty: all faces. Cleared
  /// when another field is shown (default empty).
  std::vector<int> faces{};
};

/// @brief A picked point of the part surface.
struct PickResult {
  ddf::SurfaceLocation location;     ///< support face, barycentric coords, height, point
  std::optional<double> fieldValue;  ///< shown field at the point, if a field is shown
  std::string fieldName;             ///< name of the shown field (empty if none)
  std::string fieldUnit;             ///< its unit
};

/// @brief Observes a Document and shows its part in a VtkView through a PartScene: rebuilds
/// the surface when the part or its heights change, colours it by the chosen field (scalar bar
/// with units), draws the tool paths and an optional tool, and maps view clicks to PickResult
/// through the core's ddf::locateOnFace. Owns the scene.
class PartView : public QObject {
  Q_OBJECT

 public:
  PartView(Document& document, VtkView& view, DisplayParams params = {}, QObject* parent = nullptr);
  ~PartView() override;

  PartScene& scene() const { return *scene_; }
  VtkView& view() const { return view_; }
  /// @brief Geometry of the shown part, or null if the document has no part.
  const PartGeometry* geometry() const { return geometry_.get(); }
  /// @brief Size, raster spacing and crust reach of the shown part (recomputed with the
  /// geometry), or null if the document has no part.
  const PartFacts* facts() const { return facts_ ? &*facts_ : nullptr; }
  /// @brief One-line summary for the status bar: name, size in mm, "support N faces, m = ..,
  /// spacing .. mm", points, surface triangles.
  std::string summary() const;

  /// @brief Colours the surface by the field named @p name (empty: none), auto range.
  /// @throws InvalidInput if the document has no such field.
  void showField(const std::string& name);
  /// @brief Current field display settings.
  const FieldDisplay& fieldDisplay() const { return display_; }
  /// @brief The shown field's values, or null.
  const planning::ScalarField* shownField() const;
  /// @brief Changes the colour map of the shown field.
  void setColourMap(ColourMap map);
  /// @brief Fixes the colour range to [lo, hi] (field unit).
  /// @throws InvalidInput unless lo < hi, both finite.
  void setRange(double lo, double hi);
  /// @brief Lets the colour range follow the data again.
  void setAutoRange();
  /// @brief Colours the shown field as an error map with tolerance band @p band (nullopt:
  /// back to the colour map). An automatic range then also spans twice the band.
  /// @throws InvalidInput for an invalid band.
  void setToleranceBand(const std::optional<planning::ToleranceBand>& band);
  /// @brief Draws the shown field on @p faces only (FieldDisplay::faces; empty: all faces).
  /// @throws InvalidInput if a face index is out of range.
  void setShownFaces(std::vector<int> faces);

  /// @brief Shows @p tool at @p pose (part frame) as a translucent overlay; nullopt hides it.
  void setToolOverlay(const std::optional<std::pair<planning::Tool, Eigen::Isometry3d>>& tool);
  /// @brief Shows or hides the displacement vectors of the support vertices as arrows.
  void setVectorGlyphsVisible(bool visible);
  /// @brief Shows or hides the tool-path overlays (cuts, links, selected path).
  void setPathsVisible(bool visible);
  /// @brief Shows or hides the path named @p name (kept by name while paths are edited).
  void setPathVisible(const std::string& name, bool visible);
  bool isPathVisible(const std::string& name) const;
  /// @brief Highlights path @p index (-1: none) over the others (path_overlay.h).
  void setSelectedPath(int index);
  int selectedPath() const { return selectedPath_; }
  /// @brief Name of the overlay of the crust's offset surface on side @p side (+1: h = +1,
  /// -1: h = -1): "crust+1" or "crust-1".
  static std::string crustOverlayName(int side);
  /// @brief Shows or hides the crust's offset surface h = @p side (+1 or -1) as a translucent
  /// overlay (adapters/crust_surface.h), rebuilt when the part changes.
  /// @throws InvalidInput unless side is +1 or -1.
  void setCrustVisible(int side, bool visible);
  bool isCrustVisible(int side) const;

  /// @brief The surface point under widget position @p pos, or nullopt if the surface is not
  /// hit there. Marks the point with an arrow along its stubble (overlay "pick") and emits
  /// picked().
  std::optional<PickResult> pick(QPointF pos);

 signals:
  /// @brief The surface geometry was rebuilt; @p partReplaced if it is a different part.
  void geometryChanged(bool partReplaced);
  /// @brief The shown field, its values, colour map or range changed.
  void fieldDisplayChanged();
  /// @brief A pick succeeded.
  void picked(const ddfcam::gui::PickResult& result);

 private:
  void onDocumentChanged(Changes what);
  void rebuildGeometry(bool partReplaced);
  void applyFieldDisplay();
  /// The shown field's values with NaN outside FieldDisplay::faces.
  std::vector<float> shownValues(const planning::ScalarField& field) const;
  void rebuildPathOverlay();
  void rebuildGlyphOverlay();
  void rebuildCrustOverlay(int side);
  void showPickMarker(const ddf::SurfaceLocation& location);

  Document& document_;
  VtkView& view_;
  DisplayParams params_;
  std::unique_ptr<PartScene> scene_;
  std::unique_ptr<PartGeometry> geometry_;
  std::optional<PartFacts> facts_;
  FieldDisplay display_;
  bool pathsVisible_ = true;
  std::set<std::string> hiddenPaths_;  ///< names of the paths not drawn
  int selectedPath_ = -1;
  bool glyphsVisible_ = false;
  bool crustVisible_[2] = {false, false};  ///< h = +1, h = -1
};

}  // namespace ddfcam::gui

Q_DECLARE_METATYPE(ddfcam::gui::PickResult)
