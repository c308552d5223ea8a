// SPDX-License-Identifier: MIT
// ddfcam-cli simulate: the coverage of the part by the path and the warnings of the run.
#include "simulate_checks.h"

#include "console.h"

#include <cstdio>
#include <string>

namespace ddfcam::cli {

planning::Coverage simulationCoverage(const ddf::DisplacementField& goal, const SimulateOptions& o,
                                      const planning::ToolPath& path) {
  planning::PathCoverageParams params;
  params.progress = consoleProgress("coverage");
  const planning::Coverage coverage = planning::pathCoverage(goal, o.tool, path, params).coverage;
  endProgressLine();
  return coverage;
}

void collectSimulateWarnings(const SimulateOptions& o, const SimulateFindings& found,
                             RunWarnings& warnings) {
  warnings.addPrinted(found.import.warnings);
  const planning::Coverage& c = found.coverage;
  char text[400];
  if (c.percent() < o.minCoveragePercent) {
    std::snprintf(text, sizeof text,
                  "the tool touches only %.3g %% of the part (%.6g of %.6g mm^2, --min-coverage "
                  "%.3g %%): the statistics describe the untouched surface; check the path's "
                  "frame, unit and placement (--translate, --rotate, --path-units)",
                  c.percent(), c.coveredAreaMm2, c.totalAreaMm2, o.minCoveragePercent);
    warnings.add(text);
  }
  if (found.clamping.points > 0) {
    std::snprintf(text, sizeof text,
                  "%zu raster points (%.4g mm^2) were cut below the crust bottom and clamped to "
                  "it: the true overcut there is deeper than the deviation shows, so min %.4g mm "
                  "is only a bound (a part with longer vectors shows the full depth)",
                  found.clamping.points, found.clamping.areaMm2, found.stats.minMm);
    warnings.add(text);
  }
  if (!found.grinding.vConvexity.empty())
    warnings.add(std::to_string(found.grinding.vConvexity.size()) +
                 " poses cut non-V-convex stubbles (fig. 8.15)");
  if (!found.grinding.collisions.empty())
    warnings.add(std::to_string(found.grinding.collisions.size()) +
                 " poses collide with the non-cutting part (sec. 8.5)");
}

}  // namespace ddfcam::cli
