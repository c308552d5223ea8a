// SPDX-License-Identifier: MIT
// ddfcam gui: loading a part (demo or file) and turning it into scene geometry, in one place.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/gui/part_geometry.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/io/part_loader.h>

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>

namespace ddfcam::gui {

/// @brief The part shown by the workbench.
struct PartDocument {
  ddf::DisplacementField ddf;        ///< the field as loaded or generated
  std::string name;                  ///< "demo part" or the file name
  std::filesystem::path path;        ///< source file; empty for the demo part
  std::size_t surfaceTriangles = 0;  ///< triangles of the displayed surface
  bool adaptiveSurface = false;      ///< surface from triangulateAdaptive (else the raster mesh)
  double adaptiveEpsMm = 0.0;        ///< eps used when adaptiveSurface, mm
  int stubbleStride = 1;             ///< lattice stride of the stubble layer
  io::LoadPartReport load;           ///< what loading did (conversion statistics for meshes)
};

/// @brief Owns the current PartDocument and feeds its geometry to a PartScene. Every load
/// builds the new document and its geometry completely before replacing the current one, so a
/// failed load leaves the previous part shown. Loads block the calling thread (for now).
class PartController {
 public:
  /// @param scene receives the geometry of every loaded part; must outlive the controller.
  explicit PartController(PartScene& scene, DisplayParams params = {});
  ~PartController();

  /// @brief Generates and shows the built-in demo part (ddf::demoPart()).
  /// @throws ddfcam::Error from the generator; the current part stays.
  void openDemo();
  /// @brief Loads a .ddf, or a .stl/.obj/.ply/.off mesh converted to a DDF, and shows it.
  /// @throws ddfcam::IoError or InvalidInput naming the file; the current part stays.
  void openFile(const std::filesystem::path& path);

  /// @brief The part shown, or null before the first successful load.
  const PartDocument* document() const { return document_.get(); }
  /// @brief One-line summary for the status bar: name, faces, m, points, triangles.
  std::string summary() const;

 private:
  void show(std::unique_ptr<PartDocument> document);

  PartScene& scene_;
  DisplayParams params_;
  std::unique_ptr<PartDocument> document_;
};

}  // namespace ddfcam::gui
