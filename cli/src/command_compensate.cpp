// SPDX-License-Identifier: MIT
// ddfcam-cli compensate: springback compensation by displacement adjustment on DDF heights,
// mould_{j+1} = mould_j - lambda (formed_j - target), from imported formings or a linear model.
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/error.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/planning/mould/springback_compensation.h>

#include "arguments.h"
#include "commands.h"
#include "console.h"
#include "json_output.h"
#include "mould_options.h"
#include "unit_options.h"

#include <Eigen/Geometry>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ddfcam::cli {
namespace {

constexpr const char* kDescription =
    "Plans a mould that springs back onto TARGET (a surface file, in --units) by displacement\n"
    "adjustment on the heights of a DDF on TARGET: mould_{j+1} = mould_j - lambda (formed_j -\n"
    "TARGET), mould_0 = TARGET. With --formed, F0, F1, ... are the parts formed in mould_0,\n"
    "mould_1, ... (the history of forming simulations or tryouts run between iterations); the\n"
    "next mould is planned from the last. With --model-alpha, a linear springback model\n"
    "S(C) = P + (1 - alpha)(C - P) calibrated so that mould_0 forms F0 replaces the forming and\n"
    "runs --iterations steps. Writes mould_<j>.stl per iteration and prints the max and RMS\n"
    "deviation along the target normal per iteration.";

Arguments options() {
  Arguments args(
      "compensate",
      "compensate TARGET --formed F0 [F1 ...] [options]\n"
      "       ddfcam-cli compensate TARGET --model-alpha A --calibrate-from F0 [options]",
      kDescription);
  args.positional("TARGET", "target surface file");
  args.positional("F1", "with --formed: the parts formed in mould_1, mould_2, ...", true);
  args.option("--formed", "F [F2 ...]",
              "formed parts of mould_0, mould_1, ... (files after TARGET)");
  args.option("--model-alpha", "A", "isotropic springback share alpha in (0, 1)")
      ->check(positiveNumber());
  args.option("--model-axes", "AX,AY,AZ",
              "with --model-alpha: springback shares along x, y, z for the\n"
              "forming steps (anisotropic model; alpha calibrates P)");
  args.option("--calibrate-from", "F0",
              "part formed in the target itself (required with the model)");
  args.option("--lambda", "L", "adjustment factor in (0, 10]")
      ->check(positiveNumber())
      ->default_str("1");
  args.option("--iterations", "N", "model steps")->check(integerIn(1, 100))->default_str("3");
  args.option("--out-dir", "DIR", "where mould_<j>.stl go (default: the current directory)");
  addMouldOptions(args, {.surfaces = "TARGET and the formed parts",
                         .written = "the moulds are written in mm",
                         .ddf = "the target DDF",
                         .reach = "length of the target DDF's vectors (default 5 % of the\n"
                                  "bounding-box diagonal; mould heights beyond it are reported)",
                         .json = "convergence per iteration (max, RMS) as JSON"});
  return args;
}

std::string help() {
  return options().help();
}

ddf::DisplacementField targetDdf(const ddf::TriangleMesh& mesh, int resolution,
                                 std::optional<double> reach) {
  ddf::ConversionParams params;
  params.resolution = resolution;
  params.chooseLengths = false;  // unit pseudo-normals, heights 0: the target itself
  ddf::DisplacementField target = ddf::convertMeshToDdf(mesh, params).ddf;
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& v : mesh.vertices) box.extend(v);
  const double length = reach.value_or(0.05 * box.diagonal().norm());
  std::vector<ddf::Vec3> vectors = target.vectors();
  for (ddf::Vec3& v : vectors) v = length * v.normalized();
  target.setVectors(std::move(vectors));
  return target;
}

std::vector<float> heightsOf(const Arguments& args, const planning::CompensationHistory& history,
                             const std::filesystem::path& file, const std::string& role) {
  const planning::LoadedSurface formed = loadSurface(file, role, unitOption(args));
  ddf::DeformationSequenceParams params;
  params.progress = consoleProgress("comparing " + formed.name);
  std::vector<float> heights = planning::formedHeightsFromMesh(history.target, formed.mesh, params);
  endProgressLine();
  return heights;
}

void printIteration(const planning::CompensationHistory& history, std::size_t j) {
  const planning::CompensationIteration& it = history.iterations[j];
  std::printf(
      "  iteration %zu: lambda %.4g, max %.4g mm, rms %.4g mm, %zu points outside the "
      "crust%s%s\n",
      j, it.lambda, it.maxDeviationMm, it.rmsDeviationMm, it.pointsOutsideCrust,
      it.formedSource.empty() ? "" : ", formed: ", it.formedSource.c_str());
}

/// The imported formings: F_j is the response of mould_j; the next mould follows the last.
void runImported(const Arguments& args, planning::CompensationHistory& history, double lambda) {
  std::vector<std::string> files = {*args.value("formed")};
  files.insert(files.end(), args.positionals().begin() + 1, args.positionals().end());
  for (std::size_t j = 0; j < files.size(); ++j) {
    const std::filesystem::path file = files[j];
    planning::recordFormedResponse(history,
                                   heightsOf(args, history, file, "formed " + std::to_string(j)),
                                   file.filename().string());
    printIteration(history, j);
    planning::compensationStep(history, lambda);
  }
}

planning::LinearSpringbackModel springbackModel(const Arguments& args,
                                                const planning::CompensationHistory& history) {
  const double alpha = *args.number("model-alpha");
  const auto calibration = args.value("calibrate-from");
  if (!calibration) throw UsageError("compensate: --model-alpha needs --calibrate-from F0");
  planning::LinearSpringbackModel model = planning::calibrateSpringback(
      history.target, heightsOf(args, history, *calibration, "calibration"), alpha);
  if (const auto axes = args.value("model-axes")) {
    const std::vector<double> a = parseNumberList(*axes, 3, "model-axes");
    model.axisAlpha = Eigen::Vector3d(a[0], a[1], a[2]);
  }
  return model;
}

void runModel(const Arguments& args, planning::CompensationHistory& history, double lambda) {
  const planning::LinearSpringbackModel model = springbackModel(args, history);
  const int steps = args.integer("iterations", 3);
  std::string source = "linear model alpha=" + *args.value("model-alpha");
  if (model.axisAlpha) source += " axes=" + *args.value("model-axes");
  for (int j = 0; j <= steps; ++j) {
    planning::recordFormedResponse(
        history,
        planning::linearSpringback(model, history.target, history.iterations.back().mouldHeights),
        source);
    printIteration(history, static_cast<std::size_t>(j));
    if (j < steps) planning::compensationStep(history, lambda);
  }
}

void writeConvergence(const planning::CompensationHistory& history,
                      const std::filesystem::path& file, const std::string& mode) {
  JsonReport json;
  json["mode"] = mode;
  JsonReport& iterations = json["iterations"] = JsonReport::array();
  for (std::size_t j = 0; j < history.iterations.size(); ++j) {
    const planning::CompensationIteration& it = history.iterations[j];
    JsonReport& row = iterations.emplace_back();
    row["iteration"] = j;
    row["lambda"] = it.lambda;
    row["max_mm"] = it.maxDeviationMm;
    row["rms_mm"] = it.rmsDeviationMm;
    row["formed"] = it.formedSource;
    row["points_outside_crust"] = it.pointsOutsideCrust;
    row["mould"] = "mould_" + std::to_string(j) + ".stl";
  }
  writeTextFile(jsonText(json), file, "compensate");
}

void writeMoulds(const planning::CompensationHistory& history, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  for (std::size_t j = 0; j < history.iterations.size(); ++j)
    io::writeMesh(planning::mouldMesh(history, static_cast<int>(j)),
                  dir / ("mould_" + std::to_string(j) + ".stl"));
  std::printf("wrote mould_0.stl .. mould_%zu.stl to %s\n", history.iterations.size() - 1,
              dir.string().c_str());
}

int runCompensate(std::span<const std::string> words) {
  Arguments args = options();
  args.parse(words);
  if (args.positionals().empty()) throw UsageError("compensate: TARGET is missing");
  const bool imported = args.has("formed");
  if (args.has("model-axes") && !args.has("model-alpha"))
    throw UsageError("compensate: --model-axes needs --model-alpha (the calibration's share)");
  if (imported == args.has("model-alpha"))
    throw UsageError("compensate: give either --formed files or --model-alpha");
  if (!imported && args.positionals().size() != 1)
    throw UsageError("compensate: extra files after TARGET need --formed");
  installLogSink();
  const double lambda = args.number("lambda").value_or(1.0);
  const int resolution = args.integer("resolution", kMouldResolution);
  const auto start = std::chrono::steady_clock::now();
  const planning::LoadedSurface target =
      loadSurface(args.positionals()[0], "target", unitOption(args));
  planning::CompensationHistory history =
      planning::startCompensation(targetDdf(target.mesh, resolution, args.number("reach")));
  std::printf("compensate %s (m = %d, lambda %.4g)\n", target.name.c_str(), resolution, lambda);
  if (imported)
    runImported(args, history, lambda);
  else
    runModel(args, history, lambda);
  writeMoulds(history, args.value("out-dir").value_or("."));
  if (const auto json = args.value("json")) {
    writeConvergence(history, *json, imported ? "imported" : "model");
    std::printf("wrote %s\n", json->c_str());
  }
  std::printf("  time: %.3f s\n", secondsSince(start));
  return 0;
}

}  // namespace

const Command kCompensateCommand{"compensate",
                                 "springback compensation: corrected moulds and convergence", &help,
                                 &runCompensate};

}  // namespace ddfcam::cli
