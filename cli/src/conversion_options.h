// SPDX-License-Identifier: MIT
// ddfcam-cli: the mesh and CAD conversion options of convert and info, and the printed
// conversion summary.
#pragma once

#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/io/mesh/part_loader.h>

#include "arguments.h"

#include <filesystem>

namespace ddfcam::cli {

/// @brief Exit code of a conversion whose result violates a DDF constraint or whose crust
/// cannot hold the requested stock.
inline constexpr int kInvalidResultExitCode = 3;

/// @brief Adds the options conversionParams() reads to @p args: --units, --support,
/// --resolution, --tolerance, --raster-spacing, --stock, --weld-tolerance, --max-vector-length.
void addConversionOptions(Arguments& args);

/// @brief Conversion parameters from the command line (support default Reduced, as the import
/// dialog; m default 10).
/// @throws UsageError for --tolerance together with --raster-spacing.
io::LoadPartParams conversionParams(const Arguments& args);

/// @brief Prints what reading and converting @p input did: sizes, unit, repairs, the summary
/// lines (reduction, m and spacing, distances, stock) and, for CAD input, the CAD faces and
/// healing.
void printConversion(const std::filesystem::path& input, const io::LoadPartReport& report);

/// @brief Prints the verdict: on stdout when the result is valid and the stock (if asked) is
/// held, else the problems on stderr (for a stock the crust cannot hold, the limit's message
/// and the largest allowance).
/// @return whether the result is usable: a valid DDF that holds the requested stock.
bool printVerdict(const std::filesystem::path& input, const io::LoadPartReport& report);

}  // namespace ddfcam::cli
