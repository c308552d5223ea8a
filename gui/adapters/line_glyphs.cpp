// SPDX-License-Identifier: MIT
// ddfcam gui adapters: line glyphs of line fields and point markers.
#include <ddfcam/gui/adapters/line_glyphs.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/planning/lines/streamline_path.h>

#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <string>

namespace ddfcam::gui {

double meanRasterSpacingMm(const ddf::DisplacementField& ddf) {
  const auto& mesh = ddf.support();
  double sum = 0.0;
  for (const auto& e : mesh.edges()) sum += mesh.calc_edge_length(e);
  const double edges = static_cast<double>(mesh.n_edges());
  return edges > 0 ? sum / edges / ddf.raster().steps() : 1.0;
}

int glyphStride(const ddf::DisplacementField& ddf, int targetCount) {
  const int n = ddf.raster().steps();
  for (int s = 1; s < n; ++s) {
    const double rows = n / s + 1;
    if (ddf.faceCount() * rows * (rows + 1) / 2 <= targetCount) return s;
  }
  return n;
}

std::vector<int> glyphSamplePoints(const ddf::DisplacementField& ddf, int stride) {
  if (stride < 1)
    throw InvalidInput("glyph stride must be at least 1, got " + std::to_string(stride));
  const int n = ddf.raster().steps();
  const auto perFace = static_cast<int>(ddf.raster().pointCount());
  std::vector<std::uint8_t> seen(ddf.topology().pointCount(), 0);
  std::vector<int> entries;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; k += stride)
      for (int i = 0; i + k <= n; i += stride) {
        const auto id = ddf.topology().id(f, i, k);
        if (seen[id]) continue;
        seen[id] = 1;
        entries.push_back(f * perFace + static_cast<int>(ddf.raster().index(i, k)));
      }
  return entries;
}

LineGlyphs lineGlyphs(const ddf::DisplacementField& ddf, const planning::LineField& field,
                      const LineGlyphParams& params) {
  const auto perFace = static_cast<int>(ddf.raster().pointCount());
  if (field.size() != static_cast<std::size_t>(ddf.faceCount()) * perFace)
    throw InvalidInput("line glyphs: the field has " + std::to_string(field.size()) +
                       " entries, the part " + std::to_string(ddf.faceCount() * perFace));
  if (params.stride < 0 || params.targetCount < 1 || !(params.lengthFactor > 0) ||
      !(params.liftFactor >= 0))
    throw InvalidInput("line glyphs: stride, target count, length or lift factor out of range");
  LineGlyphs out;
  out.stride = params.stride > 0 ? params.stride : glyphStride(ddf, params.targetCount);
  const double spacing = meanRasterSpacingMm(ddf);
  out.lengthMm = params.lengthFactor * out.stride * spacing;
  const int n = ddf.raster().steps();
  for (const int entry : glyphSamplePoints(ddf, out.stride)) {
    const ddf::Vec3& d = field[entry];
    if (!(d.squaredNorm() > 0)) continue;
    const int f = entry / perFace, local = entry % perFace;
    int k = 0;
    while (k < n && static_cast<int>(ddf.raster().rowOffset(k + 1)) <= local) ++k;
    const int i = local - static_cast<int>(ddf.raster().rowOffset(k));
    ddf::SurfaceLocation at;
    at.face = f;
    at.bary = ddf.rasterBary(i, k);
    at.point = ddf.surfacePoint(f, i, k);
    const ddf::Vec3 normal = planning::surfaceNormal(ddf, at);
    out.entries.push_back(entry);
    out.centres.push_back(at.point + params.liftFactor * spacing * normal);
    out.directions.push_back(d.normalized());
  }
  return out;
}

vtkSmartPointer<vtkPolyData> toLineGlyphPolyData(const LineGlyphs& glyphs) {
  std::vector<Eigen::Vector3d> from, to;
  from.reserve(glyphs.centres.size());
  to.reserve(glyphs.centres.size());
  const double half = 0.5 * glyphs.lengthMm;
  for (std::size_t g = 0; g < glyphs.centres.size(); ++g) {
    from.push_back(glyphs.centres[g] - half * glyphs.directions[g]);
    to.push_back(glyphs.centres[g] + half * glyphs.directions[g]);
  }
  return toSegmentPolyData(from, to);
}

vtkSmartPointer<vtkPolyData> toPointPolyData(const std::vector<Eigen::Vector3d>& points) {
  auto vtkPts = vtkSmartPointer<vtkPoints>::New();
  vtkPts->SetDataTypeToDouble();
  vtkPts->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  for (std::size_t p = 0; p < points.size(); ++p) {
    const auto id = static_cast<vtkIdType>(p);
    vtkPts->SetPoint(id, points[p].data());
    verts->InsertNextCell(1, &id);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(vtkPts);
  poly->SetVerts(verts);
  return poly;
}

}  // namespace ddfcam::gui
