// SPDX-License-Identifier: MIT
// ddfcam: which region of the part each tool path machines, by locating its contacts.
#include <ddfcam/planning/model/path_regions.h>

#include <ddfcam/ddf/surface_locator.h>
#include <ddfcam/error.h>

#include <tbb/parallel_for.h>

#include <string>

namespace ddfcam::planning {
namespace {

/// Region of every support face (-1: none); the first region listing a face wins.
std::vector<int> faceRegions(const ddf::DisplacementField& part,
                             const std::vector<Region>& regions) {
  std::vector<int> region(static_cast<std::size_t>(part.faceCount()), -1);
  for (std::size_t r = 0; r < regions.size(); ++r)
    for (const int f : regions[r].faces) {
      if (f < 0 || f >= part.faceCount())
        throw InvalidInput("path regions: region '" + regions[r].name + "' lists face " +
                           std::to_string(f) + " of a part with " +
                           std::to_string(part.faceCount()) + " faces");
      int& owner = region[static_cast<std::size_t>(f)];
      if (owner < 0) owner = static_cast<int>(r);
    }
  return region;
}

/// The region with the most votes (lowest index on ties), -1 if no vote.
int majority(const std::vector<int>& votes) {
  int best = -1;
  for (std::size_t r = 0; r < votes.size(); ++r)
    if (votes[r] > 0 && (best < 0 || votes[r] > votes[static_cast<std::size_t>(best)]))
      best = static_cast<int>(r);
  return best;
}

}  // namespace

std::vector<int> pathRegions(const ddf::DisplacementField& part, const std::vector<Region>& regions,
                             const std::vector<ToolPath>& paths) {
  const std::vector<int> regionOfFace = faceRegions(part, regions);
  const ddf::SurfaceLocator locator(part);
  std::vector<int> result(paths.size(), -1);
  for (std::size_t p = 0; p < paths.size(); ++p) {
    const std::vector<PathPose>& poses = paths[p].poses;
    // Face region of every contact, located in parallel (each query tests every face box).
    std::vector<int> contactRegion(poses.size(), -1);
    tbb::parallel_for(std::size_t{0}, poses.size(), [&](std::size_t i) {
      const auto location = locator.locate(poses[i].contact);
      if (location && location->face >= 0)
        contactRegion[i] = regionOfFace[static_cast<std::size_t>(location->face)];
    });
    std::vector<int> votes(regions.size(), 0);
    for (const int r : contactRegion)
      if (r >= 0) ++votes[static_cast<std::size_t>(r)];
    result[p] = majority(votes);
  }
  return result;
}

}  // namespace ddfcam::planning
