// SPDX-License-Identifier: MIT
// ddfcam gui adapters: one texel per raster point of a part, so that colours drawn on a coarse
// display mesh keep the raster's resolution (a thin out-of-tolerance band stays visible).
#pragma once

#include <vtkSmartPointer.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

class vtkImageData;
class vtkTexture;

namespace ddfcam::gui {

/// @brief A texture atlas with one opaque RGBA texel per raster point: support face f's
/// triangular raster (steps + 1 points per edge) occupies square block (f mod columns,
/// f div columns) of (steps + 1)^2 texels, raster point (i, k) at texel (i, k) of its block;
/// texels outside the triangle (i + k > steps) repeat (steps - k, k). Sampled nearest with texel
/// centres on the raster points, so a fragment at parameter position (u, w) shows raster point
/// (round(u), round(w)): each colour covers the parameter cell around its point, whatever the
/// mesh. (Linear sampling would be bilinear over the square lattice, not linear over the
/// raster's triangles: a line of raster points along i + k = const would fade to half between
/// them.)
class RasterTextureAtlas {
 public:
  /// Largest texture side used, texels: what every OpenGL 3.2 implementation (Mesa's llvmpipe
  /// included) accepts.
  static constexpr int kMaxSide = 8192;

  /// @brief Whether the atlas of @p faces faces at @p steps steps fits in kMaxSide^2.
  static bool fits(int faces, int steps);
  /// @throws InvalidInput unless faces > 0, steps > 0 and fits(faces, steps).
  RasterTextureAtlas(int faces, int steps);

  int width() const { return width_; }
  int height() const { return height_; }
  /// @brief Texture coordinates (s, t) in [0, 1] of parameter position (@p u, @p w) (raster
  /// steps) on face @p face.
  std::array<float, 2> texCoord(int face, float u, float w) const;
  /// @brief Colours every raster point by its class (values laid out like the heights: face
  /// after face, Raster order; planning::ToleranceClass values, anything else grey). Only faces
  /// whose classes differ from the previous call are rewritten (all on the first, which VTK
  /// uploads whole); later changes reach the GPU through uploadChanged().
  /// @throws InvalidInput if @p classes has another size than faces * pointsPerFace.
  void setClasses(const std::vector<std::uint8_t>& classes);
  /// @brief Colours every raster point: @p rgba holds 4 bytes (red, green, blue, alpha) per
  /// raster point, laid out like the heights (e.g. a field through a colour map). Rewrites the
  /// whole atlas, which VTK then uploads whole.
  /// @throws InvalidInput if @p rgba has another size than 4 * faces * pointsPerFace.
  void setColours(std::span<const std::uint8_t> rgba);
  /// @brief Sends the blocks of the faces rewritten since the last upload to the texture VTK
  /// made of this atlas (glTexSubImage2D per block). Call with the view's GL context current,
  /// before VTK renders (the renderer's StartEvent); before VTK made the texture, it marks the
  /// whole image for VTK's own upload instead.
  void uploadChanged();
  /// @brief Faces rewritten and not uploaded yet.
  std::size_t pendingFaces() const { return dirtyFaces_.size(); }
  /// @brief RGB of texel (@p x, @p y) (for tests).
  std::array<unsigned char, 3> texel(int x, int y) const;
  /// @brief The texture (nearest sampling, clamped), owned by the atlas.
  vtkTexture* texture() const;
  /// @brief Number of faces rewritten by the last setClasses().
  int lastRewrittenFaces() const { return lastRewritten_; }

 private:
  // Writes face's block; colourOfPoint(p) gives the 4 bytes of the face's raster point p.
  template <typename Colour>
  void writeFace(int face, Colour colourOfPoint);
  void checkSize(std::size_t points, const char* caller) const;
  void wholeImageChanged();

  int faces_, steps_, block_, columns_, width_, height_;
  std::size_t pointsPerFace_;
  std::vector<std::uint8_t> shown_;  // classes last written
  std::vector<std::uint8_t> dirty_;  // per face: rewritten, not uploaded
  std::vector<int> dirtyFaces_;
  vtkSmartPointer<vtkImageData> image_;
  vtkSmartPointer<vtkTexture> texture_;
  int lastRewritten_ = 0;
};

}  // namespace ddfcam::gui
