// SPDX-License-Identifier: MIT
// ddfcam gui adapters: RasterTextureAtlas.
#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/raster_texture_atlas.h>
#include <ddfcam/gui/adapters/tolerance_colours.h>

#include <vtkImageData.h>
#include <vtkOpenGLTexture.h>
#include <vtkPointData.h>
#include <vtkTexture.h>
#include <vtkTextureObject.h>
#include <vtkUnsignedCharArray.h>
#include <vtk_glew.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace ddfcam::gui {
namespace {

// RGBA although alpha is always opaque: the layout GL drivers (Mesa's llvmpipe among them)
// take without converting, which halves the cost of the upload after every cut.
using Rgb8 = std::array<unsigned char, 4>;

Rgb8 bytes(const std::array<double, 3>& rgb) {
  Rgb8 out{};
  for (int c = 0; c < 3; ++c)
    out[c] = static_cast<unsigned char>(std::lround(255.0 * std::clamp(rgb[c], 0.0, 1.0)));
  out[3] = 255;
  return out;
}

// Colour per class value: the three ToleranceClass values, then grey for "no value".
std::array<Rgb8, 4> classColours() {
  using planning::ToleranceClass;
  return {bytes(toleranceClassColour(ToleranceClass::MaterialLeft)),
          bytes(toleranceClassColour(ToleranceClass::InTolerance)),
          bytes(toleranceClassColour(ToleranceClass::Overcut)), Rgb8{150, 150, 150, 255}};
}

int columnsFor(int faces) {
  return std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(faces)))));
}

}  // namespace

bool RasterTextureAtlas::fits(int faces, int steps) {
  if (faces <= 0 || steps <= 0) return false;
  const long long block = steps + 1, columns = columnsFor(faces);
  const long long rows = (faces + columns - 1) / columns;
  return block * columns <= kMaxSide && block * rows <= kMaxSide;
}

RasterTextureAtlas::RasterTextureAtlas(int faces, int steps)
    : faces_(faces), steps_(steps), block_(steps + 1), columns_(columnsFor(faces)) {
  if (!fits(faces, steps))
    throw InvalidInput("RasterTextureAtlas: " + std::to_string(faces) + " faces at " +
                       std::to_string(steps) + " raster steps do not fit in a " +
                       std::to_string(kMaxSide) + "^2 texture");
  width_ = block_ * columns_;
  height_ = block_ * ((faces_ + columns_ - 1) / columns_);
  pointsPerFace_ = static_cast<std::size_t>(block_) * (block_ + 1) / 2;
  dirty_.assign(static_cast<std::size_t>(faces_), 0);
  image_ = vtkSmartPointer<vtkImageData>::New();
  image_->SetDimensions(width_, height_, 1);
  image_->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  auto* texels = static_cast<unsigned char*>(image_->GetScalarPointer());
  const Rgb8 grey{150, 150, 150, 255};
  for (std::size_t t = 0; t < static_cast<std::size_t>(width_) * height_; ++t)
    std::memcpy(texels + 4 * t, grey.data(), 4);
  texture_ = vtkSmartPointer<vtkTexture>::New();
  texture_->SetInputData(image_);
  texture_->InterpolateOff();  // one raster point, one colour: no blending across a band edge
  texture_->RepeatOff();
  texture_->EdgeClampOn();
  texture_->MipmapOff();
}

vtkTexture* RasterTextureAtlas::texture() const {
  return texture_;
}

std::array<float, 2> RasterTextureAtlas::texCoord(int face, float u, float w) const {
  const int bx = face % columns_, by = face / columns_;
  return {(static_cast<float>(bx * block_) + u + 0.5f) / static_cast<float>(width_),
          (static_cast<float>(by * block_) + w + 0.5f) / static_cast<float>(height_)};
}

template <typename Colour>
void RasterTextureAtlas::writeFace(int face, Colour colourOfPoint) {
  auto* data = static_cast<unsigned char*>(image_->GetScalarPointer());
  const int x0 = (face % columns_) * block_, y0 = (face / columns_) * block_;
  // Raster order: k rows, i along each; row k holds steps - k + 1 points.
  std::size_t rowStart = 0;
  for (int k = 0; k <= steps_; ++k) {
    const int inRow = steps_ - k + 1;
    unsigned char* row = data + (static_cast<std::size_t>(y0 + k) * width_ + x0) * 4;
    for (int i = 0; i < block_; ++i)
      std::memcpy(row + 4 * i, colourOfPoint(rowStart + static_cast<std::size_t>(std::min(i, inRow - 1))), 4);
    rowStart += static_cast<std::size_t>(inRow);
  }
}

void RasterTextureAtlas::checkSize(std::size_t points, const char* caller) const {
  const std::size_t expected = pointsPerFace_ * static_cast<std::size_t>(faces_);
  if (points != expected)
    throw InvalidInput(std::string("RasterTextureAtlas::") + caller + ": " +
                       std::to_string(points) + " raster points, expected " +
                       std::to_string(expected));
}

void RasterTextureAtlas::setColours(std::span<const std::uint8_t> rgba) {
  if (rgba.size() % 4 != 0)
    throw InvalidInput("RasterTextureAtlas::setColours: " + std::to_string(rgba.size()) +
                       " bytes are not whole RGBA colours");
  checkSize(rgba.size() / 4, "setColours");
  for (int f = 0; f < faces_; ++f) {
    const std::uint8_t* block = rgba.data() + 4 * pointsPerFace_ * static_cast<std::size_t>(f);
    writeFace(f, [block](std::size_t p) { return block + 4 * p; });
  }
  shown_.clear();  // a later setClasses() writes every face again
  lastRewritten_ = faces_;
  wholeImageChanged();
}

void RasterTextureAtlas::setClasses(const std::vector<std::uint8_t>& classes) {
  checkSize(classes.size(), "setClasses");
  static const std::array<Rgb8, 4> colours = classColours();
  const bool first = shown_.empty();
  lastRewritten_ = 0;
  for (int f = 0; f < faces_; ++f) {
    const std::size_t at = pointsPerFace_ * static_cast<std::size_t>(f);
    if (!first && std::memcmp(classes.data() + at, shown_.data() + at, pointsPerFace_) == 0)
      continue;
    const std::uint8_t* block = classes.data() + at;
    writeFace(f, [block](std::size_t p) { return colours[std::min<std::uint8_t>(block[p], 3)].data(); });
    ++lastRewritten_;
    if (!first && !dirty_[static_cast<std::size_t>(f)]) {
      dirty_[static_cast<std::size_t>(f)] = 1;
      dirtyFaces_.push_back(f);
    }
  }
  shown_ = classes;
  if (first) wholeImageChanged();
}

void RasterTextureAtlas::wholeImageChanged() {
  for (int f : dirtyFaces_) dirty_[static_cast<std::size_t>(f)] = 0;
  dirtyFaces_.clear();
  image_->GetPointData()->GetScalars()->Modified();
  image_->Modified();
}

void RasterTextureAtlas::uploadChanged() {
  if (dirtyFaces_.empty()) return;
  auto* gl = vtkOpenGLTexture::SafeDownCast(texture_);
  vtkTextureObject* object = gl ? gl->GetTextureObject() : nullptr;
  if (!object || object->GetHandle() == 0 || object->GetWidth() != static_cast<unsigned>(width_) ||
      object->GetHeight() != static_cast<unsigned>(height_)) {
    wholeImageChanged();  // no texture on the GPU yet: VTK uploads the whole image
    return;
  }
  // The image's MTime stays, so VTK keeps its texture; the changed blocks go up one by one
  // (a cut changes a few hundred faces of ten thousands: a whole upload costs far more).
  object->Activate();  // a texture unit of VTK's, released again below
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, width_);
  const auto* data = static_cast<const unsigned char*>(image_->GetScalarPointer());
  for (int f : dirtyFaces_) {
    const int x0 = (f % columns_) * block_, y0 = (f / columns_) * block_;
    glTexSubImage2D(GL_TEXTURE_2D, 0, x0, y0, block_, block_, GL_RGBA, GL_UNSIGNED_BYTE,
                    data + (static_cast<std::size_t>(y0) * width_ + x0) * 4);
    dirty_[static_cast<std::size_t>(f)] = 0;
  }
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  object->Deactivate();
  dirtyFaces_.clear();
}

std::array<unsigned char, 3> RasterTextureAtlas::texel(int x, int y) const {
  const auto* data = static_cast<const unsigned char*>(image_->GetScalarPointer(x, y, 0));
  return {data[0], data[1], data[2]};
}

}  // namespace ddfcam::gui
