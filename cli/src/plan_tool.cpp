// SPDX-License-Identifier: MIT
// ddfcam-cli plan: tool options, placement along the lines and linking of the placed passes.
#include "plan_tool.h"

#include <ddfcam/error.h>
#include <ddfcam/planning/lines/streamline_path.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

namespace ddfcam::cli {

namespace {

planning::ToolKind parseKind(const Arguments& args) {
  const std::string name = args.value("tool").value_or("roll");
  static const std::pair<const char*, planning::ToolKind> kAliases[] = {
      {"roll", planning::ToolKind::CylinderRoll},
      {"ball", planning::ToolKind::Sphere},
      {"torus", planning::ToolKind::TorusCutter},
      {"belt_wheel", planning::ToolKind::BeltContactWheel},
      {"ball_end", planning::ToolKind::BallEnd},
      {"flat_end", planning::ToolKind::FlatEnd}};
  for (const auto& [alias, kind] : kAliases)
    if (name == alias) return kind;
  if (const auto kind = planning::toolKindFromName(name)) return *kind;
  throw UsageError("--tool " + name +
                   ": expected roll|ball|ball_end|flat_end|torus|belt_wheel (or cylinder_roll, "
                   "sphere, belt_contact_wheel, torus_cutter)");
}

planning::Tool makeTool(const Arguments& args) {
  const planning::ToolKind kind = parseKind(args);
  const double radius = args.number("radius").value_or(5.0);
  const bool torus = kind == planning::ToolKind::TorusCutter;
  const std::optional<double> corner = args.number("corner-radius");
  if (corner && !torus && kind != planning::ToolKind::CylinderRoll &&
      kind != planning::ToolKind::BeltContactWheel)
    throw UsageError("--corner-radius needs --tool torus, roll or belt_wheel");
  char name[80];
  std::snprintf(name, sizeof name, "%s R%g", std::string(planning::toolKindName(kind)).c_str(),
                radius);
  planning::Tool tool{.name = name,
                      .kind = kind,
                      .radiusMm = radius,
                      .widthMm = 2.0 * radius,
                      .edgeRadiusMm = corner.value_or(torus ? radius / 4.0 : 0.0),
                      .segments = 48};
  try {
    planning::validateTool(tool);
  } catch (const InvalidInput& e) {
    throw UsageError(std::string("--tool/--radius/--corner-radius: ") + e.what());
  }
  return tool;
}

}  // namespace

void addPlanToolOptions(Arguments& args) {
  args.option("--tool", "KIND",
              "tool shape: roll, ball (bare sphere), ball_end, flat_end, torus,\n"
              "belt_wheel (or a tool-library key such as torus_cutter)\n"
              "(default roll); wheels are 2 radius wide, cutters' flutes 2\n"
              "radius long");
  args.option("--radius", "MM", "tool radius")->check(positiveNumber())->default_str("5");
  args.option("--corner-radius", "MM",
              "corner radius of torus (default radius / 4) or rim radius of\n"
              "roll and belt_wheel (default 0)")
      ->check(positiveNumber());
  args.option("--lead", "DEG",
              "lead angle (axis towards the feed), |angle| < 90 (default 0;\n"
              "negative: --lead=-5)");
  args.option("--tilt", "DEG", "tilt angle (about the feed), |angle| < 90 (default 0)");
  args.option("--tolerance", "MM",
              "resample the lines along the feed at the step that keeps the\n"
              "feed chord error and the cusp between poses below MM (bounded\n"
              "by the raster spacing) (default: a pose at every line point)")
      ->check(positiveNumber());
  args.option("--step", "MM", "resample at this fixed step instead (overrides the tolerance)")
      ->check(positiveNumber());
}

PlanTool parsePlanTool(const Arguments& args) {
  PlanTool t;
  t.tool = makeTool(args);
  t.placement.leadDeg = args.number("lead").value_or(0.0);
  t.placement.tiltDeg = args.number("tilt").value_or(0.0);
  for (const auto& [name, deg] :
       {std::pair{"lead", t.placement.leadDeg}, std::pair{"tilt", t.placement.tiltDeg}})
    if (!(std::abs(deg) < 90.0))
      throw UsageError(std::string("--") + name + " must lie within (-90, 90) deg");
  const std::optional<double> tolerance = args.number("tolerance");
  const std::optional<double> step = args.number("step");
  if (tolerance || step) {
    t.sampling = planning::PathSamplingParams{};
    if (tolerance) t.sampling->toleranceMm = *tolerance;
    t.sampling->stepOverrideMm = step;
  }
  return t;
}

PlacedProgram placeAndLink(const ddf::DisplacementField& part,
                           const std::vector<planning::Streamline>& lines, const PlanTool& tool,
                           double feedMmPerMin, const planning::LinkingParams& linking) {
  planning::StreamlinePathParams params;
  params.feedMmPerMin = feedMmPerMin;
  params.placement = tool.placement;
  params.sampling = tool.sampling;
  planning::PlacedPath placed =
      planning::toolPathFromStreamlinesDetailed(part, lines, tool.tool, 0, params);
  PlacedProgram out;
  out.path = std::move(placed.path);
  out.passes = std::move(placed.passes);
  std::vector<std::vector<ddf::Vec3>> contacts, normals;
  for (std::size_t p = 0; p < out.path.passStarts.size(); ++p) {
    const std::size_t end =
        p + 1 < out.path.passStarts.size() ? out.path.passStarts[p + 1] : out.path.poses.size();
    contacts.emplace_back();
    normals.emplace_back();
    for (std::size_t i = out.path.passStarts[p]; i < end; ++i) {
      const planning::PathPose& pose = out.path.poses[i];
      out.normals.push_back(planning::placedNormal(tool.tool, pose.pose, tool.placement));
      contacts.back().push_back(pose.contact);
      normals.back().push_back(out.normals.back());
    }
  }
  out.linked = planning::linkPaths(contacts, normals, linking);
  return out;
}

}  // namespace ddfcam::cli
