// SPDX-License-Identifier: MIT
// ddfcam gui: PartController, the single place where parts are loaded for display.
#include <ddfcam/gui/part_controller.h>

#include <ddfcam/ddf/analytic_generators.h>

#include <iomanip>
#include <sstream>
#include <utility>

namespace ddfcam::gui {

namespace {

std::string withThousands(std::size_t value) {
  const std::string digits = std::to_string(value);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

}  // namespace

PartController::PartController(PartScene& scene, DisplayParams params)
    : scene_(scene), params_(params) {}

PartController::~PartController() = default;

void PartController::openDemo() {
  auto doc = std::make_unique<PartDocument>();
  doc->ddf = ddf::demoPart().ddf;
  doc->name = "demo part";
  show(std::move(doc));
}

void PartController::openFile(const std::filesystem::path& path) {
  auto doc = std::make_unique<PartDocument>();
  doc->ddf = io::loadPart(path, io::LoadPartParams{}, &doc->load);
  doc->name = path.filename().string();
  doc->path = path;
  show(std::move(doc));
}

void PartController::show(std::unique_ptr<PartDocument> document) {
  // Everything that can throw happens before the scene or the current document is touched.
  PartGeometry geometry = buildPartGeometry(document->ddf, params_);
  document->surfaceTriangles = geometry.surfaceTriangles;
  document->adaptiveSurface = geometry.adaptiveSurface;
  document->adaptiveEpsMm = geometry.adaptiveEpsMm;
  document->stubbleStride = geometry.stubbleStride;
  scene_.setGeometry(geometry.scene);
  document_ = std::move(document);
}

std::string PartController::summary() const {
  if (!document_) return "no part";
  const ddf::DisplacementField& f = document_->ddf;
  std::ostringstream out;
  out << document_->name << "   faces: " << withThousands(f.faceCount())
      << "   m: " << f.resolution() << "   points: " << withThousands(f.topology().pointCount())
      << "   surface: " << withThousands(document_->surfaceTriangles) << " triangles";
  if (document_->adaptiveSurface)
    out << " (adaptive, eps " << std::setprecision(2) << document_->adaptiveEpsMm << " mm)";
  else
    out << " (raster mesh)";
  const io::LoadPartReport& load = document_->load;
  if (load.converted) {
    out << "   converted from a mesh of " << withThousands(load.meshTriangles) << " triangles";
    if (load.droppedFaces + load.degenerateFaces > 0)
      out << ", " << load.droppedFaces + load.degenerateFaces << " dropped";
  }
  return out.str();
}

}  // namespace ddfcam::gui
