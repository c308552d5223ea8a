// SPDX-License-Identifier: MIT
// ddfcam gui: the VTK actors showing one part (surface, support wireframe, stubbles).
#pragma once

#include <vtkPolyData.h>  // complete type: SceneGeometry is copied and destroyed by value
#include <vtkSmartPointer.h>

#include <array>

class vtkActor;
class vtkRenderer;

namespace ddfcam::gui {

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
};

/// @brief Owns one actor per Layer in a renderer and their styling. Knows nothing of DDFs: it
/// shows the polydata it is given.
class PartScene {
 public:
  /// @brief Adds the (initially empty) actors to @p renderer, which must outlive the scene.
  explicit PartScene(vtkRenderer* renderer);
  ~PartScene();
  PartScene(const PartScene&) = delete;
  PartScene& operator=(const PartScene&) = delete;

  /// @brief Replaces the geometry of every layer (null members show nothing).
  void setGeometry(const SceneGeometry& geometry);
  /// @brief Shows or hides @p layer.
  void setVisible(Layer layer, bool visible);
  bool isVisible(Layer layer) const;
  /// @brief Number of cells (triangles or lines) currently held by @p layer.
  long long cellCount(Layer layer) const;

 private:
  vtkSmartPointer<vtkRenderer> renderer_;
  std::array<vtkSmartPointer<vtkActor>, kLayerCount> actors_;
};

}  // namespace ddfcam::gui
