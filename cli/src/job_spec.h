// SPDX-License-Identifier: MIT
// ddfcam-cli run: the batch job file (JSON) as plain values; every stage is a library call.
#pragma once

#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/length_unit.h>
#include <ddfcam/planning/analysis/segmentation.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/lines/streamline_path.h>
#include <ddfcam/planning/model/region_plan.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>
#include <ddfcam/planning/tools/tool.h>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::cli {

/// @brief The part to plan on: the built-in demo part or a file (.ddf, mesh, CAD, .ddfproj).
struct PartSpec {
  bool demo = true;                  ///< the built-in demo part (job "part": "demo") (default true)
  std::filesystem::path file;        ///< part file, absolute (resolved against the job's directory)
  ddf::ConversionParams conversion;  ///< mesh and CAD conversion (default m = 10, support input)
  /// Unit of a mesh or CAD file ("units"); std::nullopt: a CAD file's own, mm for meshes.
  std::optional<ddfcam::LengthUnit> unit;
};

/// @brief How the part is divided into regions (Segmentation panel).
enum class SegmentationMethod {
  WholePart,      ///< one region "whole part" holding every face
  CurvatureType,  ///< planning::segmentByCurvatureType
  ToolRadius      ///< planning::segmentByToolRadius
};

/// @brief Segmentation stage.
struct SegmentationSpec {
  SegmentationMethod method = SegmentationMethod::WholePart;  ///< default whole part
  planning::SegmentationParams params;  ///< thresholds, minFaces (defaults of the library)
  std::vector<double> toolRadiiMm;      ///< for ToolRadius, mm, ascending (default none)
};

/// @brief How the lines of a region are made.
enum class LineMethod {
  Even,        ///< evenly spaced streamlines ("Cover region" of the Streamlines panel)
  Transverse,  ///< a family seeded along the transverse line through the region's centre
  Refined      ///< planning::refineSpacing (Spacing refinement panel)
};

/// @brief What the job does on one region (selected by index or name).
struct RegionJob {
  std::optional<int> index;              ///< region index; empty: by name, or every region
  std::string name;                      ///< region name (when index is empty and name not empty)
  planning::RegionPlan plan;             ///< field source, smoothing, spacing, linking, tool
  LineMethod method = LineMethod::Even;  ///< default even spacing
  planning::StreamlineMethod tracing = planning::StreamlineMethod::Rk4;  ///< Transverse only
  bool link = true;                 ///< order the lines by linkStreamlines (default true)
  double refineToleranceMm = 0.01;  ///< Refined: largest material left, mm (default 0.01)
  int refineMaxIterations = 20;     ///< Refined: fix-up iterations (default 20)
};

/// @brief Simulation stage (Simulation panel).
struct SimulationSpec {
  bool enabled = false;               ///< run the stage (default false)
  std::optional<double> allowanceMm;  ///< raise by this stock allowance first (default none)
  planning::GrindingSimulationParams grinding;  ///< sweep mode and checks (library defaults)
};

/// @brief Error map stage (Error map panel).
struct ErrorMapSpec {
  bool enabled = false;                      ///< run the stage (default false; needs simulation)
  planning::ToleranceBand band;              ///< tolerance band, mm (default +-0.01)
  std::optional<std::filesystem::path> vtp;  ///< error map .vtp file (default none)
};

/// @brief Path file formats of the exports.
enum class ExportFormat { Csv, Apt, Gcode };

/// @brief One exported path file.
struct ExportSpec {
  ExportFormat format = ExportFormat::Csv;  ///< file format
  std::filesystem::path file;               ///< output file (absolute after resolution)
  bool inches = false;                      ///< units "in" instead of "mm" (default mm)
  int decimals = 6;                         ///< digits after the point of lengths (default 6)
  int vectorDecimals = 7;                   ///< APT: digits of tool-axis components (default 7)
  std::string dialect;     ///< apt: "standard" | "nx"; gcode: "3axis" | "5axis-ac" | "5axis-bc"
  bool perRegion = false;  ///< one file per path, "<stem>_<n><ext>" (default one file)
  bool toolPoint = false;  ///< point "tool" (tool reference point) instead of "contact"
};

/// @brief A whole batch job.
struct JobSpec {
  std::filesystem::path baseDir;      ///< directory of the job file (relative paths resolve here)
  PartSpec part;                      ///< the part
  bool curvature = true;              ///< add the curvature fields to the project (default true)
  SegmentationSpec segmentation;      ///< regions
  std::vector<planning::Tool> tools;  ///< tools (inline or from a tool library file)
  std::vector<RegionJob> regions;     ///< planning per region, in this order
  planning::StreamlinePathParams placement;        ///< lead, tilt, sampling, feed of every path
  SimulationSpec simulation;                       ///< grinding simulation
  ErrorMapSpec errorMap;                           ///< error map
  std::vector<ExportSpec> exports;                 ///< path files
  std::filesystem::path project = "job.ddfproj";   ///< project file written (default job.ddfproj)
  std::optional<std::filesystem::path> report;     ///< report JSON (default report.json)
  std::vector<std::filesystem::path> screenshots;  ///< PNG files rendered by the workbench
};

/// @brief Parses a job file's text. Relative paths in it resolve against @p baseDir; output
/// paths (project, report, exports, vtp, screenshots) resolve against @p outDir if it is given.
/// @param sourceName file name used in messages.
/// @throws InvalidInput "<sourceName>: line L, column C: ..." for bad JSON, "<sourceName>:
/// <key path>: ..." for an unknown key, a wrong type or a value out of range.
JobSpec parseJobSpec(std::string_view text, const std::string& sourceName,
                     const std::filesystem::path& baseDir,
                     const std::optional<std::filesystem::path>& outDir);

/// @brief Reads and parses a job file (see parseJobSpec; base directory = the file's).
/// @throws IoError if the file cannot be read; InvalidInput as parseJobSpec.
JobSpec readJobSpec(const std::filesystem::path& file,
                    const std::optional<std::filesystem::path>& outDir);

/// @brief The built-in job on the demo part (resources/jobs/demo_job.json, compiled in).
std::string_view builtinDemoJob();

}  // namespace ddfcam::cli
