// SPDX-License-Identifier: MIT
// ddfcam-cli run: the report JSON of a job (counts, statistics, files; timings apart).
#include "job_exports.h"
#include "json_output.h"

namespace ddfcam::cli {

namespace {

void writePart(JsonReport& json, const planning::Project& p) {
  json["part"] = {{"name", p.partName},
                  {"faces", p.part->faceCount()},
                  {"resolution", p.part->raster().m},
                  {"raster_points", p.part->allHeights().size()}};
  JsonReport& regions = json["regions"] = JsonReport::array();
  for (const planning::Region& r : p.regions)
    regions.push_back({{"name", r.name}, {"faces", r.faces.size()}});
  JsonReport& tools = json["tools"] = JsonReport::array();
  for (const planning::Tool& t : p.tools)
    tools.push_back({{"name", t.name},
                     {"kind", std::string(planning::toolKindName(t.kind))},
                     {"radius_mm", t.radiusMm}});
}

JsonReport pathsJson(const JobResult& r) {
  JsonReport json = JsonReport::array();
  for (const RegionPathInfo& info : r.paths) {
    const planning::ToolPath& path = r.project.paths[static_cast<std::size_t>(info.path)];
    JsonReport& row = json.emplace_back();
    row["name"] = path.name;
    row["region"] = r.project.regions[static_cast<std::size_t>(info.region)].name;
    row["tool"] = path.tool;
    row["lines"] = info.lines;
    row["passes"] = path.passStarts.size();
    row["poses"] = path.poses.size();
    row["line_length_mm"] = info.lengthMm;
    row["feed_mm_per_min"] = path.feedMmPerMin;
  }
  return json;
}

JsonReport simulationJson(const JobResult& r) {
  JsonReport json = JsonReport::array();
  for (std::size_t i = 0; i < r.grinding.size(); ++i) {
    const planning::GrindingReport& g = r.grinding[i];
    JsonReport& row = json.emplace_back();
    row["path"] = r.project.paths[i].name;
    row["poses_cut"] = g.posesCut;
    row["removed_volume_mm3"] = g.removedVolumeMm3;
    row["heights_lowered"] = g.pointsLowered;
    row["v_convexity_poses"] = g.vConvexity.size();
    row["collision_poses"] = g.collisions.size();
  }
  return json;
}

JsonReport errorsJson(const JobSpec& spec, const JobResult& r) {
  if (!r.errors) return nullptr;
  const planning::ErrorStatistics& e = *r.errors;
  JsonReport json;
  json["tolerance_lower_mm"] = spec.errorMap.band.lowerMm;
  json["tolerance_upper_mm"] = spec.errorMap.band.upperMm;
  json["max_mm"] = e.maxMm;
  json["min_mm"] = e.minMm;
  json["mean_mm"] = e.meanMm;
  json["rms_mm"] = e.rmsMm;
  json["in_tolerance_percent"] = e.inTolerancePercent;
  json["material_left_percent"] = e.materialLeftPercent;
  json["overcut_percent"] = e.overcutPercent;
  json["area_mm2"] = e.areaMm2;
  json["points"] = e.points;
  return json;
}

}  // namespace

std::string jobReport(const JobSpec& spec, const JobResult& r, bool timings) {
  JsonReport json;
  json["ddfcam_job_report"] = 1;
  writePart(json, r.project);
  json["paths"] = pathsJson(r);
  json["simulation"] = simulationJson(r);
  json["error_map"] = errorsJson(spec, r);
  // Relative to the report, so that two runs into different directories report alike.
  const std::filesystem::path dir = spec.report ? spec.report->parent_path() : spec.baseDir;
  JsonReport& files = json["files"] = JsonReport::array();
  for (const std::filesystem::path& f : r.written)
    files.push_back(f.lexically_relative(dir).generic_string());
  json["notes"] = r.notes;
  if (timings) {
    JsonReport& stages = json["timings"] = JsonReport::object();
    for (const StageTiming& t : r.timings) stages[t.stage + "_s"] = t.seconds;
  }
  return jsonText(json);
}

}  // namespace ddfcam::cli
