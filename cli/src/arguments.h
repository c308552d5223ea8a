// SPDX-License-Identifier: MIT
// ddfcam-cli: a small command-line argument parser (positionals, --name value, --name=value,
// flags).
#pragma once

#include <ddfcam/error.h>

#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ddfcam::cli {

/// @brief Wrong command-line usage; main() prints it and exits with code 2.
class UsageError : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

/// @brief One option a command accepts.
struct OptionSpec {
  std::string name;         ///< long name without dashes, e.g. "resolution"
  char shortName = '\0';    ///< single-letter alias, e.g. 'o' for -o; '\0' for none
  bool takesValue = false;  ///< true: needs a value; false: a flag
};

/// @brief The parsed command line of one subcommand.
class Arguments {
 public:
  /// @brief Parses @p args (the words after the subcommand name) against @p specs.
  /// "--help" and "-h" are always accepted as flags.
  /// @throws UsageError for an unknown option, a missing value or a repeated option.
  Arguments(std::span<const std::string> args, std::span<const OptionSpec> specs,
            std::string command);

  const std::vector<std::string>& positionals() const { return positionals_; }
  /// @brief True if the flag or option @p name was given.
  bool has(const std::string& name) const { return values_.count(name) > 0; }
  /// @brief Value of option @p name, if given.
  std::optional<std::string> value(const std::string& name) const;
  /// @brief Value of a required option.
  /// @throws UsageError if it is missing.
  std::string required(const std::string& name) const;
  /// @brief Integer value of @p name in [minValue, maxValue], or @p fallback if absent.
  /// @throws UsageError if it is not such an integer.
  int integer(const std::string& name, int fallback, int minValue, int maxValue) const;
  /// @brief Positive finite number given for @p name, or std::nullopt if absent.
  /// @throws UsageError if it is not a positive number.
  std::optional<double> positiveNumber(const std::string& name) const;
  /// @brief Requires exactly @p count positionals, named in @p what for the message.
  /// @throws UsageError otherwise.
  void expectPositionals(std::size_t count, const std::string& what) const;

 private:
  std::string command_;
  std::vector<std::string> positionals_;
  std::map<std::string, std::string> values_;
};

}  // namespace ddfcam::cli
