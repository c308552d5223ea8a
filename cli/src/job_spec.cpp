// SPDX-License-Identifier: MIT
// ddfcam-cli run: the job file (JSON) parsed into a JobSpec; unknown keys are refused by name.
#include "job_spec.h"

#include <ddfcam/error.h>
#include <ddfcam/io/project/tool_library_file.h>

#include "json_fields.h"

#include <fstream>
#include <sstream>

namespace ddfcam::cli {

namespace {

using nlohmann::json;

/// Where output files go: the --out directory, else the job's directory.
struct Dirs {
  std::filesystem::path in, out;
};

void parsePart(JsonFields& job, PartSpec& part, const Dirs& dirs) {
  const json* v = job.find("part");
  if (!v || (v->is_string() && v->get<std::string>() == "demo")) return;
  if (v->is_string()) {
    part.demo = false;
    const std::filesystem::path p = v->get<std::string>();
    part.file = p.is_absolute() ? p : dirs.in / p;
    return;
  }
  JsonFields f(*v, "part", job.source());
  const std::optional<std::filesystem::path> file = f.path("file", dirs.in);
  part.demo = !file || file->filename() == "demo";
  if (!part.demo) part.file = *file;
  ddf::ConversionParams& c = part.conversion;
  c.resolution = f.integer("resolution", c.resolution, 2, 200);
  c.weldToleranceMm = f.number("weldToleranceMm", c.weldToleranceMm, 0.0);
  if (const json* units = f.find("units")) {
    part.unit = units->is_string() ? parseLengthUnit(units->get<std::string>()) : std::nullopt;
    if (!part.unit) f.fail("units", "expected " + std::string(lengthUnitChoices()));
  }
  c.support = f.choice("support", {"input", "reduced"}, 0) == 1 ? ddf::SupportChoice::Reduced
                                                                : ddf::SupportChoice::Input;
  c.toleranceMm = f.number("toleranceMm", 0.0, 0.0);
  c.rasterSpacingMm = f.number("rasterSpacingMm", 0.0, 0.0);
  if (c.toleranceMm > 0.0 && c.rasterSpacingMm > 0.0)
    f.fail("rasterSpacingMm", "give toleranceMm or rasterSpacingMm, not both");
  c.stockMm = f.number("stockMm", 0.0, 0.0);
  f.finish();
}

void parseSegmentation(JsonFields& job, SegmentationSpec& s) {
  const json* v = job.find("segmentation");
  if (!v) return;
  JsonFields f(*v, "segmentation", job.source());
  s.method = static_cast<SegmentationMethod>(
      f.choice("method", {"wholePart", "curvatureType", "toolRadius"}, 0));
  s.params.type.flatCurvaturePerMm =
      f.number("flatCurvaturePerMm", s.params.type.flatCurvaturePerMm, 0.0);
  s.params.minFaces = f.integer("minFaces", s.params.minFaces, 1, 1 << 30);
  s.params.minAreaMm2 = f.number("minAreaMm2", s.params.minAreaMm2, 0.0);
  s.toolRadiiMm = f.numbers("toolRadiiMm", {});
  if (s.method == SegmentationMethod::ToolRadius && s.toolRadiiMm.empty())
    f.fail("toolRadiiMm", "needed by the method toolRadius");
  f.finish();
}

planning::Tool parseTool(const json& v, const std::string& path, const std::string& source) {
  JsonFields f(v, path, source);
  planning::Tool t;
  const std::string kind = f.text("kind", std::string(planning::toolKindName(t.kind)));
  const std::optional<planning::ToolKind> k = planning::toolKindFromName(kind);
  if (!k) f.fail("kind", "unknown tool kind '" + kind + "'");
  t.kind = *k;
  t.name = f.text("name", t.name);
  t.radiusMm = f.number("radiusMm", t.radiusMm);
  t.widthMm = f.number("widthMm", t.widthMm);
  t.edgeRadiusMm = f.number("edgeRadiusMm", t.edgeRadiusMm);
  t.crownRadiusMm = f.number("crownRadiusMm", t.crownRadiusMm);
  t.shankRadiusMm = f.number("shankRadiusMm", t.shankRadiusMm);
  t.shankLengthMm = f.number("shankLengthMm", t.shankLengthMm);
  t.holderRadiusMm = f.number("holderRadiusMm", t.holderRadiusMm);
  t.holderLengthMm = f.number("holderLengthMm", t.holderLengthMm);
  t.chordToleranceMm = f.number("chordToleranceMm", t.chordToleranceMm);
  t.segments = f.integer("segments", t.segments, 0, 100000);
  f.finish();
  try {
    planning::validateTool(t);
  } catch (const InvalidInput& e) {
    throw InvalidInput(source + ": " + path + ": " + e.what());
  }
  return t;
}

void parseTools(JsonFields& job, JobSpec& spec, const Dirs& dirs) {
  if (const std::optional<std::filesystem::path> library = job.path("toolLibrary", dirs.in))
    spec.tools = io::readToolLibrary(*library);
  if (const json* v = job.find("tools")) {
    if (!v->is_array()) job.fail("tools", "expected a list of tools");
    for (std::size_t i = 0; i < v->size(); ++i)
      spec.tools.push_back(parseTool((*v)[i], "tools[" + std::to_string(i) + "]", job.source()));
  }
  if (spec.tools.empty()) spec.tools.push_back(planning::Tool{});
}

void parseField(JsonFields& f, planning::RegionPlan& plan) {
  using Source = planning::FlowFieldSource;
  plan.flowSource = static_cast<Source>(f.choice("field", {"kmax", "kmin", "fixed"}, 0));
  const std::vector<double> d = f.numbers("direction", {1.0, 0.0, 0.0});
  if (d.size() != 3 || ddf::Vec3(d[0], d[1], d[2]).squaredNorm() == 0.0)
    f.fail("direction", "expected three numbers, not all zero");
  plan.fixedDirection = ddf::Vec3(d[0], d[1], d[2]);
  plan.smoothField = f.flag("smooth", plan.smoothField);
  plan.smoothnessWeight = f.number("smoothnessWeight", plan.smoothnessWeight, 0.0);
}

RegionJob parseRegion(const json& v, const std::string& path, const std::string& source,
                      int toolCount) {
  JsonFields f(v, path, source);
  RegionJob r;
  if (const json* sel = f.find("region")) {
    if (sel->is_number_integer() && sel->get<int>() >= 0)
      r.index = sel->get<int>();
    else if (sel->is_string() && sel->get<std::string>() != "all")
      r.name = sel->get<std::string>();
    else if (!sel->is_string())
      f.fail("region", "expected a region index, a region name or \"all\"");
  }
  r.plan.tool = f.integer("tool", 0, 0, toolCount - 1);
  parseField(f, r.plan);
  r.method = static_cast<LineMethod>(f.choice("lines", {"even", "transverse", "refined"}, 0));
  r.tracing = static_cast<planning::StreamlineMethod>(
      f.choice("tracing", {"rk4", "walk", "continuous"}, 0));
  if (r.method == LineMethod::Even && r.tracing != planning::StreamlineMethod::Rk4)
    f.fail("tracing", "even spacing traces with rk4 only");
  r.plan.spacingMm = f.number("spacingMm", r.plan.spacingMm, 1e-3);
  if (f.find("scallopMm")) {
    r.plan.spacingMode = planning::SpacingMode::ScallopTolerance;
    r.plan.scallopToleranceMm = f.number("scallopMm", r.plan.scallopToleranceMm, 1e-6);
    if (r.method == LineMethod::Transverse)
      f.fail("scallopMm",
             "a spacing from the scallop height varies, so it needs \"lines\": "
             "\"even\"");
  }
  r.plan.feedSign = f.integer("feedSign", r.plan.feedSign, -1, 1);
  if (r.plan.feedSign == 0) f.fail("feedSign", "expected 1 (along the field) or -1 (against it)");
  r.plan.linking =
      static_cast<planning::LinkingOrder>(f.choice("linking", {"zigzag", "oneDirection"}, 0));
  r.link = f.flag("link", r.link);
  r.refineToleranceMm = f.number("toleranceMm", r.refineToleranceMm, 1e-6);
  r.refineMaxIterations = f.integer("maxIterations", r.refineMaxIterations, 0, 10000);
  f.finish();
  return r;
}

void parseRegions(JsonFields& job, JobSpec& spec) {
  const json* v = job.find("regions");
  if (!v) {
    spec.regions.push_back(RegionJob{});
    return;
  }
  if (!v->is_array()) job.fail("regions", "expected a list of region jobs");
  for (std::size_t i = 0; i < v->size(); ++i)
    spec.regions.push_back(parseRegion((*v)[i], "regions[" + std::to_string(i) + "]", job.source(),
                                       static_cast<int>(spec.tools.size())));
}

void parsePlacement(JsonFields& job, planning::StreamlinePathParams& p) {
  const json* v = job.find("placement");
  if (!v) return;
  JsonFields f(*v, "placement", job.source());
  p.placement.leadDeg = f.number("leadDeg", 0.0, -89.0, 89.0);
  p.placement.tiltDeg = f.number("tiltDeg", 0.0, -89.0, 89.0);
  p.feedMmPerMin = f.number("feedMmPerMin", p.feedMmPerMin, 1e-6);
  const json* tol = f.find("samplingToleranceMm");
  const json* step = f.find("samplingStepMm");
  if (tol || step) {
    planning::PathSamplingParams s;
    s.toleranceMm = f.number("samplingToleranceMm", s.toleranceMm, 1e-4, 10.0);
    if (step) s.stepOverrideMm = f.number("samplingStepMm", 0.5, 1e-3, 1000.0);
    p.sampling = s;
  }
  f.finish();
}

void parseSimulation(JsonFields& job, SimulationSpec& s) {
  const json* v = job.find("simulation");
  if (!v) return;
  JsonFields f(*v, "simulation", job.source());
  s.enabled = f.flag("enabled", true);
  if (f.find("allowanceMm")) s.allowanceMm = f.number("allowanceMm", 0.0);
  s.grinding.mode = static_cast<planning::SweepMode>(f.choice("mode", {"discrete", "swept"}, 0));
  s.grinding.checkVConvexity = f.flag("checkVConvexity", s.grinding.checkVConvexity);
  s.grinding.checkCollisions = f.flag("checkCollisions", s.grinding.checkCollisions);
  f.finish();
}

void parseErrorMap(JsonFields& job, ErrorMapSpec& e, const Dirs& dirs) {
  const json* v = job.find("errorMap");
  if (!v) return;
  JsonFields f(*v, "errorMap", job.source());
  e.enabled = f.flag("enabled", true);
  e.band.lowerMm = f.number("lowerMm", e.band.lowerMm, -100.0, 0.0);
  e.band.upperMm = f.number("upperMm", e.band.upperMm, 0.0, 100.0);
  e.vtp = f.path("vtp", dirs.out);
  f.finish();
}

ExportSpec parseExport(const json& v, const std::string& path, const std::string& source,
                       const Dirs& dirs) {
  JsonFields f(v, path, source);
  ExportSpec e;
  e.format = static_cast<ExportFormat>(f.choice("format", {"csv", "apt", "gcode"}, -1));
  if (!f.find("format")) f.fail("format", "missing (csv, apt or gcode)");
  const std::optional<std::filesystem::path> file = f.path("file", dirs.out);
  if (!file) f.fail("file", "missing");
  e.file = *file;
  e.inches = f.choice("units", {"mm", "in"}, 0) == 1;
  e.decimals = f.integer("decimals", e.format == ExportFormat::Csv ? 6 : 4, 0, 17);
  e.vectorDecimals = f.integer("vectorDecimals", e.vectorDecimals, 0, 17);
  static const std::vector<std::string> kApt = {"standard", "nx"};
  static const std::vector<std::string> kGcode = {"3axis", "5axis-ac", "5axis-bc"};
  if (e.format == ExportFormat::Apt) e.dialect = kApt[f.choice("dialect", kApt, 0)];
  if (e.format == ExportFormat::Gcode) e.dialect = kGcode[f.choice("dialect", kGcode, 1)];
  if (e.format == ExportFormat::Csv && f.find("dialect")) f.fail("dialect", "csv has none");
  e.perRegion = f.flag("perRegion", false);
  e.toolPoint = f.choice("point", {"contact", "tool"}, e.format == ExportFormat::Csv ? 0 : 1) == 1;
  f.finish();
  return e;
}

void parseOutputs(JsonFields& job, JobSpec& spec, const Dirs& dirs) {
  if (const json* v = job.find("exports")) {
    if (!v->is_array()) job.fail("exports", "expected a list of exports");
    for (std::size_t i = 0; i < v->size(); ++i)
      spec.exports.push_back(
          parseExport((*v)[i], "exports[" + std::to_string(i) + "]", job.source(), dirs));
  }
  spec.project = job.path("project", dirs.out).value_or(dirs.out / "job.ddfproj");
  spec.report = job.path("report", dirs.out).value_or(dirs.out / "report.json");
  if (const json* v = job.find("screenshots")) {
    if (!v->is_array()) job.fail("screenshots", "expected a list of PNG file names");
    for (const json& s : *v) {
      if (!s.is_string()) job.fail("screenshots", "expected a list of PNG file names");
      const std::filesystem::path p = s.get<std::string>();
      spec.screenshots.push_back(p.is_absolute() ? p : dirs.out / p);
    }
  }
}

}  // namespace

JobSpec parseJobSpec(std::string_view text, const std::string& sourceName,
                     const std::filesystem::path& baseDir,
                     const std::optional<std::filesystem::path>& outDir) {
  json root;
  try {
    root = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    // what() starts with "[json.exception.parse_error.101] parse error at line L, column C".
    std::string what = e.what();
    if (const auto at = what.find("] "); at != std::string::npos) what.erase(0, at + 2);
    throw InvalidInput(sourceName + ": " + what);
  }
  const Dirs dirs{baseDir, outDir.value_or(baseDir)};
  JobSpec spec;
  spec.baseDir = baseDir;
  JsonFields job(root, "", sourceName);
  job.find("comment");  // free text for the reader of the file
  parsePart(job, spec.part, dirs);
  parseSegmentation(job, spec.segmentation);
  parseTools(job, spec, dirs);
  parseRegions(job, spec);
  parsePlacement(job, spec.placement);
  parseSimulation(job, spec.simulation);
  parseErrorMap(job, spec.errorMap, dirs);
  if (spec.errorMap.enabled && !spec.simulation.enabled)
    job.fail("errorMap", "needs the simulation stage");
  parseOutputs(job, spec, dirs);
  job.finish();
  return spec;
}

JobSpec readJobSpec(const std::filesystem::path& file,
                    const std::optional<std::filesystem::path>& outDir) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError("cannot read job file " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  const std::filesystem::path dir = std::filesystem::absolute(file).parent_path();
  return parseJobSpec(text.str(), file.filename().string(), dir, outDir);
}

}  // namespace ddfcam::cli
