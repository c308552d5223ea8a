// SPDX-License-Identifier: MIT
// ddfcam gui: PartView, the document -> scene synchronisation and picking.
#include <ddfcam/gui/part_view.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/crust_surface.h>
#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/path_overlay.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/planning/model/field_freshness.h>
#include <ddfcam/planning/model/field_statistics.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <vtkPolyData.h>
#include <iomanip>
#include <sstream>

namespace ddfcam::gui {

namespace {

// An error map's range keeps the band in view: at least twice its wider bound on each side, so
// the light shades next to the band and the green are never squeezed into a few colours.
ValueRange widenedForBand(ValueRange range, const planning::ToleranceBand& band) {
  const double reach = 2.0 * std::max(std::abs(band.lowerMm), std::abs(band.upperMm));
  return {std::min(range.lo, -reach), std::max(range.hi, reach)};
}

constexpr const char* kToolOverlay = "tool";
constexpr const char* kGlyphOverlay = "vectors";
constexpr const char* kPickOverlay = "pick";

std::string withThousands(std::size_t value) {
  const std::string digits = std::to_string(value);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

const planning::ScalarField* findField(const planning::Project& project, const std::string& name) {
  for (const planning::ScalarField& f : project.fields)
    if (f.name == name) return &f;
  return nullptr;
}

std::string fieldTitle(const planning::ScalarField& field, bool stale) {
  const std::string title =
      field.unit.empty() ? field.name : field.name + " [" + field.unit + "]";
  // The colours stay (they show where the field was), but nobody should read them as current.
  return stale ? title + " - STALE: heights changed, recompute" : title;
}

}  // namespace

PartView::PartView(Document& document, VtkView& view, DisplayParams params, QObject* parent)
    : QObject(parent),
      document_(document),
      view_(view),
      params_(params),
      scene_(std::make_unique<PartScene>(view.renderer())) {
  connect(&document_, &Document::changed, this, &PartView::onDocumentChanged);
  connect(&view_, &VtkView::clicked, this, [this](QPointF pos) { pick(pos); });
  onDocumentChanged(Change::All);
}

PartView::~PartView() = default;

std::string PartView::summary() const {
  const planning::Project& p = document_.project();
  if (!p.part || !geometry_) return "no part";
  const ddf::DisplacementField& f = *p.part;
  std::ostringstream out;
  out << p.partName;
  if (facts_) out << "   " << sizeLine(facts_->sizeMm()) << "   " << supportLine(f, *facts_);
  out << "   points: " << withThousands(f.topology().pointCount())
      << "   surface: " << withThousands(geometry_->surfaceTriangles) << " triangles";
  if (geometry_->adaptiveSurface)
    out << " (adaptive, eps " << std::setprecision(2) << geometry_->adaptiveEpsMm << " mm)";
  else
    out << " (raster mesh)";
  return out.str();
}

void PartView::onDocumentChanged(Changes what) {
  if (what & (Change::Part | Change::Heights)) rebuildGeometry(what.testFlag(Change::Part));
  if (what & Change::Part) {  // another part: its paths start visible, none selected
    hiddenPaths_.clear();
    selectedPath_ = -1;
  }
  if (what & (Change::Paths | Change::Part)) rebuildPathOverlay();
  if (what & Change::Part) {
    setToolOverlay(std::nullopt);
    scene_->removeOverlay(kPickOverlay);
    rebuildGlyphOverlay();
    rebuildCrustOverlay(+1);
    rebuildCrustOverlay(-1);
  }
  if (what & (Change::Fields | Change::Part | Change::Heights)) {
    if (!display_.field.empty() && !findField(document_.project(), display_.field))
      display_.field.clear();
    applyFieldDisplay();
  }
  view_.requestRender();
}

void PartView::rebuildGeometry(bool partReplaced) {
  const planning::Project& p = document_.project();
  if (!p.part) {
    geometry_.reset();
    facts_.reset();
    scene_->setGeometry(SceneGeometry{});
  } else {
    auto geometry = std::make_unique<PartGeometry>(buildPartGeometry(*p.part, params_));
    scene_->setGeometry(geometry->scene);
    geometry_ = std::move(geometry);
    facts_ = partFacts(*p.part);
  }
  emit geometryChanged(partReplaced);
}

const planning::ScalarField* PartView::shownField() const {
  return display_.field.empty() ? nullptr : findField(document_.project(), display_.field);
}

void PartView::showField(const std::string& name) {
  if (!name.empty() && !findField(document_.project(), name))
    throw InvalidInput("the part has no field named '" + name + "'");
  const planning::ScalarField* field =
      name.empty() ? nullptr : findField(document_.project(), name);
  if (field && display_.field != name) {
    display_.map = defaultColourMap(field->isSigned);
    display_.band.reset();
    display_.faces.clear();
  }
  display_.field = name;
  display_.autoRange = true;
  applyFieldDisplay();
  view_.requestRender();
}

void PartView::setColourMap(ColourMap map) {
  display_.map = map;
  applyFieldDisplay();
  view_.requestRender();
}

void PartView::setRange(double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    throw InvalidInput("colour range: the low end must be below the high end");
  display_.autoRange = false;
  display_.lo = lo;
  display_.hi = hi;
  applyFieldDisplay();
  view_.requestRender();
}

void PartView::setAutoRange() {
  display_.autoRange = true;
  applyFieldDisplay();
  view_.requestRender();
}

void PartView::setToleranceBand(const std::optional<planning::ToleranceBand>& band) {
  if (band) planning::validateToleranceBand(*band);
  display_.band = band;
  applyFieldDisplay();
  view_.requestRender();
}

void PartView::setShownFaces(std::vector<int> faces) {
  const int count = document_.project().part ? document_.project().part->faceCount() : 0;
  for (int f : faces)
    if (f < 0 || f >= count)
      throw InvalidInput("shown faces: face " + std::to_string(f) + " is not one of the part's " +
                         std::to_string(count));
  std::sort(faces.begin(), faces.end());
  if (faces == display_.faces) return;
  display_.faces = std::move(faces);
  applyFieldDisplay();
  view_.requestRender();
}

std::vector<float> PartView::shownValues(const planning::ScalarField& field) const {
  std::vector<float> values = field.values;
  if (display_.faces.empty() || !document_.project().part) return values;
  const ddf::DisplacementField& part = *document_.project().part;
  const std::size_t per = part.pointsPerFace();
  std::vector<char> shown(static_cast<std::size_t>(part.faceCount()), 0);
  for (int f : display_.faces) shown[static_cast<std::size_t>(f)] = 1;
  for (std::size_t f = 0; f < shown.size(); ++f)
    if (!shown[f])
      std::fill_n(values.begin() + static_cast<std::ptrdiff_t>(f * per), per,
                  std::numeric_limits<float>::quiet_NaN());
  return values;
}

void PartView::applyFieldDisplay() {
  const planning::ScalarField* field = shownField();
  const planning::Project& p = document_.project();
  if (!field || !geometry_ || !p.part) {
    scene_->clearSurfaceField();
    emit fieldDisplayChanged();
    return;
  }
  const std::vector<float> values = shownValues(*field);
  if (display_.autoRange) {
    // Signed fields (curvature, deviation) may carry a few spikes that would wash out the
    // colours; unsigned ones (height, removal) are often zero over most of the part, where
    // quantiles would hide the largest values that matter.
    const auto range = field->isSigned ? planning::robustFieldRange(values)
                                       : planning::fieldRange(values);
    if (range) {
      ValueRange fit = defaultRange(range->min, range->max, field->isSigned);
      if (display_.band) fit = widenedForBand(fit, *display_.band);
      display_.lo = fit.lo;
      display_.hi = fit.hi;
    }
  }
  FieldStyle style;
  style.map = display_.map;
  style.lo = display_.lo;
  style.hi = display_.hi;
  style.stale = planning::isStale(*field, *p.part);
  style.title = fieldTitle(*field, style.stale);
  style.band = display_.band;
  // A coarse adaptive display would average a narrow groove or band away between its
  // vertices; through the raster texture every raster point keeps its own colour.
  if (scene_->showsRasterFields())
    scene_->setSurfaceRasterField(values, style);
  else
    scene_->setSurfaceField(ddf::valuesAtSamples(*p.part, values, geometry_->surfaceSamples),
                            style);
  emit fieldDisplayChanged();
}

void PartView::rebuildPathOverlay() {
  const PathOverlayLines lines =
      pathOverlayLines(document_.project(), hiddenPaths_, selectedPath_);
  // Links first, then cuts, then the selected path: the later overlay is drawn over.
  scene_->setOverlay(kPathLinksOverlay, toPolylinePolyData(lines.links), pathLinkStyle());
  scene_->setOverlay(kPathCutsOverlay, toPolylinePolyData(lines.cuts), pathCutStyle());
  scene_->setOverlay(kSelectedPathOverlay, toPolylinePolyData(lines.selected),
                     selectedPathStyle());
  for (const char* name : {kPathLinksOverlay, kPathCutsOverlay, kSelectedPathOverlay})
    scene_->setOverlayVisible(name, pathsVisible_);
}

void PartView::setPathsVisible(bool visible) {
  pathsVisible_ = visible;
  for (const char* name : {kPathLinksOverlay, kPathCutsOverlay, kSelectedPathOverlay})
    scene_->setOverlayVisible(name, visible);
  view_.requestRender();
}

void PartView::setPathVisible(const std::string& name, bool visible) {
  if (visible ? hiddenPaths_.erase(name) == 0 : !hiddenPaths_.insert(name).second) return;
  rebuildPathOverlay();
  view_.requestRender();
}

bool PartView::isPathVisible(const std::string& name) const {
  return hiddenPaths_.count(name) == 0;
}

void PartView::setSelectedPath(int index) {
  if (index == selectedPath_) return;
  selectedPath_ = index;
  rebuildPathOverlay();
  view_.requestRender();
}

void PartView::setToolOverlay(
    const std::optional<std::pair<planning::Tool, Eigen::Isometry3d>>& tool) {
  if (!tool) {
    scene_->removeOverlay(kToolOverlay);
  } else {
    OverlayStyle style;
    style.rgb = {0.75, 0.78, 0.85};
    style.opacity = 0.45;
    style.surface = true;
    scene_->setOverlay(kToolOverlay,
                       toSurfacePolyData(planning::toolMesh(tool->first).transformed(tool->second)),
                       style);
  }
  view_.requestRender();
}

void PartView::rebuildGlyphOverlay() {
  const planning::Project& p = document_.project();
  std::vector<Eigen::Vector3d> points, directions;
  double totalLength = 0.0;
  if (p.part) {
    for (int v = 0; v < p.part->vertexCount(); ++v) {
      points.push_back(p.part->position(v));
      directions.push_back(p.part->vector(v));
      totalLength += p.part->vector(v).norm();
    }
  }
  const double meanLength = points.empty() ? 1.0 : totalLength / points.size();
  OverlayStyle style;
  style.rgb = {0.55, 0.95, 0.55};
  style.lineWidth = 1.5;
  // Arrows one mean vector long: their tips trace roughly the +1 crust.
  scene_->setOverlay(kGlyphOverlay, toGlyphPolyData(points, directions, meanLength), style);
  scene_->setOverlayVisible(kGlyphOverlay, glyphsVisible_);
}

std::string PartView::crustOverlayName(int side) {
  return side > 0 ? "crust+1" : "crust-1";
}

void PartView::rebuildCrustOverlay(int side) {
  const std::string name = crustOverlayName(side);
  const planning::Project& p = document_.project();
  // Built only while shown: most sessions never look at the crust.
  if (!p.part || !crustVisible_[side > 0 ? 0 : 1]) {
    scene_->removeOverlay(name);
    return;
  }
  OverlayStyle style;
  style.surface = true;
  style.opacity = 0.3;
  style.rgb = side > 0 ? std::array{0.35, 0.6, 1.0} : std::array{1.0, 0.55, 0.25};
  scene_->setOverlay(name, toCrustPolyData(*p.part, side), style);
}

void PartView::setCrustVisible(int side, bool visible) {
  if (side != 1 && side != -1)
    throw InvalidInput("crust side must be +1 or -1, not " + std::to_string(side));
  crustVisible_[side > 0 ? 0 : 1] = visible;
  rebuildCrustOverlay(side);
  view_.requestRender();
}

bool PartView::isCrustVisible(int side) const {
  return crustVisible_[side > 0 ? 0 : 1];
}

void PartView::setVectorGlyphsVisible(bool visible) {
  glyphsVisible_ = visible;
  scene_->setOverlayVisible(kGlyphOverlay, visible);
  view_.requestRender();
}

void PartView::showPickMarker(const ddf::SurfaceLocation& location) {
  const ddf::DisplacementField& part = *document_.project().part;
  // An arrow along the stubble through the picked point, as long as a tenth of the part.
  const auto box =
      geometry_ && geometry_->scene.surface ? geometry_->scene.surface->GetBounds() : nullptr;
  const double size =
      box ? 0.1 * std::hypot(box[1] - box[0], box[3] - box[2], box[5] - box[4]) : 1.0;
  OverlayStyle style;
  style.rgb = {1.0, 0.2, 0.25};
  style.lineWidth = 3.0;
  style.onTop = true;
  scene_->setOverlay(
      kPickOverlay,
      toGlyphPolyData({location.point}, {part.vectorAt(location.face, location.bary)}, size),
      style);
  view_.requestRender();
}

std::optional<PickResult> PartView::pick(QPointF pos) {
  const planning::Project& p = document_.project();
  if (!p.part || !geometry_) return std::nullopt;
  const std::optional<SurfacePick> hit = scene_->pickSurface(view_, pos);
  if (!hit || hit->face < 0 || hit->face >= p.part->faceCount()) return std::nullopt;
  const std::optional<ddf::SurfaceLocation> location =
      ddf::locateOnFace(*p.part, hit->face, hit->position);
  if (!location) return std::nullopt;
  PickResult result;
  result.location = *location;
  if (const planning::ScalarField* field = shownField()) {
    result.fieldName = field->name;
    result.fieldUnit = field->unit;
    result.fieldValue =
        ddf::interpolateOnFace(*p.part, field->values, location->face, location->bary);
  }
  showPickMarker(*location);
  emit picked(result);
  return result;
}

}  // namespace ddfcam::gui
