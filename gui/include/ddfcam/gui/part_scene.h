// SPDX-License-Identifier: MIT
// ddfcam gui: the VTK actors showing one part (surface, support, stubbles, field, overlays).
#pragma once

#include <ddfcam/gui/adapters/colour_map.h>
#include <ddfcam/planning/inspection/error_map.h>

#include <Eigen/Core>

#include <QPointF>

#include <vtkPolyData.h>  // complete types: SceneGeometry is copied and destroyed by value
#include <vtkTexture.h>
#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

class vtkActor;
class vtkCellLocator;
class vtkLookupTable;
class vtkRenderer;
class vtkScalarBarActor;

namespace ddfcam::gui {

class RasterFieldSurface;
class RasterTextureAtlas;
class VtkView;

/// @brief What the workbench can draw of a part.
enum class Layer {
  Surface = 0,  ///< represented surface, shaded
  Support,      ///< support mesh S, wireframe
  Stubbles,     ///< stubbles (displacement segments), lines
};
constexpr int kLayerCount = 3;

/// @brief Polydata for every layer of one part, already converted by the adapters.
struct SceneGeometry {
  vtkSmartPointer<vtkPolyData> surface;   ///< triangles with point normals
  vtkSmartPointer<vtkPolyData> support;   ///< line cells
  vtkSmartPointer<vtkPolyData> stubbles;  ///< line cells
  /// Colours of the surface at raster resolution through its point texture coordinates (e.g.
  /// the live tolerance band); null: the plain surface colour or a field.
  vtkSmartPointer<vtkTexture> surfaceTexture;
  /// Where the surface's triangle corners lie on the part's raster, for fields shown at raster
  /// resolution (PartScene::setSurfaceRasterField): 6 floats per surface triangle, (i, k) of
  /// its corners in the cell's point order, raster steps on the triangle's support face ("face"
  /// cell data); null: fields are coloured per display vertex only.
  std::shared_ptr<const std::vector<float>> surfaceCornerParams;
  int rasterFaces = 0;  ///< support faces of the raster the corner parameters refer to
  int rasterSteps = 0;  ///< its raster steps per face edge (m - 1)
};

/// @brief How a scalar field is shown on the surface.
struct FieldStyle {
  ColourMap map = ColourMap::Viridis;  ///< colour map (default Viridis)
  double lo = 0.0;                     ///< value shown with the map's first colour (default 0)
  double hi = 1.0;                     ///< value shown with its last colour, > lo (default 1)
  std::string title;  ///< scalar bar title with unit, e.g. "material removed [mm]" (default "")
  /// Error-map colouring instead of map: green inside the band, blue above, red below
  /// (makeToleranceLookupTable); nullopt = use map (default).
  std::optional<planning::ToleranceBand> band{};
  /// The values describe other heights than the surface's (planning::isStale): the title is
  /// drawn in orange (default false).
  bool stale = false;
};

/// @brief Look of one overlay.
struct OverlayStyle {
  std::array<double, 3> rgb = {1.0, 0.85, 0.2};  ///< colour, RGB in [0, 1] (default amber)
  double lineWidth = 2.0;                        ///< pixels (default 2)
  double opacity = 1.0;                          ///< 0 transparent .. 1 opaque (default 1)
  /// false: lines (polygons as their edges), unlit; true: polygons shaded (lit), e.g. a tool
  /// mesh (default false)
  bool surface = false;
  double pointSize = 5.0;  ///< pixels, for vertex cells (default 5)
  /// Drawn over the part even where the part hides it (tool paths under the stock); it then
  /// does not take part in the 3D scene's depth order. Default false.
  bool onTop = false;
};

/// @brief A point of the displayed surface hit by a pick.
struct SurfacePick {
  vtkIdType cell = -1;  ///< surface polydata cell (display triangle)
  int face = -1;        ///< its support face ("face" cell data), -1 if none
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< hit point, mm, part frame
};

/// @brief Owns one actor per Layer, a scalar bar and any number of named overlays in a
/// renderer, and their styling. Knows nothing of DDFs: it shows the polydata and values it is
/// given.
class PartScene {
 public:
  /// @brief Adds the (initially empty) actors to @p renderer and the scalar bar to
  /// @p annotationRenderer; both must outlive the scene. Without an annotation renderer the
  /// scalar bar goes to a renderer of layer 1 in @p renderer's render window (as
  /// VtkView::annotationRenderer()), else to @p renderer itself. (In the 3D renderer, VTK 9.1
  /// lays the bar out wrongly in the first frame that has translucent props.)
  explicit PartScene(vtkRenderer* renderer, vtkRenderer* annotationRenderer = nullptr);
  ~PartScene();
  PartScene(const PartScene&) = delete;
  PartScene& operator=(const PartScene&) = delete;

  /// @brief Replaces the geometry of every layer (null members show nothing) and clears the
  /// surface field (its values belonged to the old surface); a surface texture is shown on a white
  /// material (its own colours, lit), none restores the surface colour. Overlays are kept.
  void setGeometry(const SceneGeometry& geometry);
  /// @brief Shows or hides @p layer.
  void setVisible(Layer layer, bool visible);
  bool isVisible(Layer layer) const;
  /// @brief Number of cells (triangles or lines) currently held by @p layer.
  long long cellCount(Layer layer) const;
  /// @brief The actor of @p layer (e.g. to adjust its vtkProperty); owned by the scene.
  vtkActor* actor(Layer layer) const;

  // --- scalar field on the surface ---------------------------------------------------------

  /// @brief Number of surface mesh vertices a field must give values for: one more than the
  /// largest "vertex" point-data id of the surface (its point count if it has no such array).
  long long surfaceVertexCount() const;
  /// @brief Colours the surface by @p perVertexValues (one per surface mesh vertex, indexed
  /// like PartGeometry::surfaceSamples; e.g. from ddf::valuesAtSamples) through @p style's
  /// colour map over [lo, hi] (values outside get the map's out-of-range colours), and shows a
  /// scalar bar titled style.title. Replaces any field shown before.
  /// @throws InvalidInput if the scene has no surface, the value count differs from
  /// surfaceVertexCount(), or style.lo >= style.hi or either is not finite.
  void setSurfaceField(const std::vector<float>& perVertexValues, const FieldStyle& style);
  /// @brief Whether the surface can show fields at raster resolution: the geometry came with
  /// corner parameters (SceneGeometry::surfaceCornerParams) and the raster fits a texture.
  bool showsRasterFields() const;
  /// @brief Colours the surface by @p rasterValues, one per raster point laid out like the
  /// heights (face after face, Raster order), through a texture with one texel per raster
  /// point: a groove or band narrower than the display triangles still shows. Colours, range,
  /// out-of-range swatches and scalar bar as setSurfaceField(); each raster point's colour
  /// covers the parameter cell around it (no blending between points). The textured copy of
  /// the surface is made on first use and kept until the geometry changes.
  /// @throws InvalidInput unless showsRasterFields(), or if the value count is not the raster's.
  void setSurfaceRasterField(std::span<const float> rasterValues, const FieldStyle& style);
  /// @brief The texture atlas the shown field is drawn from, or null when no field is shown at
  /// raster resolution (e.g. for tests that check its texels).
  const RasterTextureAtlas* rasterFieldAtlas() const;
  /// @brief Back to the plain surface colour; hides the scalar bar.
  void clearSurfaceField();
  /// @brief True while a field colours the surface.
  bool isFieldShown() const;
  /// @brief Title on the scalar bar ("" when no field is shown).
  std::string scalarBarTitle() const;
  /// @brief Value range of the surface colouring as the lookup table holds it ({0, 0} when no
  /// field is shown).
  ValueRange scalarRange() const;

  // --- overlays -----------------------------------------------------------------------------

  /// @brief Shows @p data (mm, part frame; null = empty) as overlay @p name with @p style;
  /// replaces an overlay of that name, keeping its visibility; a new one is visible.
  void setOverlay(const std::string& name, vtkSmartPointer<vtkPolyData> data,
                  const OverlayStyle& style);
  /// @brief Removes overlay @p name. @return false if there was none.
  bool removeOverlay(const std::string& name);
  /// @brief Shows or hides overlay @p name.
  /// @throws InvalidInput if there is no overlay of that name.
  void setOverlayVisible(const std::string& name, bool visible);
  /// @throws InvalidInput if there is no overlay of that name.
  bool isOverlayVisible(const std::string& name) const;
  bool hasOverlay(const std::string& name) const;
  /// @brief Names of all overlays, sorted.
  std::vector<std::string> overlayNames() const;
  /// @brief Number of cells of overlay @p name.
  /// @throws InvalidInput if there is no overlay of that name.
  long long overlayCellCount(const std::string& name) const;
  /// @brief The polydata overlay @p name shows (owned by the scene; valid until the overlay
  /// is replaced or removed), e.g. for tests that check what is drawn.
  /// @throws InvalidInput if there is no overlay of that name.
  vtkPolyData* overlayData(const std::string& name) const;

  // --- picking ------------------------------------------------------------------------------

  /// @brief The visible surface point under widget position @p widgetPos (logical pixels of
  /// @p view, origin top left, as in QMouseEvent::position()); only the surface layer is
  /// considered (overlays, support and stubbles never occlude it). The first pick on a new
  /// surface builds a cell locator (O(triangles)); later picks are fast.
  /// @param view the view whose renderer holds this scene
  /// @return std::nullopt if the surface is hidden or not hit there.
  /// @throws InvalidInput if @p view does not render this scene.
  std::optional<SurfacePick> pickSurface(const VtkView& view, QPointF widgetPos) const;

 private:
  vtkActor* overlayActor(const std::string& name, const char* caller) const;
  // The geometry's own look: its texture (e.g. the live tolerance band) or the surface colour.
  void showPlainSurface();
  void showScalarBar(vtkLookupTable* table, const FieldStyle& style,
                     std::pair<bool, bool> outOfRange);

  vtkSmartPointer<vtkRenderer> renderer_;
  vtkSmartPointer<vtkRenderer> annotationRenderer_;
  std::array<vtkSmartPointer<vtkActor>, kLayerCount> actors_;
  vtkSmartPointer<vtkPolyData> surface_;  ///< the surface as given, without field scalars
  vtkSmartPointer<vtkTexture> surfaceTexture_;  ///< the geometry's texture, may be null
  std::shared_ptr<const std::vector<float>> cornerParams_;
  int rasterFaces_ = 0, rasterSteps_ = 0;
  std::unique_ptr<RasterFieldSurface> rasterField_;  ///< made on the first raster field
  vtkSmartPointer<vtkScalarBarActor> scalarBar_;
  bool fieldShown_ = false;
  std::map<std::string, vtkSmartPointer<vtkActor>> overlays_;
  mutable vtkSmartPointer<vtkCellLocator> locator_;  ///< of the surface mapper's input, for picks
};

}  // namespace ddfcam::gui
