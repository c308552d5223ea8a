// SPDX-License-Identifier: MIT
// ddfcam-cli run: strict reading of JSON objects (every key known, every value checked).
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace ddfcam::cli {

/// @brief The members of one JSON object, read by name. Every read key is remembered; finish()
/// refuses the keys nobody read. Messages name the source file and the key path
/// ("job.json: regions[0].spacingMm: expected a number > 0").
class JsonFields {
 public:
  /// @throws InvalidInput if @p value is not an object.
  JsonFields(const nlohmann::json& value, std::string path, const std::string& source);

  /// @brief The member @p key, or null if absent (the key counts as read).
  const nlohmann::json* find(const std::string& key);
  /// @brief A finite number in [lo, hi], or @p fallback if absent.
  double number(const std::string& key, double fallback, double lo = -1e300, double hi = 1e300);
  /// @brief An integer in [lo, hi], or @p fallback if absent.
  int integer(const std::string& key, int fallback, int lo, int hi);
  /// @brief true or false, or @p fallback if absent.
  bool flag(const std::string& key, bool fallback);
  /// @brief A string, or @p fallback if absent.
  std::string text(const std::string& key, const std::string& fallback);
  /// @brief The index of the string value among @p names, or @p fallback if absent.
  int choice(const std::string& key, const std::vector<std::string>& names, int fallback);
  /// @brief A list of numbers, or @p fallback if absent.
  std::vector<double> numbers(const std::string& key, const std::vector<double>& fallback);
  /// @brief A string path resolved against @p base (absolute paths stay), if present.
  std::optional<std::filesystem::path> path(const std::string& key,
                                            const std::filesystem::path& base);

  /// @brief "<source>: <path>.<key>: <what>" as an InvalidInput.
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;
  /// @brief The key path of @p key ("regions[0].spacingMm").
  std::string keyPath(const std::string& key) const;
  /// @brief The source file name.
  const std::string& source() const { return source_; }

  /// @throws InvalidInput naming the first key that was never read.
  void finish() const;

 private:
  const nlohmann::json& value_;
  std::string path_;
  std::string source_;
  std::set<std::string> read_;
};

}  // namespace ddfcam::cli
