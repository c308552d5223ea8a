// SPDX-License-Identifier: MIT
// ddfcam gui: MouldToolsPanel: the compensated mould in the mould view.
#include <ddfcam/gui/panels/mould_tools_panel.h>

#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/mould_view.h>
#include <ddfcam/planning/model/project.h>

namespace ddfcam::gui {
namespace {

// Per mesh vertex, (c - t) |v| at the first stored copy of its raster point: how far the mould
// moved from the target along the stubble, mm (copies of shared points agree by construction).
std::vector<float> offsetsAlongStubbles(const ddf::DisplacementField& target,
                                        const std::vector<float>& mouldHeights,
                                        const std::vector<ddf::PointId>& vertexPoint) {
  const ddf::RasterTopology& topology = target.topology();
  std::vector<float> offsets(vertexPoint.size(), 0.0f);
  for (std::size_t v = 0; v < vertexPoint.size(); ++v) {
    bool done = false;
    topology.forEachCopy(vertexPoint[v], [&](ddf::PointCopy c) {
      if (done) return;
      done = true;
      const std::size_t at = static_cast<std::size_t>(c.face) * target.pointsPerFace() + c.local;
      const ddf::RasterCoord rc = topology.coord(c);
      const double length = target.vectorAt(c.face, target.rasterBary(rc.i, rc.k)).norm();
      offsets[v] = static_cast<float>((mouldHeights[at] - target.allHeights()[at]) * length);
    });
  }
  return offsets;
}

}  // namespace

bool MouldToolsPanel::showMould(int iteration) {
  const planning::Project& p = workbench().document.project();
  const planning::CompensationHistory* h = history();
  MouldView* view = workbench().mouldView;
  if (h == nullptr || view == nullptr || iteration < 0 ||
      iteration >= static_cast<int>(h->iterations.size()))
    return false;
  return runUserAction(workbench().reportError, tr("Show mould"), [&] {
    ddf::DisplacementField mould = h->target;
    mould.allHeights() = h->iterations[static_cast<std::size_t>(iteration)].mouldHeights;
    ddf::RasterMesh shown = ddf::extractRasterMesh(mould);
    shownOffsets_ = offsetsAlongStubbles(h->target, mould.allHeights(), shown.vertexPoint);
    view->showPrimary(shown.mesh, shownOffsets_, p.mould->comparison.band);
  });
}

}  // namespace ddfcam::gui
