// SPDX-License-Identifier: MIT
// ddfcam-cli: the JSON reports and --json output, built as nlohmann-json documents.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace ddfcam::cli {

/// @brief A JSON report. Members print in the order they were set, so a report reads in the
/// order its command works and two runs print the same bytes.
using JsonReport = nlohmann::ordered_json;

/// @brief @p value indented by two spaces per level, followed by a line end. Non-finite numbers
/// print as null (JSON has no NaN or infinity); bytes that are not UTF-8 (a file name in another
/// encoding) print as U+FFFD instead of failing the run.
inline std::string jsonText(const JsonReport& value) {
  return value.dump(2, ' ', false, JsonReport::error_handler_t::replace) + '\n';
}

/// @brief @p value, or null when it is absent (a quantity the run did not measure).
template <typename T>
JsonReport jsonOrNull(const std::optional<T>& value) {
  return value ? JsonReport(*value) : JsonReport(nullptr);
}

}  // namespace ddfcam::cli
