// SPDX-License-Identifier: MIT
// ddfcam-cli run: the report JSON of a job (counts, statistics, files; timings apart).
#include "job_exports.h"
#include "json_writer.h"

namespace ddfcam::cli {

namespace {

void writePart(JsonWriter& json, const planning::Project& p) {
  json.key("part").beginObject();
  json.key("name").value(p.partName);
  json.key("faces").value(p.part->faceCount());
  json.key("resolution").value(p.part->raster().m);
  json.key("raster_points").value(p.part->allHeights().size());
  json.endObject();
  json.key("regions").beginArray();
  for (const planning::Region& r : p.regions)
    json.beginObject().key("name").value(r.name).key("faces").value(r.faces.size()).endObject();
  json.endArray();
  json.key("tools").beginArray();
  for (const planning::Tool& t : p.tools)
    json.beginObject()
        .key("name")
        .value(t.name)
        .key("kind")
        .value(std::string(planning::toolKindName(t.kind)))
        .key("radius_mm")
        .value(t.radiusMm)
        .endObject();
  json.endArray();
}

void writePaths(JsonWriter& json, const JobResult& r) {
  json.key("paths").beginArray();
  for (const RegionPathInfo& info : r.paths) {
    const planning::ToolPath& path = r.project.paths[static_cast<std::size_t>(info.path)];
    json.beginObject();
    json.key("name").value(path.name);
    json.key("region").value(r.project.regions[static_cast<std::size_t>(info.region)].name);
    json.key("tool").value(path.tool);
    json.key("lines").value(info.lines);
    json.key("passes").value(path.passStarts.size());
    json.key("poses").value(path.poses.size());
    json.key("line_length_mm").value(info.lengthMm);
    json.key("feed_mm_per_min").value(path.feedMmPerMin);
    json.endObject();
  }
  json.endArray();
}

void writeSimulation(JsonWriter& json, const JobResult& r) {
  json.key("simulation").beginArray();
  for (std::size_t i = 0; i < r.grinding.size(); ++i) {
    const planning::GrindingReport& g = r.grinding[i];
    json.beginObject();
    json.key("path").value(r.project.paths[i].name);
    json.key("poses_cut").value(g.posesCut);
    json.key("removed_volume_mm3").value(g.removedVolumeMm3);
    json.key("heights_lowered").value(g.pointsLowered);
    json.key("v_convexity_poses").value(g.vConvexity.size());
    json.key("collision_poses").value(g.collisions.size());
    json.endObject();
  }
  json.endArray();
}

void writeErrors(JsonWriter& json, const JobSpec& spec, const JobResult& r) {
  if (!r.errors) {
    json.key("error_map").null();
    return;
  }
  const planning::ErrorStatistics& e = *r.errors;
  json.key("error_map").beginObject();
  json.key("tolerance_lower_mm").value(spec.errorMap.band.lowerMm);
  json.key("tolerance_upper_mm").value(spec.errorMap.band.upperMm);
  json.key("max_mm").value(e.maxMm).key("min_mm").value(e.minMm);
  json.key("mean_mm").value(e.meanMm).key("rms_mm").value(e.rmsMm);
  json.key("in_tolerance_percent").value(e.inTolerancePercent);
  json.key("material_left_percent").value(e.materialLeftPercent);
  json.key("overcut_percent").value(e.overcutPercent);
  json.key("area_mm2").value(e.areaMm2);
  json.key("points").value(e.points);
  json.endObject();
}

}  // namespace

std::string jobReport(const JobSpec& spec, const JobResult& r, bool timings) {
  JsonWriter json;
  json.beginObject();
  json.key("ddfcam_job_report").value(1);
  writePart(json, r.project);
  writePaths(json, r);
  writeSimulation(json, r);
  writeErrors(json, spec, r);
  // Relative to the report, so that two runs into different directories report alike.
  const std::filesystem::path dir = spec.report ? spec.report->parent_path() : spec.baseDir;
  json.key("files").beginArray();
  for (const std::filesystem::path& f : r.written)
    json.value(f.lexically_relative(dir).generic_string());
  json.endArray();
  json.key("notes").beginArray();
  for (const std::string& n : r.notes) json.value(n);
  json.endArray();
  if (timings) {
    json.key("timings").beginObject();
    for (const StageTiming& t : r.timings) json.key(t.stage + "_s").value(t.seconds);
    json.endObject();
  }
  json.endObject();
  return json.str();
}

}  // namespace ddfcam::cli
