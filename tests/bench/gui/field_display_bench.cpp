// SPDX-License-Identifier: MIT
// ddfcam-gui-bench: the UI thread's cost of showing a field on the turbine blade's adaptive
// display: per display vertex (sampled at the vertices, VTK interpolates) against at raster
// resolution (every raster point's colour into the texture atlas), and the display build.
#include "planning/blade_workload.h"

#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/gui/part_geometry.h>
#include <ddfcam/gui/part_scene.h>

#include <benchmark/benchmark.h>

#include <vtkRenderer.h>

#include <algorithm>
#include <optional>

namespace ddfcam::bench {
namespace {

struct BladeDisplay {
  ddf::DisplacementField ddf;
  gui::PartGeometry geometry;
  std::vector<float> field;  // one value per raster point: the heights
  gui::FieldStyle style;
};

const std::optional<BladeDisplay>& bladeDisplay() {
  static const std::optional<BladeDisplay> display = []() -> std::optional<BladeDisplay> {
    std::optional<BladeWorkload> w = bladeWorkload(kBladeResolution);
    if (!w) return std::nullopt;
    BladeDisplay d{std::move(w->ddf), {}, {}, {}};
    d.geometry = gui::buildPartGeometry(d.ddf, {});
    d.field = d.ddf.allHeights();
    const auto [lo, hi] = std::minmax_element(d.field.begin(), d.field.end());
    d.style = {gui::ColourMap::Viridis, *lo, *hi + 1e-3, "height [1]"};
    return d;
  }();
  return display;
}

void counters(benchmark::State& state, const BladeDisplay& d) {
  state.counters["triangles"] = static_cast<double>(d.geometry.surfaceTriangles);
  state.counters["raster_points"] = static_cast<double>(d.field.size());
}

// Showing a field per display vertex, as the workbench did on adaptive displays: sample the
// field at the vertices, hand the values to the scene.
void BM_FieldDisplay_BladePerVertex(benchmark::State& state) {
  const auto& d = bladeDisplay();
  if (!d) return state.SkipWithError("turbine-blade-jigsaw.stl not found");
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  gui::PartScene scene(renderer);
  scene.setGeometry(d->geometry.scene);
  for (auto _ : state)
    scene.setSurfaceField(ddf::valuesAtSamples(d->ddf, d->field, d->geometry.surfaceSamples),
                          d->style);
  counters(state, *d);
}

// At raster resolution: every raster point's colour into the atlas (the textured copy of the
// surface is made once, before the loop, as on the first field shown after a load).
void BM_FieldDisplay_BladeRaster(benchmark::State& state) {
  const auto& d = bladeDisplay();
  if (!d) return state.SkipWithError("turbine-blade-jigsaw.stl not found");
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  gui::PartScene scene(renderer);
  scene.setGeometry(d->geometry.scene);
  scene.setSurfaceRasterField(d->field, d->style);
  for (auto _ : state) scene.setSurfaceRasterField(d->field, d->style);
  counters(state, *d);
}

// The first raster field after a load: the textured copy of the surface and the colours.
void BM_FieldDisplay_BladeRasterFirst(benchmark::State& state) {
  const auto& d = bladeDisplay();
  if (!d) return state.SkipWithError("turbine-blade-jigsaw.stl not found");
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  gui::PartScene scene(renderer);
  for (auto _ : state) {
    scene.setGeometry(d->geometry.scene);
    scene.setSurfaceRasterField(d->field, d->style);
  }
  counters(state, *d);
}

// The display build on load (adaptive triangulation, vertex samples and corner parameters).
void BM_FieldDisplay_BladeBuild(benchmark::State& state) {
  const auto& d = bladeDisplay();
  if (!d) return state.SkipWithError("turbine-blade-jigsaw.stl not found");
  for (auto _ : state) benchmark::DoNotOptimize(gui::buildPartGeometry(d->ddf, {}));
  counters(state, *d);
}

BENCHMARK(BM_FieldDisplay_BladePerVertex)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FieldDisplay_BladeRaster)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FieldDisplay_BladeRasterFirst)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FieldDisplay_BladeBuild)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ddfcam::bench
